#include "skin/skinning_job_checks.h"

#include <algorithm>
#include <cmath>

#include "core/mesh.h"

namespace kinema {

std::string validateSkinningArrays(const glm::vec3* positions, const glm::vec3* normals, int vertexCount,
                                   const uint16_t* influenceJoints, const float* influenceWeights,
                                   int influencesPerVertex, int influenceStride, const glm::mat4* jointMatrices,
                                   int jointCount,
                                   const glm::vec3* outPositions, const glm::vec3* outNormals) {
  if (vertexCount < 0) return "vertexCount is negative";
  if (jointCount < 0) return "jointCount is negative";
  if (influencesPerVertex < 1 || influencesPerVertex > kMaxInfluences)
    return "influencesPerVertex must be 1.." + std::to_string(kMaxInfluences) + ", not " +
           std::to_string(influencesPerVertex);
  if (influenceStride != 0 && influenceStride < influencesPerVertex)
    return "influenceStride " + std::to_string(influenceStride) + " is smaller than influencesPerVertex " +
           std::to_string(influencesPerVertex);
  if ((normals == nullptr) != (outNormals == nullptr))
    return normals ? "normals are given but outNormals is null" : "outNormals is given but normals is null";
  if (vertexCount == 0) return {};
  if (!positions || !outPositions) return "positions and outPositions are required";
  if (!influenceJoints || !influenceWeights) return "influenceJoints and influenceWeights are required";
  if (jointCount == 0 || !jointMatrices) return "the vertices need joint matrices (jointCount is 0 or jointMatrices null)";
  for (int j = 0; j < jointCount; ++j) {
    const float* m = glm::value_ptr(jointMatrices[j]);
    for (int k = 0; k < 16; ++k)
      if (!std::isfinite(m[k])) return "joint matrix " + std::to_string(j) + " is not finite";
  }
  // A max over the indices first (vectorises): the index search runs only on failure.
  const size_t stride = influenceStride ? influenceStride : influencesPerVertex;
  uint16_t largest = 0;
  if (stride == static_cast<size_t>(influencesPerVertex)) {
    const size_t count = static_cast<size_t>(vertexCount) * stride;
    for (size_t i = 0; i < count; ++i) largest = std::max(largest, influenceJoints[i]);
  } else {
    for (size_t v = 0; v < static_cast<size_t>(vertexCount); ++v)
      for (int k = 0; k < influencesPerVertex; ++k) largest = std::max(largest, influenceJoints[v * stride + k]);
  }
  if (largest >= jointCount) {
    for (size_t v = 0; v < static_cast<size_t>(vertexCount); ++v)
      for (int k = 0; k < influencesPerVertex; ++k)
        if (influenceJoints[v * stride + k] >= jointCount)
          return "vertex " + std::to_string(v) + " influence " + std::to_string(k) + " uses joint " +
                 std::to_string(influenceJoints[v * stride + k]) + ", past the " + std::to_string(jointCount) +
                 " joint matrices";
  }
  return {};
}

bool sharedSimilarity(const glm::mat4* matrices, int count) {
  if (count <= 0) return true;
  const float s2 = glm::dot(glm::vec3(matrices[0][0]), glm::vec3(matrices[0][0]));
  if (!(s2 > 0.0f) || !std::isfinite(s2)) return false;
  const float tol = 1e-6f * s2;
  for (int i = 0; i < count; ++i) {
    const glm::vec3 a(matrices[i][0]), b(matrices[i][1]), c(matrices[i][2]);
    if (std::abs(glm::dot(a, a) - s2) > tol || std::abs(glm::dot(b, b) - s2) > tol ||
        std::abs(glm::dot(c, c) - s2) > tol || std::abs(glm::dot(a, b)) > tol || std::abs(glm::dot(a, c)) > tol ||
        std::abs(glm::dot(b, c)) > tol)
      return false;
  }
  return true;
}

glm::mat3 normalMatrixOf(const glm::mat4& m) {
  const glm::vec3 a(m[0]), b(m[1]), c(m[2]);
  // inverse(A)^T = [b x c, c x a, a x b] / det(A) for A = [a b c] (columns).
  const glm::mat3 cofactors(glm::cross(b, c), glm::cross(c, a), glm::cross(a, b));
  const float det = glm::dot(a, glm::cross(b, c));
  const float inv = 1.0f / det;
  return det != 0.0f && std::isfinite(inv) ? cofactors * inv : cofactors;
}

}  // namespace kinema
