#pragma once
#include <cstdint>
#include <vector>

#include "core/math.h"

namespace kinema {

// Whether a triangle list (three indices a triangle into `positions`) bounds a solid with
// every face wound counter-clockwise seen from outside: each edge, taken between positions
// (vertices at the same place are one point, as texture seams split them), is met exactly
// once in each direction, and the signed volume is positive. Seen from outside such a
// surface, only front faces are visible, so a renderer may leave the back faces out (half
// the triangles a software rasteriser sets up and fills). False for an empty list, indices
// out of range, open or non-manifold surfaces and inward-facing ones.
bool isClosedOutwardSurface(const std::vector<glm::vec3>& positions, const std::vector<uint32_t>& indices);

// Whether every corner of the box [min, max] lies in front of the near plane of
// `viewProjection` (clip z > -w, w > 0): then the near plane does not cut what the box holds,
// and a closed surface inside it is seen from outside only.
bool boxInFrontOfNearPlane(const glm::mat4& viewProjection, const glm::vec3& min, const glm::vec3& max);

}  // namespace kinema
