#pragma once
// What the CPU skinning jobs (linear blend, dual quaternion) share: input checks and the
// per-joint normal matrix.
#include <cstdint>
#include <string>

#include "core/math.h"

namespace kinema {

// Empty when the arrays of a skinning job can be used; otherwise one sentence naming what
// is wrong (null arrays, influencesPerVertex out of 1..kMaxInfluences or above a non-zero
// influenceStride, normals without outNormals or the reverse, a joint index >= jointCount,
// a non-finite matrix).
std::string validateSkinningArrays(const glm::vec3* positions, const glm::vec3* normals, int vertexCount,
                                   const uint16_t* influenceJoints, const float* influenceWeights,
                                   int influencesPerVertex, int influenceStride, const glm::mat4* jointMatrices,
                                   int jointCount,
                                   const glm::vec3* outPositions, const glm::vec3* outNormals);

// True when every matrix's upper 3x3 is an orthogonal matrix times one uniform scale s
// shared by all of them (within 1e-6 relative): then inverseTranspose(M) = M / s^2 for
// each, and a blend of normal matrices is the blend of the matrices up to that factor.
bool sharedSimilarity(const glm::mat4* matrices, int count);

// inverseTranspose of the upper 3x3, from the cofactors; a singular matrix gives its
// cofactor matrix (still maps normals of the surviving plane correctly, never NaN).
glm::mat3 normalMatrixOf(const glm::mat4& m);

}  // namespace kinema
