#pragma once
#include <string>
#include <vector>

#include "core/math.h"
#include "core/mesh.h"

namespace kinema {

// Blend shapes, glTF semantics: p = p_bind + sum_k weight_k * delta_k (normals likewise,
// renormalised). Applied before skinning. Weights beyond the primitive's target count are
// ignored; missing weights count as 0.
struct MorphTargetsJob {
  const MeshPrimitive* primitive = nullptr;
  const float* weights = nullptr;
  int weightCount = 0;
  std::vector<glm::vec3>* outPositions = nullptr;  // resized to vertexCount
  std::vector<glm::vec3>* outNormals = nullptr;    // optional; resized (left empty without normals)

  std::string validate() const;
  bool run() const;
};

}  // namespace kinema
