#pragma once
#include <cstdint>
#include <string>

#include "core/math.h"
#include "core/mesh.h"

namespace kinema {

// Linear blend (smooth) skinning on the CPU, ozz SkinningJob style: flat input arrays in,
// flat output arrays out, no allocation, no hidden state.
//   p' = sum_i w_i * M_i * p,   n' = normalize(sum_i w_i * inverseTranspose(M_i) * n)
// Rigid binding is the same job with one influence per vertex.
// On x86 CPUs with AVX2 and FMA a wider loop is chosen at run time; it fuses the blend's
// multiply-adds, so its results differ from the SSE2 loop's in the last float bits (both
// are within float rounding of the exact sums; positions of one-influence vertices are
// bit-identical to glm's M * p in both).
struct LinearBlendSkinningJob {
  // Bind-pose vertices (after morph targets, when the mesh has them).
  const glm::vec3* positions = nullptr;
  const glm::vec3* normals = nullptr;  // optional: null skips normals
  int vertexCount = 0;
  // influencesPerVertex entries per vertex (the stride of both arrays, 1..kMaxInfluences),
  // largest weight first, weights summing to 1; zero weights may follow.
  const uint16_t* influenceJoints = nullptr;
  const float* influenceWeights = nullptr;
  int influencesPerVertex = kMaxInfluences;
  // Entries from one vertex to the next in both arrays when only the first
  // influencesPerVertex of each are to be read (MeshPrimitive's kMaxInfluences layout
  // with at most 4 in use); 0: influencesPerVertex.
  int influenceStride = 0;
  // Skinning matrices (computeSkinningMatrices), indexed by influenceJoints.
  const glm::mat4* jointMatrices = nullptr;
  int jointCount = 0;
  // Outputs, vertexCount each; outNormals is required exactly when normals is given.
  glm::vec3* outPositions = nullptr;
  glm::vec3* outNormals = nullptr;
  // false leaves the skinned normals unnormalised, as ozz's SkinningJob does, for callers
  // that normalise later (a shader): outNormals is then sum_i w_i inverseTranspose(M_i) n.
  bool normalizeNormals = true;
  // false forces the SSE2 loop even where AVX2 + FMA is available (tests, comparisons).
  bool allowAvx2 = true;

  // Empty when the job can run; otherwise one sentence naming what is wrong (null arrays,
  // a stride out of range, a joint index >= jointCount, a non-finite matrix).
  std::string validate() const;
  // Runs the job; false (outputs untouched) when validate() fails.
  bool run() const;
};

}  // namespace kinema
