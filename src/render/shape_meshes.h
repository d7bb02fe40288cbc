#pragma once
#include <vector>

#include "core/math.h"

namespace kinema {

// A triangle list with one normal per vertex (flat shapes repeat their corners per face).
struct ShapeMesh {
  std::vector<glm::vec3> positions;
  std::vector<glm::vec3> normals;
  int vertexCount() const { return static_cast<int>(positions.size()); }
};

// Blender's octahedral bone in bone space: head at the origin, tail at (0, 1, 0), the
// square waist at y = 0.1 with corners (+-0.1, 0.1, +-0.1). Scaling by the bone's length
// keeps Blender's proportions. 8 flat faces, counter-clockwise seen from outside.
ShapeMesh makeOctahedralBone();

// A unit sphere (radius 1, centre at the origin) with smooth normals; `slices` around Y,
// `stacks` from pole to pole. Counter-clockwise seen from outside.
ShapeMesh makeSphere(int slices, int stacks);

}  // namespace kinema
