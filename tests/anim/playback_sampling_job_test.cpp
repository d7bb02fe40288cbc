// PlaybackSamplingJob (the PlaybackClip fast path) against sampleChannelReference, the plain
// evaluation, applied channel by channel in clip order: equal to 1e-6 on random clips of
// every target and interpolation, sampled forward, backward, by jumps, at key times and
// before the first / after the last key, with one context carried through all of it.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "anim/playback_sampling_job.h"
#include "anim/sampling.h"
#include "anim/reference_pose.h"
#include "test_support.h"

namespace kinema {
namespace KINEMA_UNITY_ID {

constexpr float kTolerance = 1e-6f;

const Interpolation kVectorModes[] = {Interpolation::Step,       Interpolation::Linear, Interpolation::Hermite,
                                      Interpolation::CatmullRom, Interpolation::TCB,    Interpolation::Bezier,
                                      Interpolation::Ease};
const Interpolation kRotationModes[] = {Interpolation::Step,   Interpolation::Linear, Interpolation::Hermite,
                                        Interpolation::Bezier, Interpolation::Ease,   Interpolation::Nlerp,
                                        Interpolation::Squad};

// A unit quaternion turned from `q` by up to `step` radians about a random axis; now and
// then its negative (the same rotation), so that slerp must pick the shorter arc.
glm::quat wander(const glm::quat& q, float step, std::mt19937& rng) {
  std::normal_distribution<float> g(0.0f, 1.0f);
  std::uniform_real_distribution<float> a(0.0f, step);
  const glm::quat r =
      glm::normalize(q * glm::angleAxis(a(rng), glm::normalize(glm::vec3(g(rng), g(rng), g(rng)) + 1e-3f)));
  return rng() % 7 == 0 ? -r : r;
}

// How a random channel is made.
enum class Form { SharedLinear, SharedStep, SharedPerKeyLinear, OwnTimesLinear, OtherMode, PerKeyMixed, SingleKey };

// `joints` joints with a random base pose; for each joint and part (translation, rotation or
// Euler, scale) maybe a channel of a random form. Two shared key grids (one regular, one
// uneven) carry most channels, as imported motion does; rotation keys wander from fractions
// of a degree to beyond the series' 74 degrees, some stored off unit length. Some parts get
// two channels (the later counts), and there are Scalar channels and channels of joints the
// skeleton lacks, which sampling skips.
Clip randomClip(int joints, int keys, std::mt19937& rng) {
  std::uniform_real_distribution<float> val(-2.0f, 2.0f), gap(0.01f, 0.2f), coin(0.0f, 1.0f);
  std::vector<float> grids[2];
  for (int k = 0; k < keys; ++k) grids[0].push_back(k / 30.0f);
  for (float t = gap(rng) - 0.1f; static_cast<int>(grids[1].size()) < keys; t += gap(rng)) grids[1].push_back(t);
  const float steps[] = {0.01f, 0.05f, 0.3f, 1.0f, 2.5f};
  Clip clip;
  auto makeChannel = [&](int joint, ChannelTarget target) {
    Channel c;
    c.joint = joint;
    c.target = target;
    const bool rotation = target == ChannelTarget::Rotation;
    const Interpolation* modes = rotation ? kRotationModes : kVectorModes;
    const Form form = static_cast<Form>(rng() % 7 < 3 ? rng() % 3 : rng() % 7);  // shared grids more often
    const bool shared = form == Form::SharedLinear || form == Form::SharedStep || form == Form::SharedPerKeyLinear;
    const std::vector<float>& grid = grids[rng() % 2];
    const int n = form == Form::SingleKey ? 1 : keys;
    float t = gap(rng) - 0.1f;
    for (int k = 0; k < n; ++k, t += gap(rng)) c.times.push_back(shared ? grid[k] : t);
    const float step = steps[rng() % 5];
    const float scale = rng() % 4 == 0 ? 1.5f : 1.0f;
    glm::quat q = test::randomRotation(rng);
    for (int k = 0; k < n; ++k) {
      if (rotation) {
        q = wander(q, step, rng);
        c.values.emplace_back(scale * q.x, scale * q.y, scale * q.z, scale * q.w);
      } else {
        c.values.emplace_back(val(rng), val(rng), val(rng), 0.0f);
      }
    }
    c.interpolation = form == Form::SharedStep ? Interpolation::Step
                      : form == Form::OtherMode ? modes[rng() % 7]
                                                : Interpolation::Linear;
    if (form == Form::SharedPerKeyLinear || form == Form::PerKeyMixed) {
      for (int k = 0; k < n; ++k) {
        KeySettings s;
        s.interpolation = form == Form::PerKeyMixed ? modes[rng() % 7] : Interpolation::Linear;
        s.easing = static_cast<EasingFunction>(rng() % 10);
        s.outTangent = glm::vec4(val(rng));
        s.inTangent = glm::vec4(val(rng));
        s.tension = val(rng) / 4, s.continuity = val(rng) / 4, s.bias = val(rng) / 4;
        c.keys.push_back(s);
      }
    }
    return c;
  };
  for (int j = 0; j < joints; ++j) {
    for (ChannelTarget target : {ChannelTarget::Translation, ChannelTarget::Rotation, ChannelTarget::Scale}) {
      if (coin(rng) < 0.15f) continue;  // this part keeps the base pose
      const int count = coin(rng) < 0.1f ? 2 : 1;
      for (int i = 0; i < count; ++i) {
        Channel c = makeChannel(j, target);
        if (target == ChannelTarget::Rotation && coin(rng) < 0.15f) {
          c.target = ChannelTarget::Euler;
          c.eulerOrder = static_cast<EulerOrder>(rng() % 6);
          for (glm::vec4& v : c.values) v = glm::vec4(val(rng), val(rng), val(rng), 0.0f);
          if (c.interpolation == Interpolation::Nlerp || c.interpolation == Interpolation::Squad)
            c.interpolation = Interpolation::Linear;
          for (KeySettings& s : c.keys)
            if (s.interpolation == Interpolation::Nlerp || s.interpolation == Interpolation::Squad)
              s.interpolation = Interpolation::Linear;
        }
        clip.channels.push_back(std::move(c));
      }
    }
  }
  Channel scalar = makeChannel(-1, ChannelTarget::Translation);
  scalar.target = ChannelTarget::Scalar;
  scalar.property = "weight";
  clip.channels.insert(clip.channels.begin() + rng() % (clip.channels.size() + 1), scalar);
  clip.channels.push_back(makeChannel(joints, ChannelTarget::Translation));  // a joint the skeleton lacks
  return clip;
}

// sampleClip's meaning, from the plain evaluation: each channel in clip order onto the base.
Pose randomBase(int joints, std::mt19937& rng) {
  std::uniform_real_distribution<float> val(-1.0f, 1.0f);
  Pose p;
  for (int j = 0; j < joints; ++j) {
    Transform t;
    t.translation = glm::vec3(val(rng), val(rng), val(rng));
    t.rotation = test::randomRotation(rng);
    t.scale = glm::vec3(1.0f + 0.5f * val(rng));
    p.local.push_back(t);
  }
  return p;
}

// The times of one case, in the order they are sampled with one context: forward playback
// from before the first key to past the last, then backward, then jumps anywhere, then
// every key time of every channel.
std::vector<float> sampleTimes(const Clip& clip, std::mt19937& rng) {
  float start = 0.0f, end = 0.0f;
  for (const Channel& ch : clip.channels) start = std::min(start, ch.startTime()), end = std::max(end, ch.endTime());
  std::vector<float> times;
  for (float t = start - 0.2f; t <= end + 0.2f; t += 1.0f / 60.0f) times.push_back(t);
  for (float t = end + 0.1f; t >= start - 0.1f; t -= 1.0f / 24.0f) times.push_back(t);
  std::uniform_real_distribution<float> any(start - 0.3f, end + 0.3f);
  for (int i = 0; i < 150; ++i) times.push_back(any(rng));
  for (const Channel& ch : clip.channels) times.insert(times.end(), ch.times.begin(), ch.times.end());
  return times;
}

TEST(PlaybackSamplingJob, EqualsReferenceOnRandomClipsOfEveryInterpolation) {
  const int cases = test::propertyCases(60);
  std::mt19937 rng(2020);
  int gridTracks = 0, otherTracks = 0;
  for (int c = 0; c < cases; ++c) {
    const int joints = 1 + static_cast<int>(rng() % 24);
    const int keys = 2 + static_cast<int>(rng() % 40);
    const Clip clip = randomClip(joints, keys, rng);
    const Pose base = randomBase(joints, rng);
    const PlaybackClip playback = PlaybackClip::build(clip, joints);
    otherTracks += static_cast<int>(playback.channels.size());
    gridTracks += playback.trackCount() - static_cast<int>(playback.channels.size());
    PlaybackContext context;
    Pose pose = base;
    float worst = 0.0f, worstTime = 0.0f;
    for (float t : sampleTimes(clip, rng)) {
      ASSERT_TRUE(samplePlayback(playback, t, pose, context));
      const float d = test::maxPoseDifference(pose, test::referencePose(clip, base, t));
      if (d > worst) worst = d, worstTime = t;
    }
    EXPECT_LE(worst, kTolerance) << "case " << c << " at time " << worstTime;
  }
  // Both halves of the job were exercised.
  EXPECT_GT(gridTracks, cases * 5);
  EXPECT_GT(otherTracks, cases * 5);
}

// A grid whose rows are long enough for the software prefetches (over 16,384 floats: 2,400
// joints of translation, rotation and scale make rows of 2,400 x 40 = 96,000 floats) gives
// the reference's values like any other, a few keys apart, at and between keys and off
// both ends (the prefetches change no value; here they run, and past a row's end too).
TEST(PlaybackSamplingJob, LongRowsWithPrefetchesEqualTheReference) {
  constexpr int kJoints = 2400;
  std::mt19937 rng(24);
  std::uniform_real_distribution<float> val(-2.0f, 2.0f);
  const std::vector<float> times = {0.0f, 0.4f, 0.5f, 1.25f};
  Clip clip;
  for (int j = 0; j < kJoints; ++j) {
    std::vector<glm::vec4> t, r, sc;
    glm::quat q = test::randomRotation(rng);
    for (size_t k = 0; k < times.size(); ++k) {
      t.emplace_back(val(rng), val(rng), val(rng), 0.0f);
      q = wander(q, 0.5f, rng);
      r.emplace_back(q.x, q.y, q.z, q.w);
      sc.emplace_back(1.0f + 0.2f * val(rng), 1.0f, 1.0f + 0.1f * val(rng), 0.0f);
    }
    clip.channels.push_back(Channel(j, ChannelTarget::Translation, Interpolation::Linear, times, t));
    clip.channels.push_back(Channel(j, ChannelTarget::Rotation, Interpolation::Linear, times, r));
    clip.channels.push_back(Channel(j, ChannelTarget::Scale, j % 3 ? Interpolation::Linear : Interpolation::Step, times, sc));
  }
  const PlaybackClip playback = PlaybackClip::build(clip, kJoints);
  ASSERT_EQ(playback.grids.size(), 1u);
  ASSERT_GT(playback.grids[0].rowFloats, 16384);
  const Pose base = randomBase(kJoints, rng);
  PlaybackContext context;
  Pose pose = base;
  for (float t : {-0.1f, 0.0f, 0.2f, 0.4f, 0.45f, 1.0f, 0.5f, 1.25f, 2.0f, 0.01f}) {
    ASSERT_TRUE(samplePlayback(playback, t, pose, context));
    EXPECT_LE(test::maxPoseDifference(pose, test::referencePose(clip, base, t)), kTolerance) << "time " << t;
  }
}

// Imported motion (one key grid, Linear, unit quaternions): every channel lands in one grid,
// in blocks of four tracks; 5 joints need two blocks per part, the second padded.
TEST(PlaybackSamplingJob, ImportedMotionIsOneGridOfFourTrackBlocks) {
  Clip clip;
  const std::vector<float> times = {0.0f, 0.5f, 1.0f};
  for (int j = 0; j < 5; ++j) {
    clip.channels.push_back(Channel(j, ChannelTarget::Translation, Interpolation::Linear, times,
                                    {glm::vec4(j, 0, 0, 0), glm::vec4(j, 2, 0, 0), glm::vec4(j, 2, 4, 0)}));
    const glm::quat q0(1, 0, 0, 0), q1 = glm::angleAxis(1.0f, glm::vec3(0, 0, 1));
    clip.channels.push_back(Channel(j, ChannelTarget::Rotation, Interpolation::Linear, times,
                                    {glm::vec4(0, 0, 0, 1), glm::vec4(q1.x, q1.y, q1.z, q1.w),
                                     glm::vec4(q0.x, q0.y, q0.z, q0.w)}));
  }
  const PlaybackClip p = PlaybackClip::build(clip, 5);
  ASSERT_EQ(p.grids.size(), 1u);
  EXPECT_TRUE(p.channels.empty());
  EXPECT_EQ(p.grids[0].translationBlocks, 2);
  EXPECT_EQ(p.grids[0].scaleBlocks, 0);
  EXPECT_EQ(p.grids[0].rotationBlocks, 2);
  EXPECT_EQ(p.trackCount(), 10);
  // Hand-derived values: a straight line in translation, constant angular speed in rotation.
  Skeleton s;
  for (int j = 0; j < 5; ++j) s.addJoint("j" + std::to_string(j), j - 1, Transform());
  Pose pose = Pose::rest(s);
  PlaybackContext context;
  ASSERT_TRUE(samplePlayback(p, 0.75f, pose, context));
  for (int j = 0; j < 5; ++j) {
    EXPECT_NEAR(pose.local[j].translation.x, j, 1e-6f);
    EXPECT_NEAR(pose.local[j].translation.y, 2.0f, 1e-6f);
    EXPECT_NEAR(pose.local[j].translation.z, 2.0f, 1e-6f);
    const glm::quat expected = glm::angleAxis(0.5f, glm::vec3(0, 0, 1));  // half-way back from 1 rad
    for (int i = 0; i < 4; ++i) EXPECT_NEAR(pose.local[j].rotation[i], expected[i], 1e-6f) << j;
    EXPECT_EQ(pose.local[j].scale, glm::vec3(1.0f));  // not animated: the rest pose
  }
}

// Cursors are hints: a context first used with one clip gives the right values for another.
TEST(PlaybackSamplingJob, AContextFromAnotherClipOnlyCostsASearch) {
  std::mt19937 rng(9);
  const Clip a = randomClip(8, 30, rng), b = randomClip(8, 5, rng);
  const Pose base = randomBase(8, rng);
  const PlaybackClip pa = PlaybackClip::build(a, 8), pb = PlaybackClip::build(b, 8);
  PlaybackContext context;
  Pose pose = base;
  ASSERT_TRUE(samplePlayback(pa, a.duration(), pose, context));
  pose = base;
  ASSERT_TRUE(samplePlayback(pb, 0.1f, pose, context));
  EXPECT_LE(test::maxPoseDifference(pose, test::referencePose(b, base, 0.1f)), kTolerance);
}

TEST(PlaybackSamplingJob, ValidateRefusesMissingOrShortInputsAndWritesNothing) {
  Clip clip;
  clip.channels.push_back(Channel(2, ChannelTarget::Translation, Interpolation::Linear, {0.0f, 1.0f},
                                  {glm::vec4(1.0f), glm::vec4(2.0f)}));
  const PlaybackClip p = PlaybackClip::build(clip, 3);
  PlaybackContext context;
  std::vector<Transform> out(3);
  PlaybackSamplingJob job;
  job.clip = &p;
  job.context = &context;
  job.output = out.data();
  job.outputCount = 3;
  job.time = 0.5f;
  EXPECT_EQ(job.validate(), "");
  PlaybackSamplingJob bad = job;
  bad.clip = nullptr;
  EXPECT_NE(bad.validate(), "");
  bad = job;
  bad.context = nullptr;
  EXPECT_NE(bad.validate(), "");
  bad = job;
  bad.outputCount = 2;  // joint 2 would be written past the end
  EXPECT_NE(bad.validate().find("3 joints"), std::string::npos);
  EXPECT_FALSE(bad.run());
  bad = job;
  bad.time = std::nanf("");
  EXPECT_FALSE(bad.run());
  bad = job;
  bad.output = nullptr;
  EXPECT_FALSE(bad.run());
  EXPECT_EQ(out[2].translation, glm::vec3(0.0f));  // nothing written by the refused runs
  ASSERT_TRUE(job.run());
  EXPECT_EQ(out[2].translation, glm::vec3(1.5f));
}

}  // namespace
}  // namespace kinema
