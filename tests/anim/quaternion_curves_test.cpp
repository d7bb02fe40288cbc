// Rotation channels: slerp, nlerp, squad, glTF cubic spline, eased slerp.
#include <gtest/gtest.h>

#include <cmath>

#include "anim/quaternion_curves.h"
#include "anim_test_support.h"

namespace kinema {
namespace KINEMA_UNITY_ID {

constexpr double kPi = 3.14159265358979323846;

glm::vec4 rot(const glm::vec3& axis, double angle) {
  const glm::vec3 a = glm::normalize(axis);
  const float s = static_cast<float>(std::sin(angle / 2)), c = static_cast<float>(std::cos(angle / 2));
  return {s * a.x, s * a.y, s * a.z, c};
}

glm::dquat dq(const glm::vec4& v) { return glm::dquat(v.w, v.x, v.y, v.z); }

// Angle (radians, [0, pi]) of the rotation between two unit quaternions.
double angleBetween(const glm::vec4& a, const glm::vec4& b) {
  const double d = std::abs(glm::dot(glm::dvec4(a), glm::dvec4(b)));
  return 2.0 * std::acos(std::min(1.0, d));
}

Channel rotationChannel(const std::vector<float>& times, const std::vector<glm::vec4>& values, Interpolation mode) {
  Channel c;
  c.joint = 0;
  c.target = ChannelTarget::Rotation;
  c.interpolation = mode;
  c.times = times;
  c.values = values;
  return c;
}

glm::vec4 at(const Channel& c, double t) { return sampleChannel(c, static_cast<float>(t)); }

// Body-frame angular velocity vector by a one-sided difference.
glm::dvec3 angularVelocity(const Channel& c, double t, double h) {
  const glm::dquat a = dq(at(c, t)), b = dq(at(c, t + h));
  glm::dquat r = glm::conjugate(h > 0 ? a : b) * (h > 0 ? b : a);
  if (r.w < 0) r = -r;
  const glm::dvec3 v(r.x, r.y, r.z);
  const double s = glm::length(v);
  if (s < 1e-15) return glm::dvec3(0.0);
  return v * (2.0 * std::atan2(s, r.w) / s / std::abs(h));
}

TEST(Slerp, UnitLengthConstantAngularVelocityShortestArc) {
  // 170 degrees about (1,1,0); the second key is stored negated (same rotation, other
  // hemisphere): the path must still be the 170-degree arc, not the 190-degree one.
  const double theta = 170.0 * kPi / 180.0;
  const glm::vec4 a = rot({0, 0, 1}, 0.3), b = -rot({1, 1, 0}, theta);
  const Channel c = rotationChannel({0, 2}, {a, glm::vec4(dq(b).x, dq(b).y, dq(b).z, dq(b).w)}, Interpolation::Linear);
  const double total = angleBetween(a, b);
  for (int i = 0; i <= 20; ++i) {
    const double t = 2.0 * i / 20;
    const glm::vec4 q = at(c, t);
    EXPECT_NEAR(glm::length(glm::dvec4(q)), 1.0, 1e-6) << t;
    EXPECT_NEAR(angleBetween(a, q), total * t / 2, 2e-5) << t;
  }
  EXPECT_LT(total, kPi);
}

TEST(Nlerp, UnitLengthButNotConstantSpeed) {
  // 120 degrees about Z. nlerp's half-angle alpha at t satisfies
  // tan(alpha) = t sin(60deg) / ((1 - t) + t cos(60deg)); t = 1/4: tan = 0.216506/0.875,
  // alpha = 13.8979 deg, so the angle is 27.7958 deg (slerp: 30).
  const Channel c = rotationChannel({0, 1}, {rot({0, 0, 1}, 0), rot({0, 0, 1}, 2 * kPi / 3)}, Interpolation::Nlerp);
  const glm::vec4 q = at(c, 0.25);
  EXPECT_NEAR(glm::length(glm::dvec4(q)), 1.0, 1e-6);
  EXPECT_NEAR(angleBetween(rot({0, 0, 1}, 0), q) * 180 / kPi, 2 * std::atan(0.216506351 / 0.875) * 180 / kPi, 1e-3);
  EXPECT_NEAR(angleBetween(rot({0, 0, 1}, 0), at(c, 0.5)) * 180 / kPi, 60.0, 1e-3);  // symmetric midpoint
  // Shortest arc across the sign flip too.
  const Channel flipped = rotationChannel({0, 1}, {rot({0, 0, 1}, 0), -rot({0, 0, 1}, 2 * kPi / 3)}, Interpolation::Nlerp);
  EXPECT_NEAR(angleBetween(at(c, 0.25), at(flipped, 0.25)), 0.0, 1e-3);
}

TEST(Squad, PassesThroughKeysAndIsC1AtKeys) {
  const std::vector<float> times = {0, 0.5f, 1.75f, 2.25f, 3.5f};
  const std::vector<glm::vec4> keys = {rot({0, 1, 0}, 0.2), -rot({1, 0.2f, 0}, 1.4), rot({0.3f, 1, 0.5f}, 2.5),
                                       rot({0, 0, 1}, -0.7), rot({1, 1, 1}, 1.1)};
  const Channel c = rotationChannel(times, keys, Interpolation::Squad);
  const Channel lin = rotationChannel(times, keys, Interpolation::Linear);
  for (size_t k = 0; k < keys.size(); ++k) EXPECT_NEAR(angleBetween(at(c, times[k]), keys[k]), 0.0, 1e-3) << k;
  const double h = 1e-3;
  for (int k = 1; k <= 3; ++k) {
    // Richardson: 2 w(h) - w(2h) cancels the first-order error of one-sided differences.
    const glm::dvec3 left = 2.0 * angularVelocity(c, times[k], -h) - angularVelocity(c, times[k], -2 * h);
    const glm::dvec3 right = 2.0 * angularVelocity(c, times[k], h) - angularVelocity(c, times[k], 2 * h);
    EXPECT_LT(glm::length(left - right), 0.02 * std::max(1.0, glm::length(right))) << k;
    // Slerp through the same keys has a visible kink there (so this test can fail).
    const glm::dvec3 l2 = angularVelocity(lin, times[k], -h), r2 = angularVelocity(lin, times[k], h);
    EXPECT_GT(glm::length(l2 - r2), 0.3) << k;
  }
  for (int i = 0; i <= 70; ++i) EXPECT_NEAR(glm::length(glm::dvec4(at(c, i * 0.05))), 1.0, 1e-5);
}

TEST(GltfCubicSpline, ComponentWiseHermiteThenNormalised) {
  // v0 = identity (0,0,0,1), v1 = (0,0,1,0), 2 s apart, out tangent of key 0 = (0,0,2,0)/s.
  // At u = 1/2: 0.5 v0 + 0.125*2*(0,0,2,0) + 0.5 v1 = (0, 0, 1, 0.5) -> (0, 0, 2, 1)/sqrt(5).
  Channel c = rotationChannel({0, 2}, {{0, 0, 0, 1}, {0, 0, 1, 0}}, Interpolation::Hermite);
  KeySettings s;
  s.interpolation = Interpolation::Hermite;
  c.keys.assign(2, s);
  c.keys[0].outTangent = {0, 0, 2, 0};
  const glm::vec4 q = at(c, 1.0);
  EXPECT_NEAR(q.z, 2 / std::sqrt(5.0), 1e-6);
  EXPECT_NEAR(q.w, 1 / std::sqrt(5.0), 1e-6);
  EXPECT_NEAR(q.x, 0.0, 1e-7);
}

TEST(EasedSlerp, EasesTheAngle) {
  // Quad-in at half time covers a quarter of the 90-degree arc.
  Channel c = rotationChannel({0, 1}, {rot({0, 1, 0}, 0), rot({0, 1, 0}, kPi / 2)}, Interpolation::Ease);
  KeySettings s;
  s.interpolation = Interpolation::Ease;
  s.easing = EasingFunction::Quad;
  s.easingMode = EasingMode::In;
  c.keys.assign(2, s);
  EXPECT_NEAR(angleBetween(rot({0, 1, 0}, 0), at(c, 0.5)), kPi / 8, 1e-5);
}

TEST(QuatLogExp, RoundTrip) {
  const glm::quat q = glm::normalize(glm::quat(0.3f, -0.5f, 0.7f, 0.2f));
  const glm::quat r = quatExp(quatLog(q));
  EXPECT_NEAR(glm::dot(q, r), 1.0f, 1e-6f);
}

}  // namespace
}  // namespace kinema
