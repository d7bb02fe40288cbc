#include "skin/morph_targets.h"

#include <algorithm>
#include <cmath>

namespace kinema {

std::string MorphTargetsJob::validate() const {
  if (!primitive) return "primitive is null";
  if (!outPositions) return "outPositions is null";
  if (weightCount < 0) return "weightCount is negative";
  if (weightCount > 0 && !weights) return "weights is null but weightCount is " + std::to_string(weightCount);
  for (int k = 0; k < weightCount; ++k)
    if (!std::isfinite(weights[k])) return "morph weight " + std::to_string(k) + " is not finite";
  const size_t n = primitive->positions.size();
  if (!primitive->normals.empty() && primitive->normals.size() != n)
    return "the primitive has " + std::to_string(primitive->normals.size()) + " normals for " + std::to_string(n) +
           " positions";
  for (size_t t = 0; t < primitive->targets.size(); ++t) {
    const MorphTarget& target = primitive->targets[t];
    if (target.positionDeltas.size() != n || (!target.normalDeltas.empty() && target.normalDeltas.size() != n))
      return "morph target " + std::to_string(t) + " does not have one delta per vertex (" + std::to_string(n) + ")";
  }
  return {};
}

bool MorphTargetsJob::run() const {
  if (!validate().empty()) return false;
  const MeshPrimitive& prim = *primitive;
  const size_t n = prim.positions.size();
  const int targets = std::min(weightCount, static_cast<int>(prim.targets.size()));
  std::vector<glm::vec3>& pos = *outPositions;
  pos.assign(prim.positions.begin(), prim.positions.end());
  // Target by target over all vertices: each pass streams two arrays; zero weights cost nothing.
  for (int t = 0; t < targets; ++t) {
    const float w = weights[t];
    if (w == 0.0f) continue;
    const glm::vec3* d = prim.targets[t].positionDeltas.data();
    for (size_t v = 0; v < n; ++v) pos[v] += w * d[v];
  }
  if (!outNormals) return true;
  std::vector<glm::vec3>& nrm = *outNormals;
  nrm.assign(prim.normals.begin(), prim.normals.end());
  if (prim.normals.empty()) return true;
  bool changed = false;
  for (int t = 0; t < targets; ++t) {
    const float w = weights[t];
    if (w == 0.0f || prim.targets[t].normalDeltas.empty()) continue;
    const glm::vec3* d = prim.targets[t].normalDeltas.data();
    for (size_t v = 0; v < n; ++v) nrm[v] += w * d[v];
    changed = true;
  }
  if (changed)
    for (size_t v = 0; v < n; ++v) {
      const float len2 = glm::dot(nrm[v], nrm[v]);
      // A normal the deltas cancel keeps its bind direction rather than becoming NaN.
      nrm[v] = len2 > 0.0f ? nrm[v] / std::sqrt(len2) : prim.normals[v];
    }
  return true;
}

}  // namespace kinema
