#pragma once
#include <vector>

#include "core/math.h"
#include "core/mesh.h"

namespace kinema {

// The matrix each skin joint applies to bind-pose vertices, glTF semantics:
// out[i] = world[skin.joints[i]] * skin.inverseBind[i]. The skinned node's own transform is
// ignored (glTF says so). `world` holds one transform per skeleton joint.
void computeSkinningMatrices(const Skin& skin, const std::vector<glm::mat4>& world, std::vector<glm::mat4>& out);

}  // namespace kinema
