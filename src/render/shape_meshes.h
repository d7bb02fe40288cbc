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

// The same triangles with each distinct (position, normal) pair stored once and referenced by
// index, in the same order: a rasteriser then shades each corner once instead of once per
// triangle (a 16 x 10 sphere: 146 vertices instead of 864). Pairs are merged only when equal.
struct IndexedShapeMesh {
  std::vector<glm::vec3> positions;
  std::vector<glm::vec3> normals;
  std::vector<unsigned int> indices;  // three per triangle, into positions / normals
};
IndexedShapeMesh weldVertices(const ShapeMesh& mesh);

// Blender's octahedral bone in bone space: head at the origin, tail at (0, 1, 0), the
// square waist at y = 0.1 with corners (+-0.1, 0.1, +-0.1). Scaling by the bone's length
// keeps Blender's proportions. 8 flat faces, counter-clockwise seen from outside.
ShapeMesh makeOctahedralBone();

// The square [-1, 1]^2 in the plane z = 0: two triangles, counter-clockwise seen from +z
// (the card a sphere impostor is drawn on, shaders/sphere_impostor.*).
ShapeMesh makeSquare();

// A unit sphere (radius 1, centre at the origin) with smooth normals; `slices` around Y,
// `stacks` from pole to pole. Counter-clockwise seen from outside.
ShapeMesh makeSphere(int slices, int stacks);

}  // namespace kinema
