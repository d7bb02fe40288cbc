#include "test_support.h"

#include <cmath>
#include <cstring>
#include <limits>
#include <string>
#include <vector>

#include "anim/clip.h"

namespace kinema {
namespace KINEMA_UNITY_ID {

constexpr double kPi = 3.14159265358979323846;

// Three joints: root -> a -> b, with a distinctive base pose.
Skeleton threeJoints() {
  Skeleton s;
  s.addJoint("root", -1, Transform::fromTranslation({0, 1, 0}));
  s.addJoint("a", 0, Transform::fromTranslation({0, 0.5f, 0}));
  s.addJoint("b", 1, Transform::fromTranslation({0.25f, 0, 0}));
  return s;
}

Channel channel(int joint, ChannelTarget target, std::vector<float> times,
                std::vector<glm::vec4> values, Interpolation interp = Interpolation::Linear) {
  Channel c;
  c.joint = joint;
  c.target = target;
  c.interpolation = interp;
  c.times = std::move(times);
  c.values = std::move(values);
  return c;
}

// A rotation about a unit axis, written out: (x, y, z, w) = (sin(a/2) axis, cos(a/2)).
glm::vec4 rotKey(const glm::vec3& axis, double angle) {
  const float s = static_cast<float>(std::sin(angle / 2)), c = static_cast<float>(std::cos(angle / 2));
  return {s * axis.x, s * axis.y, s * axis.z, c};
}
glm::quat rotQuat(const glm::vec3& axis, double angle) {
  const glm::vec4 k = rotKey(axis, angle);
  return glm::quat(k.w, k.x, k.y, k.z);
}

double rotationDistance(const glm::quat& a, const glm::quat& b) {
  const glm::dquat da(a.w, a.x, a.y, a.z), db(b.w, b.x, b.y, b.z);
  return std::min(glm::length(da - db), glm::length(da + db));
}

Pose sampled(const Clip& clip, float t, const Skeleton& s) {
  Pose p = Pose::rest(s);
  sampleClip(clip, t, p);
  return p;
}

// ---------------------------------------------------------------------------------------
// Sampling.

TEST(SampleClip, ClampsBeforeTheFirstAndAfterTheLastKey) {
  const Skeleton s = threeJoints();
  Clip clip;
  clip.channels.push_back(channel(1, ChannelTarget::Translation, {1.0f, 2.0f},
                                  {{1, 2, 3, 0}, {3, 6, 9, 0}}));
  for (float t : {-10.0f, 0.0f, 0.5f, 0.999f})
    EXPECT_EQ(sampled(clip, t, s).local[1].translation, glm::vec3(1, 2, 3)) << t;
  for (float t : {2.0f, 2.001f, 3.0f, 1e6f})
    EXPECT_EQ(sampled(clip, t, s).local[1].translation, glm::vec3(3, 6, 9)) << t;
  // Infinite times clamp too.
  EXPECT_EQ(sampled(clip, -std::numeric_limits<float>::infinity(), s).local[1].translation,
            glm::vec3(1, 2, 3));
  EXPECT_EQ(sampled(clip, std::numeric_limits<float>::infinity(), s).local[1].translation,
            glm::vec3(3, 6, 9));
}

TEST(SampleClip, ExactKeyTimesReturnTheKeyExactly) {
  const Skeleton s = threeJoints();
  Clip clip;
  const std::vector<float> times = {0.1f, 0.3f, 0.7f, 1.3f};
  const std::vector<glm::vec4> values = {{0.1f, 0.2f, 0.3f, 0}, {-1.7f, 2.9f, 0.33f, 0},
                                         {5.5f, -0.01f, 7.25f, 0}, {0, 0, 1e-3f, 0}};
  clip.channels.push_back(channel(2, ChannelTarget::Translation, times, values));
  clip.channels.push_back(channel(2, ChannelTarget::Scale, times, values, Interpolation::Step));
  const std::vector<glm::vec4> rots = {rotKey({0, 0, 1}, 0.3), rotKey({0, 1, 0}, 1.1),
                                       rotKey({1, 0, 0}, -2.0), rotKey({0.6f, 0.8f, 0}, 3.0)};
  clip.channels.push_back(channel(1, ChannelTarget::Rotation, times, rots));
  for (size_t k = 0; k < times.size(); ++k) {
    const Pose p = sampled(clip, times[k], s);
    EXPECT_EQ(p.local[2].translation, glm::vec3(values[k])) << k;
    EXPECT_EQ(p.local[2].scale, glm::vec3(values[k])) << k;
    // Rotation keys are unit already; the sample is that key (normalisation may move the
    // last bit).
    const glm::quat q(rots[k].w, rots[k].x, rots[k].y, rots[k].z);
    EXPECT_NEAR(p.local[1].rotation.w, q.w, 2e-7f) << k;
    EXPECT_NEAR(p.local[1].rotation.x, q.x, 2e-7f) << k;
    EXPECT_NEAR(p.local[1].rotation.y, q.y, 2e-7f) << k;
    EXPECT_NEAR(p.local[1].rotation.z, q.z, 2e-7f) << k;
  }
}

TEST(SampleClip, LinearTranslationMidpointAndFractions) {
  const Skeleton s = threeJoints();
  Clip clip;
  clip.channels.push_back(channel(0, ChannelTarget::Translation, {1.0f, 2.0f, 4.0f},
                                  {{0, 0, 0, 0}, {2, 4, -6, 0}, {2, 0, 0, 0}}));
  EXPECT_VEC3_NEAR(sampled(clip, 1.5f, s).local[0].translation, glm::vec3(1, 2, -3), 1e-6f);
  EXPECT_VEC3_NEAR(sampled(clip, 1.25f, s).local[0].translation, glm::vec3(0.5f, 1, -1.5f), 1e-6f);
  // Second segment (length 2): a quarter of the way from (2,4,-6) to (2,0,0).
  EXPECT_VEC3_NEAR(sampled(clip, 2.5f, s).local[0].translation, glm::vec3(2, 3, -4.5f), 1e-6f);
  // Scale interpolates the same way.
  Clip sc;
  sc.channels.push_back(channel(0, ChannelTarget::Scale, {0.0f, 1.0f}, {{1, 1, 1, 0}, {3, 2, 1, 0}}));
  EXPECT_VEC3_NEAR(sampled(sc, 0.5f, s).local[0].scale, glm::vec3(2, 1.5f, 1), 1e-6f);
}

TEST(SampleClip, StepHoldsTheEarlierKey) {
  const Skeleton s = threeJoints();
  Clip clip;
  clip.channels.push_back(channel(0, ChannelTarget::Translation, {0.0f, 1.0f, 2.0f},
                                  {{1, 0, 0, 0}, {2, 0, 0, 0}, {3, 0, 0, 0}}, Interpolation::Step));
  EXPECT_EQ(sampled(clip, 0.0f, s).local[0].translation, glm::vec3(1, 0, 0));
  EXPECT_EQ(sampled(clip, 0.5f, s).local[0].translation, glm::vec3(1, 0, 0));
  EXPECT_EQ(sampled(clip, 0.9999f, s).local[0].translation, glm::vec3(1, 0, 0));
  EXPECT_EQ(sampled(clip, 1.0f, s).local[0].translation, glm::vec3(2, 0, 0));
  EXPECT_EQ(sampled(clip, 1.999f, s).local[0].translation, glm::vec3(2, 0, 0));
  EXPECT_EQ(sampled(clip, 2.0f, s).local[0].translation, glm::vec3(3, 0, 0));
  EXPECT_EQ(sampled(clip, 9.0f, s).local[0].translation, glm::vec3(3, 0, 0));
  // Step rotations too.
  Clip rot;
  rot.channels.push_back(channel(0, ChannelTarget::Rotation, {0.0f, 1.0f},
                                 {rotKey({0, 0, 1}, 0.0), rotKey({0, 0, 1}, kPi / 2)},
                                 Interpolation::Step));
  EXPECT_LT(rotationDistance(sampled(rot, 0.9f, s).local[0].rotation, glm::quat(1, 0, 0, 0)), 1e-7);
}

TEST(SampleClip, RotationSlerpOfQuarterTurns) {
  const Skeleton s = threeJoints();
  const glm::vec3 z(0, 0, 1);
  Clip clip;
  // 0 -> 90 degrees about Z over [0, 1], then 90 -> 180 degrees over [1, 3].
  clip.channels.push_back(channel(1, ChannelTarget::Rotation, {0.0f, 1.0f, 3.0f},
                                  {rotKey(z, 0.0), rotKey(z, kPi / 2), rotKey(z, kPi)}));
  // Midpoint of the two quarter turns: 45 degrees about Z; (1,0,0) -> (cos 45, sin 45, 0).
  const glm::quat mid = sampled(clip, 0.5f, s).local[1].rotation;
  EXPECT_LT(rotationDistance(mid, rotQuat(z, kPi / 4)), 1e-6);
  const float h = static_cast<float>(std::sqrt(0.5));
  EXPECT_VEC3_NEAR(mid * glm::vec3(1, 0, 0), glm::vec3(h, h, 0), 1e-6f);
  // Slerp is constant-speed (a normalised lerp would give 21.6 degrees at t = 0.25).
  EXPECT_LT(rotationDistance(sampled(clip, 0.25f, s).local[1].rotation, rotQuat(z, kPi / 8)), 1e-6);
  // Second segment: at 2.0, half way from 90 to 180: 135 degrees.
  EXPECT_LT(rotationDistance(sampled(clip, 2.0f, s).local[1].rotation, rotQuat(z, 3 * kPi / 4)), 1e-6);
  for (float t : {0.1f, 0.5f, 1.7f, 2.9f})
    EXPECT_NEAR(glm::length(sampled(clip, t, s).local[1].rotation), 1.0f, 1e-6f) << t;
}

TEST(SampleClip, RotationTakesTheShortestArcAcrossHemispheres) {
  const Skeleton s = threeJoints();
  const glm::vec3 z(0, 0, 1);
  // Keys identity and -(90 degrees about Z): the same rotations as 0 and 90 degrees, but in
  // opposite hemispheres. Half way must be 45 degrees about +Z, not 135 about -Z.
  Clip clip;
  clip.channels.push_back(channel(0, ChannelTarget::Rotation, {0.0f, 1.0f},
                                  {rotKey(z, 0.0), -rotKey(z, kPi / 2)}));
  const glm::quat mid = sampled(clip, 0.5f, s).local[0].rotation;
  EXPECT_LT(rotationDistance(mid, rotQuat(z, kPi / 4)), 1e-6);
  // And 160 -> -160 degrees about Y goes through 180, not through 0.
  const glm::vec3 y(0, 1, 0);
  Clip wrap;
  wrap.channels.push_back(channel(0, ChannelTarget::Rotation, {0.0f, 2.0f},
                                  {rotKey(y, 160.0 * kPi / 180), rotKey(y, -160.0 * kPi / 180)}));
  EXPECT_LT(rotationDistance(sampled(wrap, 1.0f, s).local[0].rotation, rotQuat(y, kPi)), 1e-6);
  EXPECT_LT(rotationDistance(sampled(wrap, 0.5f, s).local[0].rotation,
                             rotQuat(y, 170.0 * kPi / 180)),
            1e-6);
}

TEST(SampleClip, NonUnitKeyQuaternionsAreNormalised) {
  const Skeleton s = threeJoints();
  const glm::vec3 x(1, 0, 0);
  Clip clip;
  clip.channels.push_back(channel(2, ChannelTarget::Rotation, {0.0f, 1.0f},
                                  {3.0f * rotKey(x, 0.0), 0.2f * rotKey(x, kPi / 2)}));
  for (float t : {-1.0f, 0.0f, 0.3f, 0.5f, 1.0f, 2.0f}) {
    const glm::quat q = sampled(clip, t, s).local[2].rotation;
    EXPECT_NEAR(glm::length(q), 1.0f, 1e-6f) << t;
  }
  EXPECT_LT(rotationDistance(sampled(clip, 0.0f, s).local[2].rotation, glm::quat(1, 0, 0, 0)), 1e-7);
  EXPECT_LT(rotationDistance(sampled(clip, 1.0f, s).local[2].rotation, rotQuat(x, kPi / 2)), 1e-6);
  // The weights of the keys do not skew the interpolation: still 45 degrees half way.
  EXPECT_LT(rotationDistance(sampled(clip, 0.5f, s).local[2].rotation, rotQuat(x, kPi / 4)), 1e-6);
}

TEST(SampleClip, ChannelsWithDifferentKeyTimes) {
  const Skeleton s = threeJoints();
  const glm::vec3 y(0, 1, 0);
  Clip clip;
  clip.channels.push_back(channel(1, ChannelTarget::Translation, {0.0f, 1.0f},
                                  {{0, 0, 0, 0}, {4, 0, 0, 0}}));
  clip.channels.push_back(channel(1, ChannelTarget::Rotation, {0.5f, 2.5f},
                                  {rotKey(y, 0.0), rotKey(y, kPi / 2)}));
  // t = 0.25: translation a quarter of the way; rotation holds its first key.
  Pose p = sampled(clip, 0.25f, s);
  EXPECT_VEC3_NEAR(p.local[1].translation, glm::vec3(1, 0, 0), 1e-6f);
  EXPECT_LT(rotationDistance(p.local[1].rotation, glm::quat(1, 0, 0, 0)), 1e-7);
  // t = 1.5: translation clamped at its last key; rotation half way (45 degrees).
  p = sampled(clip, 1.5f, s);
  EXPECT_EQ(p.local[1].translation, glm::vec3(4, 0, 0));
  EXPECT_LT(rotationDistance(p.local[1].rotation, rotQuat(y, kPi / 4)), 1e-6);
  EXPECT_FLOAT_EQ(clip.duration(), 2.5f);
}

TEST(SampleClip, UnanimatedJointsAndPropertiesKeepTheBasePose) {
  const Skeleton s = threeJoints();
  Pose base = Pose::rest(s);
  base.local[0].rotation = rotQuat({0, 1, 0}, 0.7);
  base.local[0].scale = glm::vec3(1.5f);
  base.local[2].rotation = rotQuat({1, 0, 0}, -0.4);
  base.local[2].scale = glm::vec3(0.5f, 2.0f, 1.0f);
  Clip clip;
  clip.channels.push_back(channel(1, ChannelTarget::Rotation, {0.0f, 1.0f},
                                  {rotKey({0, 0, 1}, 0.0), rotKey({0, 0, 1}, 1.0)}));
  clip.channels.push_back(channel(0, ChannelTarget::Translation, {0.0f, 1.0f},
                                  {{0, 0, 0, 0}, {1, 1, 1, 0}}));
  Pose p = base;
  sampleClip(clip, 0.5f, p);
  // Joint 2 is not animated: bit for bit the base.
  EXPECT_EQ(std::memcmp(&p.local[2], &base.local[2], sizeof(Transform)), 0);
  // Joint 0: translation animated; rotation and scale stay.
  EXPECT_EQ(p.local[0].rotation, base.local[0].rotation);
  EXPECT_EQ(p.local[0].scale, base.local[0].scale);
  EXPECT_NE(p.local[0].translation, base.local[0].translation);
  // Joint 1: rotation animated; translation and scale stay.
  EXPECT_EQ(p.local[1].translation, base.local[1].translation);
  EXPECT_EQ(p.local[1].scale, base.local[1].scale);
  // An empty clip changes nothing.
  Pose q = base;
  sampleClip(Clip{}, 0.3f, q);
  for (int i = 0; i < q.size(); ++i) EXPECT_EQ(q.local[i], base.local[i]);
}

// ---------------------------------------------------------------------------------------
// duration, frameToTime.

TEST(Clip, DurationIsTheLastKeyOverAllChannels) {
  Clip clip;
  EXPECT_EQ(clip.duration(), 0.0f);
  clip.channels.push_back(channel(0, ChannelTarget::Translation, {0.0f, 1.5f}, {{}, {}}));
  EXPECT_FLOAT_EQ(clip.duration(), 1.5f);
  clip.channels.push_back(channel(1, ChannelTarget::Rotation, {0.2f, 0.4f, 3.25f}, {{}, {}, {}}));
  clip.channels.push_back(channel(2, ChannelTarget::Scale, {1.0f, 2.0f}, {{}, {}}));
  EXPECT_FLOAT_EQ(clip.duration(), 3.25f);  // not the last channel's end, the latest
}

TEST(Clip, FrameToTimeIsFrameTimesFrameTimeInDouble) {
  Clip clip;
  clip.frameTime = 1.0 / 30.0;
  EXPECT_EQ(ownFrameGrid(clip).frameToTime(0), 0.0f);
  EXPECT_EQ(ownFrameGrid(clip).frameToTime(30), 1.0f);
  EXPECT_EQ(ownFrameGrid(clip).frameToTime(90), 3.0f);
  // Frame N at N x Frame Time, multiplied in double (Frame Time is a double read from the
  // file) and rounded once to float. A float product float(N) * float(frameTime) differs
  // for some N; make sure such N exist in the range checked, so the check can fail.
  int floatProductDiffers = 0;
  for (const double ft : {1.0 / 30.0, 0.008333, 1.0 / 24.0}) {
    clip.frameTime = ft;
    for (long long n = 0; n < 20000; ++n) {
      const float want = static_cast<float>(static_cast<double>(n) * ft);
      ASSERT_EQ(ownFrameGrid(clip).frameToTime(n), want) << "frame " << n << " frame time " << ft;
      if (static_cast<float>(n) * static_cast<float>(ft) != want) ++floatProductDiffers;
    }
  }
  EXPECT_GT(floatProductDiffers, 0);
}

TEST(Clip, SamplingAtFrameToTimeReturnsThatFramesKey) {
  // A frame-based clip whose keys were placed at frameToTime(f) (as the BVH reader does):
  // sampling at frameToTime(N) gives frame N's values exactly, for every frame.
  const Skeleton s = threeJoints();
  Clip clip;
  clip.frameTime = 0.0083333;
  const int frames = 2000;
  Channel c = channel(0, ChannelTarget::Translation, {}, {});
  for (int f = 0; f < frames; ++f) {
    c.times.push_back(ownFrameGrid(clip).frameToTime(f));
    c.values.push_back({static_cast<float>(f), static_cast<float>(f % 7), -0.5f * f, 0});
  }
  clip.channels.push_back(c);
  ASSERT_EQ(clip.validate(s), "");
  Pose p = Pose::rest(s);
  for (int f = 0; f < frames; ++f) {
    sampleClip(clip, ownFrameGrid(clip).frameToTime(f), p);
    ASSERT_EQ(p.local[0].translation, glm::vec3(c.values[f])) << "frame " << f;
  }
  EXPECT_EQ(clip.duration(), ownFrameGrid(clip).frameToTime(frames - 1));
}

// ---------------------------------------------------------------------------------------
// validate.

Clip goodClip() {
  Clip clip;
  clip.channels.push_back(channel(0, ChannelTarget::Translation, {0.0f, 1.0f},
                                  {{0, 0, 0, 0}, {1, 0, 0, 0}}));
  clip.channels.push_back(channel(2, ChannelTarget::Rotation, {0.0f, 0.5f, 2.0f},
                                  {{0, 0, 0, 1}, {0, 1, 0, 1}, {0, 0, 1, 0}}));
  return clip;
}

bool contains(const std::string& haystack, const std::string& needle) {
  return haystack.find(needle) != std::string::npos;
}

TEST(ClipValidate, AcceptsAGoodClip) {
  EXPECT_EQ(goodClip().validate(threeJoints()), "");
  EXPECT_EQ(Clip{}.validate(threeJoints()), "");
  // A single key is fine.
  Clip one;
  one.channels.push_back(channel(1, ChannelTarget::Scale, {0.0f}, {{1, 1, 1, 0}}));
  EXPECT_EQ(one.validate(threeJoints()), "");
}

TEST(ClipValidate, RejectsBadJointIndex) {
  const Skeleton s = threeJoints();
  for (int bad : {-1, 3, 99}) {
    Clip clip = goodClip();
    clip.channels[1].joint = bad;
    const std::string msg = clip.validate(s);
    EXPECT_TRUE(contains(msg, "joint")) << bad << ": " << msg;
    EXPECT_TRUE(contains(msg, std::to_string(bad))) << msg;
  }
}

TEST(ClipValidate, RejectsNonIncreasingTimes) {
  const Skeleton s = threeJoints();
  Clip clip = goodClip();
  clip.channels[1].times = {0.0f, 0.5f, 0.5f};  // equal
  EXPECT_TRUE(contains(clip.validate(s), "key 2")) << clip.validate(s);
  clip.channels[1].times = {0.0f, 0.5f, 0.25f};  // decreasing
  EXPECT_NE(clip.validate(s), "");
  clip.channels[1].times = {1.0f, 0.5f, 2.0f};
  EXPECT_TRUE(contains(clip.validate(s), "key 1")) << clip.validate(s);
}

TEST(ClipValidate, RejectsSizeMismatchAndEmptyChannels) {
  const Skeleton s = threeJoints();
  Clip clip = goodClip();
  clip.channels[0].values.push_back({2, 0, 0, 0});
  EXPECT_TRUE(contains(clip.validate(s), "channel 0")) << clip.validate(s);
  clip = goodClip();
  clip.channels[1].times.pop_back();
  EXPECT_TRUE(contains(clip.validate(s), "channel 1")) << clip.validate(s);
  clip = goodClip();
  clip.channels[1].times.clear();
  clip.channels[1].values.clear();
  EXPECT_TRUE(contains(clip.validate(s), "no keys")) << clip.validate(s);
}

TEST(ClipValidate, RejectsNaNAndInfinity) {
  const Skeleton s = threeJoints();
  const float nan = std::numeric_limits<float>::quiet_NaN();
  const float inf = std::numeric_limits<float>::infinity();
  for (int comp = 0; comp < 4; ++comp) {
    for (float bad : {nan, inf}) {
      Clip clip = goodClip();
      clip.channels[1].values[1][comp] = bad;
      const std::string msg = clip.validate(s);
      EXPECT_TRUE(contains(msg, "non-finite value")) << comp << ": " << msg;
    }
  }
  for (float bad : {nan, inf, -inf}) {
    Clip clip = goodClip();
    clip.channels[0].times[0] = bad;
    EXPECT_NE(clip.validate(s), "") << bad;
    clip = goodClip();
    clip.channels[0].times[1] = bad;
    EXPECT_NE(clip.validate(s), "") << bad;
  }
}

}  // namespace
}  // namespace kinema
