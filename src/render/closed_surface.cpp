#include "render/closed_surface.h"

#include <array>
#include <map>
#include <utility>

namespace kinema {

bool isClosedOutwardSurface(const std::vector<glm::vec3>& positions, const std::vector<uint32_t>& indices) {
  if (indices.empty() || indices.size() % 3 != 0) return false;
  // Vertices at one place are one point (+0 and -0 alike).
  std::map<std::array<float, 3>, int> pointOf;
  std::vector<int> point(positions.size());
  for (size_t v = 0; v < positions.size(); ++v) {
    const glm::vec3& p = positions[v];
    point[v] = pointOf.emplace(std::array<float, 3>{p.x + 0.0f, p.y + 0.0f, p.z + 0.0f}, static_cast<int>(pointOf.size()))
                   .first->second;
  }
  std::map<std::pair<int, int>, int> edges;  // directed edge -> times met
  double volume = 0.0;
  for (size_t t = 0; t < indices.size(); t += 3) {
    int corner[3];
    for (int k = 0; k < 3; ++k) {
      if (indices[t + k] >= positions.size()) return false;
      corner[k] = point[indices[t + k]];
    }
    for (int k = 0; k < 3; ++k) {
      const int a = corner[k], b = corner[(k + 1) % 3];
      if (a == b) return false;  // a degenerate triangle: no consistent winding to rely on
      ++edges[{a, b}];
    }
    const glm::dvec3 a(positions[indices[t]]), b(positions[indices[t + 1]]), c(positions[indices[t + 2]]);
    volume += glm::dot(a, glm::cross(b, c)) / 6.0;
  }
  for (const auto& [edge, count] : edges) {
    if (count != 1) return false;
    const auto back = edges.find({edge.second, edge.first});
    if (back == edges.end() || back->second != 1) return false;
  }
  return volume > 0.0;
}

bool boxInFrontOfNearPlane(const glm::mat4& viewProjection, const glm::vec3& min, const glm::vec3& max) {
  for (int k = 0; k < 8; ++k) {
    const glm::vec4 c =
        viewProjection * glm::vec4(k & 1 ? max.x : min.x, k & 2 ? max.y : min.y, k & 4 ? max.z : min.z, 1.0f);
    if (!(c.w > 0.0f && c.z > -c.w)) return false;
  }
  return true;
}

}  // namespace kinema
