#include "skin/skinning_decomposition.h"

#include <algorithm>
#include <cmath>

namespace kinema {

namespace {

// A right-handed orthonormal frame from the columns of a singular matrix: the longest
// column's direction, the next longest made perpendicular to it, and their cross product
// in the slot that keeps the frame a rotation.
glm::dmat3 orthonormalColumns(const glm::dmat3& a) {
  int order[3] = {0, 1, 2};
  std::sort(order, order + 3, [&a](int i, int j) { return glm::length(a[i]) > glm::length(a[j]); });
  const int i = order[0], j = order[1], k = order[2];
  if (!(glm::length(a[i]) > 1e-30)) return glm::dmat3(1.0);
  glm::dmat3 r(0.0);
  r[i] = glm::normalize(a[i]);
  glm::dvec3 second = a[j] - glm::dot(a[j], r[i]) * r[i];
  if (!(glm::length(second) > 1e-12 * glm::length(a[i]))) {
    // One direction only: any perpendicular (the one nearest to axis j).
    glm::dvec3 axis(0.0);
    axis[j] = 1.0;
    second = axis - glm::dot(axis, r[i]) * r[i];
    if (!(glm::length(second) > 1e-6)) {
      axis = glm::dvec3(0.0);
      axis[k] = 1.0;
      second = axis - glm::dot(axis, r[i]) * r[i];
    }
  }
  r[j] = glm::normalize(second);
  // Columns (0, 1, 2) right-handed: r[k] = r[k+1] x r[k+2] (indices mod 3).
  r[k] = glm::cross(r[(k + 1) % 3], r[(k + 2) % 3]);
  return r;
}

}  // namespace

glm::mat3 nearestRotation(const glm::mat3& a) {
  glm::dmat3 r(a);
  const double det = glm::determinant(r);
  if (!std::isfinite(det)) return glm::mat3(1.0f);  // not a matrix of numbers: no rotation in it
  if (!(std::abs(det) > 1e-30)) return glm::mat3(orthonormalColumns(r));
  for (int it = 0; it < 30; ++it) {
    const glm::dmat3 next = 0.5 * (r + glm::transpose(glm::inverse(r)));
    double change = 0;
    for (int c = 0; c < 3; ++c) change += glm::dot(next[c] - r[c], next[c] - r[c]);
    r = next;
    if (change < 1e-24) break;
  }
  if (det < 0) r = -r;
  return glm::mat3(r);
}

SkinningDecomposition decomposeSkinningMatrix(const glm::mat4& m) { return decomposeSkinningMatrix(m, nearestRotation(glm::mat3(m))); }

SkinningDecomposition decomposeSkinningMatrix(const glm::mat4& m, const glm::mat3& rotation) {
  SkinningDecomposition d;
  d.real = glm::normalize(glm::quat_cast(rotation));
  const glm::vec3 t(m[3]);
  d.dual = 0.5f * (glm::quat(0.0f, t.x, t.y, t.z) * d.real);
  d.stretch = glm::transpose(glm::mat3_cast(d.real)) * glm::mat3(m);
  return d;
}

}  // namespace kinema
