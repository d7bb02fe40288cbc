#include "editor/viewport/capsule_shape.h"
#include "core/math.h"

#include <algorithm>
#include <cmath>

namespace kinema {

namespace {

// Points centre + r (cos t u + sin t v) for t from t0 to t1 inclusive.
std::vector<glm::vec3> arc(const glm::vec3& centre, const glm::vec3& u, const glm::vec3& v, float r, float t0, float t1,
                           int steps) {
  std::vector<glm::vec3> points;
  points.reserve(static_cast<size_t>(steps) + 1);
  for (int k = 0; k <= steps; ++k) {
    const float t = t0 + (t1 - t0) * static_cast<float>(k) / static_cast<float>(steps);
    points.push_back(centre + r * (std::cos(t) * u + std::sin(t) * v));
  }
  return points;
}
}  // namespace

CapsuleWire capsuleWire(const glm::vec3& a, const glm::vec3& b, float radius, int segments) {
  CapsuleWire out;
  segments = std::max(segments, 8);
  const glm::vec3 d = b - a;
  const float length = glm::length(d);
  if (!(radius > 0.0f) || !isFinite(a) || !isFinite(b)) return out;
  const glm::vec3 axis = length > 1e-6f * radius ? d / length : glm::vec3(0, 1, 0);
  const glm::vec3 other = std::abs(axis.x) < 0.9f ? glm::vec3(1, 0, 0) : glm::vec3(0, 0, 1);
  const glm::vec3 u = glm::normalize(other - axis * glm::dot(other, axis));
  const glm::vec3 v = glm::cross(axis, u);
  out.polylines.push_back(arc(a, u, v, radius, 0.0f, 2 * kPi, segments));
  if (length <= 1e-6f * radius) {  // a sphere: the other two great circles
    out.polylines.push_back(arc(a, u, axis, radius, 0.0f, 2 * kPi, segments));
    out.polylines.push_back(arc(a, v, axis, radius, 0.0f, 2 * kPi, segments));
    return out;
  }
  out.polylines.push_back(arc(b, u, v, radius, 0.0f, 2 * kPi, segments));
  for (const glm::vec3& side : {u, v, -u, -v}) out.polylines.push_back({a + radius * side, b + radius * side});
  // The caps bulge away from the segment: behind a (towards -axis) and past b (towards +axis).
  const int half = segments / 2;
  out.polylines.push_back(arc(a, u, -axis, radius, 0.0f, kPi, half));
  out.polylines.push_back(arc(a, v, -axis, radius, 0.0f, kPi, half));
  out.polylines.push_back(arc(b, u, axis, radius, 0.0f, kPi, half));
  out.polylines.push_back(arc(b, v, axis, radius, 0.0f, kPi, half));
  return out;
}

}  // namespace kinema
