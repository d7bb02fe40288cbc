// Scalar curves: Hermite, Catmull-Rom, TCB. Expected values are derived by hand in the
// comments from the standard formulas (not printed by the code).
#include <gtest/gtest.h>

#include "anim/hermite.h"
#include "anim/tcb_spline.h"
#include "anim_test_support.h"

namespace kinema {
namespace KINEMA_UNITY_ID {

using test::leftSlope;
using test::rightSlope;
using test::scalarChannel;
using test::valueAt;

TEST(HermiteBasis, KnownValues) {
  // u = 1/2: h00 = 2/8 - 3/4 + 1, h10 = 1/8 - 1/2 + 1/2, h01 = -2/8 + 3/4, h11 = 1/8 - 1/4.
  HermiteBasis b = hermiteBasis(0.5f);
  EXPECT_FLOAT_EQ(b.h00, 0.5f);
  EXPECT_FLOAT_EQ(b.h10, 0.125f);
  EXPECT_FLOAT_EQ(b.h01, 0.5f);
  EXPECT_FLOAT_EQ(b.h11, -0.125f);
  // u = 1/4: 2/64 - 3/16 + 1 = 0.84375; 1/64 - 2/16 + 1/4 = 0.140625; -2/64 + 3/16 = 0.15625;
  // 1/64 - 1/16 = -0.046875. h01 != h10 here, so a swapped basis fails.
  b = hermiteBasis(0.25f);
  EXPECT_FLOAT_EQ(b.h00, 0.84375f);
  EXPECT_FLOAT_EQ(b.h10, 0.140625f);
  EXPECT_FLOAT_EQ(b.h01, 0.15625f);
  EXPECT_FLOAT_EQ(b.h11, -0.046875f);
  for (float u : {0.0f, 1.0f}) {
    b = hermiteBasis(u);
    EXPECT_EQ(b.h00 + b.h01, 1.0f);  // partition of unity in the value terms
    EXPECT_EQ(b.h10, 0.0f);
    EXPECT_EQ(b.h11, 0.0f);
  }
}

TEST(Hermite, ExplicitTangentsPerSecond) {
  // Keys (0, 1) and (2, 3), out tangent 4/s at the first, in tangent -2/s at the second.
  // t = 0.5 is u = 1/4 of a 2 s segment: 0.84375*1 + 0.140625*2*4 + 0.15625*3 + (-0.046875)*2*(-2)
  // = 0.84375 + 1.125 + 0.46875 + 0.1875 = 2.625.
  Channel c = scalarChannel({0, 2}, {1, 3}, Interpolation::Hermite);
  c.keys[0].outTangent.x = 4;
  c.keys[1].inTangent.x = -2;
  EXPECT_NEAR(valueAt(c, 0.5), 2.625, 1e-6);
  // The tangents are the curve's slopes at the keys.
  EXPECT_NEAR(rightSlope(c, 0.0), 4.0, 2e-3);
  EXPECT_NEAR(leftSlope(c, 2.0), -2.0, 2e-3);
}

TEST(CatmullRom, NonUniformTangentsAndNaturalEnds) {
  // Keys (0,0) (1,1) (3,0) (4,2). Tangents: key1 (0-0)/(3-0) = 0, key2 (2-1)/(4-1) = 1/3.
  // Natural first key: 1.5 * (1-0)/1 - 0.5 * 0 = 1.5.
  const Channel c = scalarChannel({0, 1, 3, 4}, {0, 1, 0, 2}, Interpolation::CatmullRom);
  glm::vec4 in, out;
  tcbTangents(c, 1, false, in, out);
  EXPECT_FLOAT_EQ(out.x, 0.0f);
  tcbTangents(c, 2, false, in, out);
  EXPECT_FLOAT_EQ(out.x, 1.0f / 3.0f);
  EXPECT_FLOAT_EQ(in.x, 1.0f / 3.0f);
  tcbTangents(c, 0, false, in, out);
  EXPECT_FLOAT_EQ(out.x, 1.5f);
  // Segment 1->2 (dt 2) at t = 2, u = 1/2: 0.5*1 + 0.125*2*0 + 0.5*0 - 0.125*2*(1/3) = 5/12.
  EXPECT_NEAR(valueAt(c, 2.0), 5.0 / 12.0, 1e-6);
  // Segment 0->1 at u = 1/2: 0.125*1.5 + 0.5*1 = 0.6875.
  EXPECT_NEAR(valueAt(c, 0.5), 0.6875, 1e-6);
  // Natural end: no curvature at the first and last keys.
  const double h = 1e-2;
  EXPECT_NEAR((valueAt(c, 2 * h) - 2 * valueAt(c, h) + valueAt(c, 0)) / (h * h), 0.0, 0.1);
  EXPECT_NEAR((valueAt(c, 4) - 2 * valueAt(c, 4 - h) + valueAt(c, 4 - 2 * h)) / (h * h), 0.0, 0.1);
}

TEST(CatmullRom, IsC1AtEveryInteriorKeyEvenWithUnevenSpacing) {
  const Channel c = scalarChannel({0, 0.3f, 1.5f, 1.7f, 3}, {0, 2, -1, 0.5f, 4}, Interpolation::CatmullRom);
  for (int k = 1; k < 4; ++k) {
    const double t = c.times[k];
    const double expected = (c.values[k + 1].x - c.values[k - 1].x) / (c.times[k + 1] - c.times[k - 1]);
    EXPECT_NEAR(leftSlope(c, t), expected, 0.01 * std::max(1.0, std::abs(expected))) << k;
    EXPECT_NEAR(rightSlope(c, t), expected, 0.01 * std::max(1.0, std::abs(expected))) << k;
  }
}

TEST(TCB, ZeroParametersEqualCatmullRom) {
  const std::vector<float> times = {0, 0.4f, 1.1f, 2, 2.2f, 3.5f};
  const std::vector<float> values = {1, -2, 0.5f, 3, 3, -1};
  const Channel cr = scalarChannel(times, values, Interpolation::CatmullRom);
  const Channel tcb = scalarChannel(times, values, Interpolation::TCB);
  for (int i = 0; i <= 350; ++i) EXPECT_EQ(valueAt(cr, i * 0.01), valueAt(tcb, i * 0.01)) << i;
}

TEST(TCB, ContinuityMakesACorner) {
  // Keys (0,0) (1,1) (2,0), C = 0.5 at key 1. Chords a = 1, b = -1, span 2:
  // out = (1.5*1*1 + 0.5*1*(-1)) / 2 = 0.5; in = (0.5*1 + 1.5*(-1)) / 2 = -0.5.
  Channel c = scalarChannel({0, 1, 2}, {0, 1, 0}, Interpolation::TCB);
  c.keys[1].continuity = 0.5f;
  glm::vec4 in, out;
  tcbTangents(c, 1, true, in, out);
  EXPECT_FLOAT_EQ(out.x, 0.5f);
  EXPECT_FLOAT_EQ(in.x, -0.5f);
  EXPECT_NEAR(leftSlope(c, 1.0), -0.5, 2e-3);
  EXPECT_NEAR(rightSlope(c, 1.0), 0.5, 2e-3);
  // With C = 0 both sides agree (a peak: slope 0).
  c.keys[1].continuity = 0.0f;
  EXPECT_NEAR(leftSlope(c, 1.0), rightSlope(c, 1.0), 1e-3);
}

TEST(TCB, TensionScalesTheTangents) {
  Channel c = scalarChannel({0, 1, 2}, {0, 1, 3}, Interpolation::TCB);
  c.keys[1].tension = 1.0f;  // (1 - T) = 0: the curve stops at the key
  glm::vec4 in, out;
  tcbTangents(c, 1, true, in, out);
  EXPECT_EQ(out.x, 0.0f);
  EXPECT_EQ(in.x, 0.0f);
  c.keys[1].tension = -1.0f;  // twice the Catmull-Rom tangent (3/2 * 2 = 3)
  tcbTangents(c, 1, true, in, out);
  EXPECT_FLOAT_EQ(out.x, 3.0f);
}

double maxOver(const Channel& c, double a, double b) {
  double m = -1e30;
  for (int i = 0; i <= 1000; ++i) m = std::max(m, valueAt(c, a + (b - a) * i / 1000.0));
  return m;
}
double minOver(const Channel& c, double a, double b) {
  double m = 1e30;
  for (int i = 0; i <= 1000; ++i) m = std::min(m, valueAt(c, a + (b - a) * i / 1000.0));
  return m;
}

TEST(TCB, BiasShiftsOvershootToTheSideTheSeedDescribes) {
  // Seed 003: b near 1 pulls the curve toward the line from the LEFT neighbour (the motion
  // carries on past the key: overshoot); b near -1 toward the RIGHT neighbour's line.
  // Keys (0,0) (1,1) (2,1): b = +1 gives key 1 the left chord's slope 1, so the curve rises
  // above 1 after the key; b = -1 gives the right chord's slope 0: no overshoot.
  Channel c = scalarChannel({0, 1, 2}, {0, 1, 1}, Interpolation::TCB);
  c.keys[1].bias = 1.0f;
  EXPECT_NEAR(rightSlope(c, 1.0), 1.0, 2e-3);
  EXPECT_GT(maxOver(c, 1, 2), 1.05);
  c.keys[1].bias = -1.0f;
  EXPECT_NEAR(rightSlope(c, 1.0), 0.0, 2e-3);
  EXPECT_LE(maxOver(c, 1, 2), 1.0 + 1e-6);
  // Keys (0,0) (1,0) (2,1): b = -1 takes the right chord's slope into the key, so the curve
  // dips below 0 before it (anticipation); b = +1 arrives flat.
  Channel d = scalarChannel({0, 1, 2}, {0, 0, 1}, Interpolation::TCB);
  d.keys[1].bias = -1.0f;
  EXPECT_LT(minOver(d, 0, 1), -0.05);
  d.keys[1].bias = 1.0f;
  EXPECT_GE(minOver(d, 0, 1), -1e-6);
}

TEST(ScalarModes, EveryScalarModePassesThroughItsKeys) {
  const std::vector<float> times = {0, 0.25f, 1, 1.6f, 3};
  const std::vector<float> values = {0.5f, -1, 2, 2, -0.75f};
  for (Interpolation mode : {Interpolation::Step, Interpolation::Linear, Interpolation::Hermite,
                             Interpolation::CatmullRom, Interpolation::TCB, Interpolation::Bezier,
                             Interpolation::Ease}) {
    Channel c = scalarChannel(times, values, mode);
    for (size_t k = 0; k < c.keys.size(); ++k) {
      c.keys[k].tension = 0.3f;
      c.keys[k].continuity = -0.4f;
      c.keys[k].bias = 0.2f;
      c.keys[k].outTangent.x = 1.5f;
      c.keys[k].inTangent.x = -0.5f;
      c.keys[k].easing = EasingFunction::Elastic;
    }
    for (size_t k = 0; k < times.size(); ++k) {
      EXPECT_EQ(valueAt(c, times[k]), values[k]) << toString(mode) << " key " << k;
      // Continuous into the key from the left (except step, which jumps there by definition).
      if (k > 0 && mode != Interpolation::Step) {
        EXPECT_NEAR(valueAt(c, times[k] - 1e-5), values[k], 2e-3) << toString(mode) << " key " << k;
      }
    }
  }
}

}  // namespace
}  // namespace kinema
