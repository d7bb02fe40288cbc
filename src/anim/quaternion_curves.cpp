#include "anim/quaternion_curves.h"

#include <cmath>

#include "anim/hermite.h"
#include "core/rotation.h"

namespace kinema {

glm::vec3 quatLog(const glm::quat& q) {
  const glm::vec3 v(q.x, q.y, q.z);
  const float s = glm::length(v);
  if (s < 1e-12f) return glm::vec3(0.0f);
  return v * (std::atan2(s, q.w) / s);
}

glm::quat quatExp(const glm::vec3& v) {
  const float a = glm::length(v);
  if (a < 1e-12f) return glm::quat(1, v.x, v.y, v.z);
  const glm::vec3 axis = v * (std::sin(a) / a);
  return glm::quat(std::cos(a), axis.x, axis.y, axis.z);
}

glm::quat nlerpShortest(const glm::quat& a, const glm::quat& b, float t) {
  const glm::quat bb = sameHemisphere(b, a);
  const glm::quat m(a.w + (bb.w - a.w) * t, a.x + (bb.x - a.x) * t, a.y + (bb.y - a.y) * t, a.z + (bb.z - a.z) * t);
  return safeNormalize(m);
}

namespace {

// Body-frame log of the rotation from `from` to `to` (both unit, same hemisphere).
glm::vec3 relLog(const glm::quat& from, const glm::quat& to) { return quatLog(glm::conjugate(from) * to); }

glm::quat slerpRaw(const glm::quat& a, const glm::quat& b, float t) {
  // No hemisphere flip: squad's inner slerps must follow the chosen signs.
  return safeNormalize(a * quatExp(relLog(a, b) * t));
}

}  // namespace

glm::quat squad(const glm::quat& q0in, const glm::quat& q1, const glm::quat& q2in, const glm::quat& q3in,
                float t0, float t1, float t2, float t3, bool hasPrevious, bool hasNext, float u) {
  const glm::quat q2 = sameHemisphere(q2in, q1);
  const glm::quat q0 = sameHemisphere(q0in, q1);
  const glm::quat q3 = sameHemisphere(q3in, q2);
  const float dt = t2 - t1;
  const glm::vec3 chord1 = relLog(q1, q2);       // at q1 toward q2
  const glm::vec3 chord2 = relLog(q2, q1);       // at q2 toward q1
  // Angular velocities (log space, per second) at q1 and q2.
  const glm::vec3 w1 = hasPrevious ? (chord1 - relLog(q1, q0)) / (t2 - t0) : chord1 / dt;
  const glm::vec3 w2 = hasNext ? (relLog(q2, q3) - chord2) / (t3 - t1) : -chord2 / dt;
  // Derivative of squad at u=0 is chord1 + 2 log(q1^-1 a); at u=1 it is -(chord2 + 2 log(q2^-1 b)).
  const glm::quat a = q1 * quatExp((w1 * dt - chord1) * 0.5f);
  const glm::quat b = q2 * quatExp(-(w2 * dt + chord2) * 0.5f);
  return slerpRaw(slerpRaw(q1, q2, u), slerpRaw(a, b, u), 2 * u * (1 - u));
}

glm::quat gltfCubicRotation(const glm::vec4& v0, const glm::vec4& m0, const glm::vec4& v1, const glm::vec4& m1,
                            float dt, float u) {
  const glm::vec4 v = hermite(v0, m0, v1, m1, dt, u);
  return safeNormalize(glm::quat(v.w, v.x, v.y, v.z));
}

}  // namespace kinema
