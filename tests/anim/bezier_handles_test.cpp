// Bezier keys with Blender's handle types. Expected handles are computed by hand from the
// keys in each test's comment.
#include <gtest/gtest.h>

#include "anim/bezier_handles.h"
#include "anim_test_support.h"

namespace kinema {
namespace KINEMA_UNITY_ID {

using test::scalarChannel;
using test::valueAt;

Channel bezier(const std::vector<float>& t, const std::vector<float>& v, HandleType type) {
  Channel c = scalarChannel(t, v, Interpolation::Bezier);
  for (KeySettings& k : c.keys) k.leftHandleType = k.rightHandleType = type;
  return c;
}

TEST(BezierHandles, VectorPointsAThirdOfTheWayToTheNeighbour) {
  // Keys (0,0) (3,3) (6,0): key 1's left handle (-1, -1), right handle (1, -1).
  const Channel c = bezier({0, 3, 6}, {0, 3, 0}, HandleType::Vector);
  const BezierHandles h = effectiveHandles(c, 1);
  EXPECT_FLOAT_EQ(h.leftTime, -1.0f);
  EXPECT_FLOAT_EQ(h.leftValue.x, -1.0f);
  EXPECT_FLOAT_EQ(h.rightTime, 1.0f);
  EXPECT_FLOAT_EQ(h.rightValue.x, -1.0f);
  // Vector handles on both ends of a segment make it the straight line between the keys.
  for (double t : {0.5, 1.0, 2.2}) EXPECT_NEAR(valueAt(c, t), t, 1e-5) << t;
}

TEST(BezierHandles, AutoLiesAlongTheNeighboursChord) {
  // Keys (0,0) (1,2) (3,4): chord slope (4-0)/(3-0) = 4/3. Left handle (-1/3, -4/9),
  // right handle (2/3, 8/9). End keys are flat.
  const Channel c = bezier({0, 1, 3}, {0, 2, 4}, HandleType::Auto);
  const BezierHandles h = effectiveHandles(c, 1);
  EXPECT_FLOAT_EQ(h.leftTime, -1.0f / 3.0f);
  EXPECT_FLOAT_EQ(h.leftValue.x, -4.0f / 9.0f);
  EXPECT_FLOAT_EQ(h.rightTime, 2.0f / 3.0f);
  EXPECT_FLOAT_EQ(h.rightValue.x, 8.0f / 9.0f);
  const BezierHandles e = effectiveHandles(c, 0);
  EXPECT_FLOAT_EQ(e.rightTime, 1.0f / 3.0f);
  EXPECT_EQ(e.rightValue.x, 0.0f);
  // Smooth: the slope through key 1 is the chord's from both sides.
  EXPECT_NEAR(test::leftSlope(c, 1.0), 4.0 / 3.0, 2e-3);
  EXPECT_NEAR(test::rightSlope(c, 1.0), 4.0 / 3.0, 2e-3);
}

TEST(BezierHandles, AutoClampedIsFlatAtExtremaAndNeverOvershoots) {
  // A peak: flat handles at key 1.
  const Channel peak = bezier({0, 1, 2}, {0, 2, 0}, HandleType::AutoClamped);
  EXPECT_EQ(effectiveHandles(peak, 1).rightValue.x, 0.0f);
  EXPECT_EQ(effectiveHandles(peak, 1).leftValue.x, 0.0f);
  for (int i = 0; i <= 200; ++i) EXPECT_LE(valueAt(peak, i * 0.01), 2.0) << i;
  // Two equal keys: a flat segment.
  const Channel flat = bezier({0, 1, 2, 3}, {0, 1, 1, 0}, HandleType::AutoClamped);
  for (int i = 0; i <= 100; ++i) EXPECT_FLOAT_EQ(static_cast<float>(valueAt(flat, 1 + i * 0.01)), 1.0f) << i;
  // Monotonic keys with a small step: (0,0) (1,1) (2,1.1) (3,3). Auto's handles (slopes 0.55
  // and 1) push the middle segment outside [1, 1.1]; auto-clamped keeps it inside.
  const Channel autoC = bezier({0, 1, 2, 3}, {0, 1, 1.1f, 3}, HandleType::Auto);
  const Channel clamped = bezier({0, 1, 2, 3}, {0, 1, 1.1f, 3}, HandleType::AutoClamped);
  double autoMax = 0, autoMin = 10;
  for (int i = 0; i <= 200; ++i) {
    const double t = 1 + i * 0.005;
    autoMax = std::max(autoMax, valueAt(autoC, t));
    autoMin = std::min(autoMin, valueAt(autoC, t));
    EXPECT_GE(valueAt(clamped, t), 1.0 - 1e-6) << t;
    EXPECT_LE(valueAt(clamped, t), 1.1 + 1e-6) << t;
  }
  EXPECT_TRUE(autoMax > 1.1 + 1e-3 || autoMin < 1.0 - 1e-3) << autoMin << " " << autoMax;
}

TEST(BezierHandles, AlignedStaysCollinearFreeDoesNot) {
  Channel c = bezier({0, 1, 2}, {0, 1, 0}, HandleType::Aligned);
  c.keys[1].leftHandleTime = -0.3f;
  c.keys[1].leftHandleValue.x = 0.0f;
  setBezierHandle(c, 1, true, 0.5f, glm::vec4(1.0f, 0, 0, 0));
  // The left handle turns to (-0.3, -0.6): opposite direction, same slope 2.
  EXPECT_FLOAT_EQ(c.keys[1].leftHandleTime, -0.3f);
  EXPECT_FLOAT_EQ(c.keys[1].leftHandleValue.x, -0.6f);
  EXPECT_NEAR(test::leftSlope(c, 1.0), test::rightSlope(c, 1.0), 5e-3);

  Channel f = bezier({0, 1, 2}, {0, 1, 0}, HandleType::Free);
  f.keys[1].leftHandleTime = -0.3f;
  f.keys[1].leftHandleValue.x = 0.0f;
  setBezierHandle(f, 1, true, 0.5f, glm::vec4(1.0f, 0, 0, 0));
  EXPECT_FLOAT_EQ(f.keys[1].leftHandleTime, -0.3f);
  EXPECT_FLOAT_EQ(f.keys[1].leftHandleValue.x, 0.0f);
  EXPECT_NEAR(test::leftSlope(f, 1.0), 0.0, 5e-3);
  EXPECT_NEAR(test::rightSlope(f, 1.0), 2.0, 5e-3);

  // Blender: editing an auto handle turns the pair aligned.
  Channel a = bezier({0, 1, 2}, {0, 1, 0}, HandleType::Auto);
  setBezierHandle(a, 1, false, -0.25f, glm::vec4(-0.25f, 0, 0, 0));
  EXPECT_EQ(a.keys[1].leftHandleType, HandleType::Aligned);
  EXPECT_EQ(a.keys[1].rightHandleType, HandleType::Aligned);
  EXPECT_FLOAT_EQ(a.keys[1].rightHandleValue.x / a.keys[1].rightHandleTime, 1.0f);
}

TEST(BezierHandles, TimeAxisIsSolvedSoTheCurveIsAFunctionOfTime) {
  // Free handles; the expected value at x(s) is the Bezier polynomial evaluated directly.
  Channel c = bezier({0, 2}, {0, 1}, HandleType::Free);
  c.keys[0].rightHandleTime = 1.5f;
  c.keys[0].rightHandleValue.x = 2.0f;
  c.keys[1].leftHandleTime = -0.2f;
  c.keys[1].leftHandleValue.x = -1.5f;
  const double x[4] = {0, 1.5, 1.8, 2}, y[4] = {0, 2, -0.5, 1};
  for (double s : {0.1, 0.3, 0.5, 0.77, 0.95}) {
    const double r = 1 - s;
    const double xs = r * r * r * x[0] + 3 * r * r * s * x[1] + 3 * r * s * s * x[2] + s * s * s * x[3];
    const double ys = r * r * r * y[0] + 3 * r * r * s * y[1] + 3 * r * s * s * y[2] + s * s * s * y[3];
    EXPECT_NEAR(valueAt(c, xs), ys, 1e-4) << s;
  }
  // Handles reaching past the other key are shortened: still one value per time, and the
  // keys are still hit.
  c.keys[0].rightHandleTime = 5.0f;
  c.keys[1].leftHandleTime = -4.0f;
  for (int i = 0; i <= 100; ++i) EXPECT_TRUE(std::isfinite(valueAt(c, i * 0.02))) << i;
  EXPECT_EQ(valueAt(c, 2.0), 1.0);
}

}  // namespace
}  // namespace kinema
