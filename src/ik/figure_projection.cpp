#include "ik/figure_projection.h"

#include <cmath>

namespace kinema {

FigureProjection FigureProjection::along(glm::vec3 d) {
  FigureProjection p;
  const float len = glm::length(d);
  if (!(len > 1e-6f)) return p;
  d /= len;
  if (std::abs(d.z) > 0.9999f) return p;  // the board, whichever side it is seen from
  const glm::vec3 upHint = std::abs(d.y) > 0.99f ? glm::vec3(0, 0, 1) : glm::vec3(0, 1, 0);
  p.right = glm::normalize(glm::cross(upHint, d));
  p.up = glm::cross(d, p.right);
  return p;
}

}  // namespace kinema
