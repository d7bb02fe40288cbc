#include "skin/skinning_matrices.h"

namespace kinema {

// Stand-in on the skin-gpu branch until the skin-cpu branch's implementation lands (same
// formula; take skin-cpu's file when merging).
void computeSkinningMatrices(const Skin& skin, const std::vector<glm::mat4>& world, std::vector<glm::mat4>& out) {
  out.resize(skin.joints.size());
  for (size_t i = 0; i < skin.joints.size(); ++i) {
    const int j = skin.joints[i];
    const glm::mat4 joint = j >= 0 && j < static_cast<int>(world.size()) ? world[j] : glm::mat4(1.0f);
    out[i] = joint * (i < skin.inverseBind.size() ? skin.inverseBind[i] : glm::mat4(1.0f));
  }
}

}  // namespace kinema
