// Motion control along a path: arc-length table, its inverse, distance-time functions.
#include <gtest/gtest.h>

#include <cmath>

#include "anim/arc_length.h"
#include "anim_test_support.h"

namespace kinema {
namespace KINEMA_UNITY_ID {

Channel path(const std::vector<float>& times, const std::vector<glm::vec3>& points, Interpolation mode) {
  Channel c;
  c.joint = 0;
  c.target = ChannelTarget::Translation;
  c.interpolation = mode;
  c.times = times;
  for (const glm::vec3& p : points) c.values.emplace_back(p, 0.0f);
  return c;
}

// P(u) = (u, u^2, 0) on [0, 1] as one Hermite segment (a cubic reproduces the parabola):
// tangents (1, 0, 0) and (1, 2, 0) per second.
Channel parabola() {
  Channel c = path({0, 1}, {{0, 0, 0}, {1, 1, 0}}, Interpolation::Hermite);
  KeySettings s;
  s.interpolation = Interpolation::Hermite;
  c.keys.assign(2, s);
  c.keys[0].outTangent = {1, 0, 0, 0};
  c.keys[1].inTangent = {1, 2, 0, 0};
  return c;
}

// Arc length of y = x^2 from 0 to x: x sqrt(1 + 4x^2) / 2 + asinh(2x) / 4.
double parabolaLength(double x) { return x * std::sqrt(1 + 4 * x * x) / 2 + std::asinh(2 * x) / 4; }

TEST(ArcLength, StraightLineAndParabolaInClosedForm) {
  const Channel line = path({0, 2}, {{0, 0, 0}, {3, 4, 0}}, Interpolation::Linear);
  // Float samples limit this to about 1e-5 relative.
  EXPECT_NEAR(buildArcLengthTable(line).length(), 5.0, 5e-5);
  const Channel p = parabola();
  const ArcLengthTable table = buildArcLengthTable(p, 256);
  EXPECT_NEAR(table.length(), parabolaLength(1.0), 1e-5 * parabolaLength(1.0));  // 1.4789428
  // u(s) inverts s(u): s(u(S)) = S, with s in closed form.
  for (double S : {0.01, 0.2, 0.7, 1.1, 1.45}) {
    const double u = parameterAtDistance(table, S);
    EXPECT_NEAR(parabolaLength(u), S, 1e-5) << S;
  }
  EXPECT_EQ(parameterAtDistance(table, -1.0), 0.0f);
  EXPECT_EQ(parameterAtDistance(table, 99.0), 1.0f);
}

Channel catmullRomPath() {
  return path({0, 1, 2.5f, 3, 4.5f}, {{0, 0, 0}, {2, 1, 0}, {3, 4, 1}, {1, 5, 2}, {-1, 3, 0}},
              Interpolation::CatmullRom);
}

TEST(MotionControl, ConstantSpeedAlongACatmullRomPath) {
  const Channel p = catmullRomPath();
  const ArcLengthTable table = buildArcLengthTable(p);
  DistanceProfile profile;
  profile.kind = DistanceProfile::Kind::ConstantSpeed;
  profile.duration = 4.0;
  profile.distance = table.length();
  const int n = 200;
  const double dt = profile.duration / n, expected = table.length() / profile.duration;
  double walked = 0.0;
  for (int i = 0; i < n; ++i) {
    const glm::dvec3 a(positionAtTime(table, profile, i * dt)), b(positionAtTime(table, profile, (i + 1) * dt));
    const double speed = glm::length(b - a) / dt;
    EXPECT_NEAR(speed, expected, 0.005 * expected) << i;
    walked += glm::length(b - a);
  }
  // The whole path is covered: the end is the last key, the polyline is the length.
  EXPECT_EQ(positionAtTime(table, profile, profile.duration), glm::vec3(p.values.back()));
  EXPECT_NEAR(walked, table.length(), 1e-3 * table.length());
  EXPECT_NEAR(distanceAt(profile, profile.duration), table.length(), 1e-4 * table.length());
  // Without motion control the same path is walked at a very uneven speed.
  double lo = 1e9, hi = 0;
  for (int i = 0; i < n; ++i) {
    const float t0 = static_cast<float>(4.5 * i / n), t1 = static_cast<float>(4.5 * (i + 1) / n);
    const double s = glm::length(glm::dvec3(glm::vec3(sampleChannel(p, t1) - sampleChannel(p, t0)))) / (t1 - t0);
    lo = std::min(lo, s);
    hi = std::max(hi, s);
  }
  EXPECT_GT(hi / lo, 1.5);
}

TEST(MotionControl, EaseInOutStartsAndEndsAtRest) {
  const Channel p = catmullRomPath();
  const ArcLengthTable table = buildArcLengthTable(p);
  for (DistanceProfile::Kind kind : {DistanceProfile::Kind::SineEase, DistanceProfile::Kind::ParabolicEase}) {
    DistanceProfile profile;
    profile.kind = kind;
    profile.duration = 3.0;
    profile.distance = table.length();
    const double h = 1e-4;
    const double mean = table.length() / profile.duration;
    EXPECT_LT(distanceAt(profile, h) / h, 1e-3 * mean);
    EXPECT_LT((profile.distance - distanceAt(profile, profile.duration - h)) / h, 1e-3 * mean);
    EXPECT_NEAR(distanceAt(profile, profile.duration), table.length(), 1e-9);
    // Position speed at the ends, too.
    const double v0 = glm::length(glm::dvec3(positionAtTime(table, profile, 0.01) - positionAtTime(table, profile, 0))) / 0.01;
    EXPECT_LT(v0, 0.05 * mean);
  }
  // Parabolic ease: constant acceleration to 0.25 T, then constant speed v0 with
  // v0 (0.125 + 0.5 + 0.125) = D, so v0 = 4D/3 per unit time fraction.
  DistanceProfile q;
  q.kind = DistanceProfile::Kind::ParabolicEase;
  q.duration = 1.0;
  q.distance = 3.0;
  EXPECT_NEAR(distanceAt(q, 0.1), 4.0 * 0.01 / (2 * 0.25), 1e-12);   // v0 x^2 / (2a)
  EXPECT_NEAR(distanceAt(q, 0.5), 4.0 * (0.125 + 0.25), 1e-12);        // v0 (a/2 + x - a)
}

TEST(MotionControl, VelocityCurveIsIntegrated) {
  // v(t) = t (linear keys (0,0) (2,2)): s(t) = t^2 / 2.
  Channel v = test::scalarChannel({0, 2}, {0, 2}, Interpolation::Linear);
  DistanceProfile p;
  p.kind = DistanceProfile::Kind::VelocityCurve;
  p.duration = 2.0;
  p.velocity = &v;
  EXPECT_TRUE(p.validate().empty());
  prepareDistanceProfile(p);
  for (double t : {0.0, 0.3, 1.0, 1.7, 2.0}) EXPECT_NEAR(distanceAt(p, t), t * t / 2, 1e-6) << t;
  DistanceProfile bad;
  bad.kind = DistanceProfile::Kind::VelocityCurve;
  EXPECT_FALSE(bad.validate().empty());
  bad.kind = DistanceProfile::Kind::ParabolicEase;
  bad.accelEnd = 0.8;
  bad.decelStart = 0.2;
  EXPECT_FALSE(bad.validate().empty());
}

}  // namespace
}  // namespace kinema
