// Channel -> glTF sampler conversion: which curves are exact, what is resampled, and the
// glTF cubic spline evaluated on hand-computed values.
#include <gtest/gtest.h>

#include "anim/sampling.h"
#include "io/gltf_curves.h"

namespace kinema {
namespace KINEMA_UNITY_ID {

Channel line(std::vector<float> times, std::vector<float> xs, Interpolation mode) {
  std::vector<glm::vec4> values;
  for (float x : xs) values.push_back({x, 0, 0, 0});
  return Channel(0, ChannelTarget::Translation, mode, std::move(times), std::move(values));
}

// Two keys 2 s apart, v0 = 0, v1 = 1, out-tangent of key 0 = 1 per second, in-tangent of
// key 1 = 0. At u = 1/2: h10 = 1/8, h01 = 1/2, so p = 2 * 1/8 * 1 + 1/2 = 0.75.
TEST(GltfCurves, CubicSplineByHand) {
  GltfSampler s;
  s.interpolation = GltfInterpolation::CubicSpline;
  s.components = 1;
  s.times = {0.0f, 2.0f};
  s.values = {0.0f, 0.0f, 1.0f, 0.0f, 1.0f, 0.0f};  // (in, value, out) per key
  EXPECT_NEAR(evaluateGltfSampler(s, false, 1.0f)[0], 0.75f, 1e-7);
  EXPECT_EQ(evaluateGltfSampler(s, false, -1.0f)[0], 0.0f);  // clamped before the first key
  EXPECT_EQ(evaluateGltfSampler(s, false, 5.0f)[0], 1.0f);
}

TEST(GltfCurves, HermiteTangentsAreCopiedPerSegment) {
  Channel ch = line({0.0f, 1.0f, 3.0f}, {0.0f, 2.0f, 1.0f}, Interpolation::Hermite);
  ch.target = ChannelTarget::Scale;
  ch.keys.resize(3);
  for (KeySettings& k : ch.keys) k.interpolation = Interpolation::Hermite;
  ch.keys[0].outTangent = {4, 0, 0, 0};
  ch.keys[1].inTangent = {-1, 0, 0, 0};
  ch.keys[1].outTangent = {3, 0, 0, 0};
  ch.keys[2].inTangent = {0.5f, 0, 0, 0};
  const GltfSampler s = toGltfSampler(ch, 30.0);
  ASSERT_FALSE(s.resampled) << s.reason;
  ASSERT_EQ(s.interpolation, GltfInterpolation::CubicSpline);
  // x of (in, value, out) for each key.
  EXPECT_EQ(s.values[0 * 9 + 6], 4.0f);
  EXPECT_EQ(s.values[1 * 9 + 0], -1.0f);
  EXPECT_EQ(s.values[1 * 9 + 3], 2.0f);
  EXPECT_EQ(s.values[1 * 9 + 6], 3.0f);
  EXPECT_EQ(s.values[2 * 9 + 0], 0.5f);
}

// The editor's default rotation keys (Bezier, auto-clamped: handles a third of each
// interval) are a cubic in time per quaternion component, then normalised: exactly glTF's
// CUBICSPLINE rotation, so they export without resampling. Checked against sampleChannel.
TEST(GltfCurves, DefaultBezierRotationKeysAreAnExactCubicSpline) {
  const glm::quat a = glm::angleAxis(0.2f, glm::vec3(0, 0, 1)), b = glm::angleAxis(1.4f, glm::vec3(1, 0, 0)),
                  c = glm::angleAxis(0.7f, glm::normalize(glm::vec3(1, 1, 0)));
  Channel ch(0, ChannelTarget::Rotation, Interpolation::Bezier, {0.0f, 0.5f, 1.5f},
             {{a.x, a.y, a.z, a.w}, {b.x, b.y, b.z, b.w}, {c.x, c.y, c.z, c.w}});
  const GltfSampler s = toGltfSampler(ch, 30.0);
  ASSERT_FALSE(s.resampled) << s.reason;
  ASSERT_EQ(s.interpolation, GltfInterpolation::CubicSpline);
  for (float t : {0.1f, 0.25f, 0.4f, 0.7f, 1.0f, 1.3f}) {
    const std::vector<float> got = evaluateGltfSampler(s, true, t);
    const glm::vec4 want = sampleChannel(ch, t);
    const float dot = got[0] * want.x + got[1] * want.y + got[2] * want.z + got[3] * want.w;
    EXPECT_NEAR(std::abs(dot), 1.0f, 1e-6f) << t;
  }
  // Free handles of other lengths are no cubic in time: resampled.
  ch.keys.resize(3);
  ch.keys[1].interpolation = ch.keys[0].interpolation = Interpolation::Bezier;
  ch.keys[1].rightHandleType = HandleType::Free;
  ch.keys[1].rightHandleTime = 0.1f;
  ch.keys[1].rightHandleValue = {0.05f, 0, 0, 0};
  EXPECT_TRUE(toGltfSampler(ch, 30.0).resampled);
}

TEST(GltfCurves, StepThenLinearIsResampledAndTheJumpShowsInTheError) {
  Channel ch = line({0.0f, 1.0f, 2.0f}, {0.0f, 1.0f, 0.0f}, Interpolation::Linear);
  ch.keys.resize(3);
  ch.keys[0].interpolation = Interpolation::Step;
  const GltfSampler s = toGltfSampler(ch, 10.0);
  EXPECT_TRUE(s.resampled);
  EXPECT_EQ(s.interpolation, GltfInterpolation::Linear);
  EXPECT_EQ(s.times.size(), 21u);  // 10 per second over 2 s, keys included
  // The step from 0 to 1 at t = 1 becomes a ramp over the 0.1 s before it: most of the
  // jump is missed just before the key.
  EXPECT_GT(s.maxError, 0.5);
  EXPECT_LE(s.maxError, 1.0);
}

TEST(GltfCurves, EaseIsResampledLinearAndLinearIsNot) {
  const GltfSampler eased = toGltfSampler(line({0.0f, 1.0f}, {0.0f, 1.0f}, Interpolation::Ease), 30.0);
  EXPECT_TRUE(eased.resampled);
  EXPECT_GT(eased.maxError, 1e-4);
  const GltfSampler linear = toGltfSampler(line({0.0f, 1.0f}, {0.0f, 1.0f}, Interpolation::Linear), 30.0);
  EXPECT_FALSE(linear.resampled);
  EXPECT_EQ(linear.times.size(), 2u);
}

// Morph weights on different key times: one grid (the union of the keys, filled to the
// rate), each target's values side by side.
TEST(GltfCurves, WeightsOnDifferentKeysShareOneGrid) {
  Channel a(0, ChannelTarget::Scalar, Interpolation::Linear, {0.0f, 1.0f}, {{0, 0, 0, 0}, {1, 0, 0, 0}});
  Channel b(0, ChannelTarget::Scalar, Interpolation::Linear, {0.0f, 0.5f, 1.0f}, {{1, 0, 0, 0}, {0, 0, 0, 0}, {1, 0, 0, 0}});
  a.property = "weights/0";
  b.property = "weights/2";
  const GltfSampler s = toGltfWeightsSampler({&a, nullptr, &b}, {0.0f, 0.3f, 0.0f}, 4.0);
  EXPECT_TRUE(s.resampled);
  EXPECT_EQ(s.components, 3);
  EXPECT_EQ(s.times, (std::vector<float>{0.0f, 0.25f, 0.5f, 0.75f, 1.0f}));
  ASSERT_EQ(s.values.size(), 15u);
  // t = 0.25: a = 0.25, the missing target keeps its default 0.3, b = 0.5.
  EXPECT_NEAR(s.values[3], 0.25f, 1e-7);
  EXPECT_EQ(s.values[4], 0.3f);
  EXPECT_NEAR(s.values[5], 0.5f, 1e-7);
  EXPECT_LT(s.maxError, 1e-6);  // both are straight lines between grid points
  // Shared key times and one interpolation: exact, no resampling.
  const GltfSampler same = toGltfWeightsSampler({&a, &a}, {0.0f, 0.0f}, 4.0);
  EXPECT_FALSE(same.resampled);
  EXPECT_EQ(same.times.size(), 2u);
}

}  // namespace
}  // namespace kinema
