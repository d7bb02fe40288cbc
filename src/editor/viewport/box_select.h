#pragma once
#include <vector>

#include "editor/viewport/viewport_view.h"

namespace kinema {

// The joints (indices, ascending) whose projected positions fall inside the screen rectangle
// spanned by two corners in pixels (either drag direction; edges included). Joints behind
// the eye are never selected.
std::vector<int> boxSelectJoints(const std::vector<glm::mat4>& world, const ViewportView& view, glm::vec2 cornerA,
                                 glm::vec2 cornerB);

}  // namespace kinema
