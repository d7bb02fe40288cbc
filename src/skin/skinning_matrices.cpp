#include "skin/skinning_matrices.h"

namespace kinema {

void computeSkinningMatrices(const Skin& skin, const std::vector<glm::mat4>& world, std::vector<glm::mat4>& out) {
  out.resize(skin.joints.size());
  for (size_t i = 0; i < skin.joints.size(); ++i) {
    const int joint = skin.joints[i];
    // Loaders check joint numbers; an out-of-range one here gives the bind pose, not a crash.
    const glm::mat4 jointWorld =
        joint >= 0 && static_cast<size_t>(joint) < world.size() ? world[joint] : glm::mat4(1.0f);
    out[i] = i < skin.inverseBind.size() ? jointWorld * skin.inverseBind[i] : jointWorld;
  }
}

}  // namespace kinema
