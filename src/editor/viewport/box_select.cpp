#include "editor/viewport/box_select.h"

namespace kinema {

std::vector<int> boxSelectJoints(const std::vector<glm::mat4>& world, const ViewportView& view, glm::vec2 cornerA,
                                 glm::vec2 cornerB) {
  const glm::vec2 lo = glm::min(cornerA, cornerB), hi = glm::max(cornerA, cornerB);
  const glm::mat4 vp = view.viewProjection();
  std::vector<int> inside;
  for (size_t i = 0; i < world.size(); ++i) {
    const glm::vec4 clip = vp * glm::vec4(glm::vec3(world[i][3]), 1.0f);
    // Behind the eye, or in front of it but before the near plane (both modes): not visible.
    if (clip.w <= 1e-7f || clip.z < -clip.w) continue;
    glm::vec2 pixel;
    if (!view.project(glm::vec3(world[i][3]), pixel)) continue;
    if (pixel.x >= lo.x && pixel.x <= hi.x && pixel.y >= lo.y && pixel.y <= hi.y) inside.push_back(static_cast<int>(i));
  }
  return inside;
}

}  // namespace kinema
