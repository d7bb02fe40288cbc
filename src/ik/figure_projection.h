#pragma once
#include "core/math.h"

namespace kinema {

// The plane a 3D teaching chain is drawn on (solver comparison figures: `kinema demo`'s
// PNGs and the editor's Compare Solvers view), seen along a view direction: right and up
// axes in the chain's space, units kept. Looking along Z either way shows the board as
// drawn (x, y); otherwise Y stays up (Z when looking along Y). One definition, so the
// editor's hit-tests land where the figures draw.
struct FigureProjection {
  glm::vec3 right{1, 0, 0}, up{0, 1, 0};
  // Any non-zero direction (normalised here); zero gives the board view.
  static FigureProjection along(glm::vec3 viewDirection);
  glm::vec2 project(glm::vec3 p) const { return {glm::dot(p, right), glm::dot(p, up)}; }
};

}  // namespace kinema
