// The fast sampling paths (cursors, the neighbouring channel's key as a guess, the series
// slerp, straight-to-pose Linear segments) against sampleChannelReference, the plain
// evaluation: equal to 1e-6 on random clips of every target and interpolation, sampled in
// playback order, at random times, at key times and outside the keys.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "anim/reference_pose.h"
#include "anim/sampling.h"

namespace kinema {
namespace KINEMA_UNITY_ID {

constexpr float kTolerance = 1e-6f;

// A unit quaternion near `q`, turned by up to `step` radians about a random axis.
glm::quat wander(const glm::quat& q, float step, std::mt19937& rng) {
  std::normal_distribution<float> g(0.0f, 1.0f);
  std::uniform_real_distribution<float> a(0.0f, step);
  return glm::normalize(q * glm::angleAxis(a(rng), glm::normalize(glm::vec3(g(rng), g(rng), g(rng)) + 1e-3f)));
}

// `joints` joints, each with a translation, a rotation (or Euler) and a scale channel. Half
// the joints share one key grid (as imported motion does), the others have their own times.
// Rotation keys wander by a random amount per channel, from fractions of a degree (where
// slerp blends linearly) to keys far apart (the exact sines); some channels store them
// scaled off unit length. Each channel is either imported (one interpolation for every key)
// or carries per-key settings of mixed interpolations.
Clip randomClip(int joints, int keys, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<float> val(-2.0f, 2.0f), gap(0.01f, 0.2f), unit(0.0f, 1.0f);
  const Interpolation vecModes[] = {Interpolation::Step,       Interpolation::Linear, Interpolation::Hermite,
                                    Interpolation::CatmullRom, Interpolation::TCB,    Interpolation::Bezier,
                                    Interpolation::Ease};
  const Interpolation rotModes[] = {Interpolation::Step,   Interpolation::Linear, Interpolation::Hermite,
                                    Interpolation::Bezier, Interpolation::Ease,   Interpolation::Nlerp,
                                    Interpolation::Squad};
  const float steps[] = {0.01f, 0.05f, 0.3f, 1.0f, 3.0f};
  std::vector<float> grid;
  for (int k = 0; k < keys; ++k) grid.push_back(k / 30.0f);
  Clip clip;
  for (int j = 0; j < joints; ++j) {
    const bool shared = j % 2 == 0;
    for (ChannelTarget target : {ChannelTarget::Translation, ChannelTarget::Rotation, ChannelTarget::Scale}) {
      if (target == ChannelTarget::Rotation && j % 5 == 4) target = ChannelTarget::Euler;
      Channel c;
      c.joint = j;
      c.target = target;
      const bool rotation = target == ChannelTarget::Rotation;
      const bool perKey = rng() % 2 == 0;
      c.interpolation = perKey ? Interpolation::Linear : (rotation ? rotModes : vecModes)[rng() % 7];
      if (rng() % 3 == 0) c.interpolation = Interpolation::Linear;  // the most common case, more often
      const float step = steps[rng() % 5];
      const float scale = rng() % 4 == 0 ? 1.5f : 1.0f;
      glm::quat q = glm::normalize(glm::quat(val(rng), val(rng), val(rng), val(rng)));
      float t = gap(rng) - 0.1f;
      for (int k = 0; k < keys; ++k) {
        c.times.push_back(shared ? grid[k] : t);
        t += gap(rng);
        if (rotation) {
          q = wander(q, step, rng);
          c.values.emplace_back(scale * q.x, scale * q.y, scale * q.z, scale * q.w);
        } else {
          c.values.emplace_back(val(rng), val(rng), val(rng), 0.0f);
        }
        if (perKey) {
          KeySettings s;
          s.interpolation = (rotation ? rotModes : vecModes)[rng() % 7];
          if (rng() % 2 == 0) s.interpolation = Interpolation::Linear;
          s.outTangent = glm::vec4(val(rng));
          s.inTangent = glm::vec4(val(rng));
          s.tension = val(rng) / 4;
          c.keys.push_back(s);
        }
      }
      clip.channels.push_back(std::move(c));
    }
  }
  return clip;
}

Skeleton skeletonOf(int joints) {
  Skeleton s;
  for (int j = 0; j < joints; ++j) s.addJoint("j" + std::to_string(j), j - 1, Transform());
  return s;
}

TEST(SamplingFastPath, EqualsReferenceOnRandomClipsOfEveryInterpolation) {
  constexpr int kJoints = 20, kKeys = 40;
  for (unsigned seed = 1; seed <= 6; ++seed) {
    const Clip clip = randomClip(kJoints, kKeys, seed);
    const Skeleton skeleton = skeletonOf(kJoints);
    const float end = clip.duration();
    std::vector<float> times;
    for (float t = -0.1f; t <= end + 0.1f; t += 1.0f / 60.0f) times.push_back(t);  // playback, past both ends
    for (const Channel& ch : clip.channels) times.push_back(ch.times[ch.keyCount() / 2]);  // on keys
    std::mt19937 rng(seed);
    std::uniform_real_distribution<float> any(-0.2f, end + 0.2f);
    for (int i = 0; i < 200; ++i) times.push_back(any(rng));  // jumps
    SamplingCache cache;
    Pose cached = Pose::rest(skeleton), plain = Pose::rest(skeleton);
    float worstCached = 0.0f, worstPlain = 0.0f, worstChannel = 0.0f;
    for (float t : times) {
      const Pose reference = test::referencePose(clip, Pose::rest(skeleton), t);
      sampleClip(clip, t, cached, cache);
      sampleClip(clip, t, plain);
      worstCached = std::max(worstCached, test::maxPoseDifference(cached, reference));
      worstPlain = std::max(worstPlain, test::maxPoseDifference(plain, reference));
      for (const Channel& ch : clip.channels) {
        const glm::vec4 d = glm::abs(sampleChannel(ch, t) - sampleChannelReference(ch, t));
        worstChannel = std::max({worstChannel, d.x, d.y, d.z, d.w});
      }
    }
    EXPECT_LE(worstCached, kTolerance) << "seed " << seed;
    EXPECT_LE(worstPlain, kTolerance) << "seed " << seed;
    EXPECT_LE(worstChannel, kTolerance) << "seed " << seed;
  }
}

// The slerp of the fast path against the closed form in double precision, over every angle
// between keys from 0 to 179 degrees: it stays a slerp (constant angular speed), not nlerp.
TEST(SamplingFastPath, LinearRotationIsSlerpToFloatPrecision) {
  for (int a = 0; a <= 179; ++a) {
    const double angle = a * 3.14159265358979323846 / 180.0;  // between the two rotations
    const glm::dvec3 axis = glm::normalize(glm::dvec3(0.3, -0.5, 0.8));
    const glm::dquat q0 = glm::angleAxis(0.4, glm::normalize(glm::dvec3(1.0, 2.0, -1.0)));
    const glm::dquat q1 = q0 * glm::angleAxis(angle, axis);
    Channel ch(0, ChannelTarget::Rotation, Interpolation::Linear, {0.0f, 1.0f},
               {glm::vec4(q0.x, q0.y, q0.z, q0.w), glm::vec4(q1.x, q1.y, q1.z, q1.w)});
    for (int i = 1; i < 20; ++i) {
      const double u = i / 20.0;
      const glm::dquat exact = q0 * glm::angleAxis(u * angle, axis);  // slerp: the angle grows linearly in u
      const glm::vec4 v = sampleChannel(ch, static_cast<float>(u));
      for (int c = 0; c < 4; ++c) EXPECT_NEAR(v[c], exact[c], 1e-6) << a << " degrees at u " << u << ", component " << c;
    }
  }
}

// The guess taken from the previous channel is only a guess: channels whose keys lie
// elsewhere still sample their own segment (their values would differ otherwise).
TEST(SamplingFastPath, ChannelsWithTheirOwnKeyTimesIgnoreTheNeighboursGuess) {
  Clip clip;
  clip.channels.push_back(Channel(0, ChannelTarget::Translation, Interpolation::Linear, {0.0f, 1.0f, 2.0f},
                                  {glm::vec4(0.0f), glm::vec4(1.0f), glm::vec4(2.0f)}));
  clip.channels.push_back(Channel(1, ChannelTarget::Translation, Interpolation::Linear, {0.0f, 0.25f, 0.5f, 2.0f},
                                  {glm::vec4(0.0f), glm::vec4(10.0f), glm::vec4(20.0f), glm::vec4(80.0f)}));
  const Skeleton skeleton = skeletonOf(2);
  Pose pose = Pose::rest(skeleton);
  sampleClip(clip, 1.25f, pose);  // channel 0: segment 1..2; channel 1: segment 0.5..2
  EXPECT_FLOAT_EQ(pose.local[0].translation.x, 1.25f);
  EXPECT_FLOAT_EQ(pose.local[1].translation.x, 20.0f + 60.0f * 0.5f);
}

}  // namespace
}  // namespace kinema
