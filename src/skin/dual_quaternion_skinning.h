#pragma once
#include <cstdint>
#include <string>

#include "core/math.h"
#include "core/mesh.h"

namespace kinema {

// Dual quaternion skinning (Kavan et al. 2007) on the CPU: blends the rigid part of each
// skinning matrix as a unit dual quaternion (shortest arc, signs aligned to the first
// influence), so twisted limbs keep their volume instead of collapsing like linear blend.
// Scale or shear in a skinning matrix is blended linearly and applied first (Kavan's
// two-phase scheme), so files whose inverse bind matrices scale still deform correctly.
// Same inputs and outputs as LinearBlendSkinningJob.
struct DualQuaternionSkinningJob {
  const glm::vec3* positions = nullptr;
  const glm::vec3* normals = nullptr;  // optional
  int vertexCount = 0;
  const uint16_t* influenceJoints = nullptr;
  const float* influenceWeights = nullptr;
  int influencesPerVertex = kMaxInfluences;
  int influenceStride = 0;  // as in LinearBlendSkinningJob: 0 means influencesPerVertex
  const glm::mat4* jointMatrices = nullptr;
  int jointCount = 0;
  glm::vec3* outPositions = nullptr;
  glm::vec3* outNormals = nullptr;

  std::string validate() const;
  bool run() const;
};

}  // namespace kinema
