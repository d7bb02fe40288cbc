#include "render/shape_meshes.h"

#include <algorithm>
#include <array>
#include <map>

namespace kinema {

namespace {
void addFlatTriangle(ShapeMesh& m, const glm::vec3& a, const glm::vec3& b, const glm::vec3& c) {
  const glm::vec3 n = glm::normalize(glm::cross(b - a, c - a));
  for (const glm::vec3& p : {a, b, c}) {
    m.positions.push_back(p);
    m.normals.push_back(n);
  }
}
}  // namespace

ShapeMesh makeOctahedralBone() {
  const glm::vec3 head(0.0f), tail(0.0f, 1.0f, 0.0f);
  // The waist corners go counter-clockwise seen from the tail (looking down -Y).
  const glm::vec3 waist[4] = {{0.1f, 0.1f, 0.1f}, {0.1f, 0.1f, -0.1f}, {-0.1f, 0.1f, -0.1f}, {-0.1f, 0.1f, 0.1f}};
  ShapeMesh m;
  for (int i = 0; i < 4; ++i) {
    const glm::vec3& a = waist[i];
    const glm::vec3& b = waist[(i + 1) % 4];
    addFlatTriangle(m, a, b, tail);
    addFlatTriangle(m, b, a, head);
  }
  return m;
}

ShapeMesh makeSquare() {
  ShapeMesh m;
  const glm::vec3 a(-1, -1, 0), b(1, -1, 0), c(1, 1, 0), d(-1, 1, 0);
  addFlatTriangle(m, a, b, c);
  addFlatTriangle(m, a, c, d);
  return m;
}

ShapeMesh makeSphere(int slices, int stacks) {
  slices = std::max(slices, 3);
  stacks = std::max(stacks, 2);
  const float pi = glm::pi<float>();
  auto point = [&](int i, int j) {
    const float theta = pi * static_cast<float>(j) / static_cast<float>(stacks);  // from +Y down
    const float phi = 2.0f * pi * static_cast<float>(i % slices) / static_cast<float>(slices);
    return glm::vec3(std::sin(theta) * std::sin(phi), std::cos(theta), std::sin(theta) * std::cos(phi));
  };
  ShapeMesh m;
  auto add = [&m](const glm::vec3& p) {
    m.positions.push_back(p);
    m.normals.push_back(p);  // on a unit sphere the position is the normal
  };
  for (int j = 0; j < stacks; ++j) {
    for (int i = 0; i < slices; ++i) {
      const glm::vec3 a = point(i, j), b = point(i, j + 1), c = point(i + 1, j + 1), d = point(i + 1, j);
      if (j != 0) {  // the top row's quads are triangles (a and d coincide at the pole)
        add(a); add(b); add(d);
      }
      if (j != stacks - 1) {
        add(b); add(c); add(d);
      }
    }
  }
  return m;
}

IndexedShapeMesh weldVertices(const ShapeMesh& mesh) {
  IndexedShapeMesh out;
  std::map<std::array<float, 6>, unsigned int> seen;  // +0 and -0 compare equal, as they draw alike
  out.indices.reserve(mesh.positions.size());
  for (size_t i = 0; i < mesh.positions.size(); ++i) {
    const glm::vec3 &p = mesh.positions[i], &n = mesh.normals[i];
    const auto key = std::array<float, 6>{p.x + 0.0f, p.y + 0.0f, p.z + 0.0f, n.x + 0.0f, n.y + 0.0f, n.z + 0.0f};
    const auto [at, added] = seen.emplace(key, static_cast<unsigned int>(out.positions.size()));
    if (added) {
      out.positions.push_back(p);
      out.normals.push_back(n);
    }
    out.indices.push_back(at->second);
  }
  return out;
}

}  // namespace kinema
