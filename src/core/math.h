#pragma once
// GLM with the experimental extensions Kinema uses (quaternion helpers, matrix decomposition).
#ifndef GLM_ENABLE_EXPERIMENTAL
#define GLM_ENABLE_EXPERIMENTAL
#endif
#include <glm/glm.hpp>
#include <glm/gtc/quaternion.hpp>
#include <glm/gtc/type_ptr.hpp>

#include <cmath>

namespace kinema {

// π once, in float (the precision of the pose maths); kDegree is one degree in radians.
constexpr float kPi = 3.14159265358979323846f;
constexpr float kTwoPi = 2.0f * kPi;
constexpr float kDegree = kPi / 180.0f;

inline bool isFinite(const glm::vec3& v) {
  return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}
inline bool isFinite(const glm::vec4& v) {
  return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z) && std::isfinite(v.w);
}
inline bool isFinite(const glm::mat4& m) { return isFinite(m[0]) && isFinite(m[1]) && isFinite(m[2]) && isFinite(m[3]); }
inline bool isFinite(const glm::quat& q) {
  return std::isfinite(q.x) && std::isfinite(q.y) && std::isfinite(q.z) && std::isfinite(q.w);
}

// |a - b| computed in double, so far points (past about 1.8e19, where float's squares
// overflow) still give their distance; infinite only beyond float's range.
inline float distanceInDouble(const glm::vec3& a, const glm::vec3& b) {
  const glm::dvec3 d = glm::dvec3(a) - glm::dvec3(b);
  return static_cast<float>(std::sqrt(d.x * d.x + d.y * d.y + d.z * d.z));
}

}  // namespace kinema
