#pragma once
#include <vector>

#include "core/math.h"

namespace kinema {

struct LineVertex {
  glm::vec3 position;
  glm::vec4 color;
};

// The ground grid on y = 0 (pairs of vertices, one line each): square cells of `cellSize`
// around the world origin, reaching at least `reach` from it, every fifth line brighter;
// the X axis drawn red and the Z axis blue through the origin (Blender's colours), and a
// short green Y axis up from the origin.
std::vector<LineVertex> makeGridLines(float cellSize, float reach);

}  // namespace kinema
