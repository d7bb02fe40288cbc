// Clip sampling with cursors, Euler and scalar channels, key editing, insert keyframe.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "anim/insert_keyframe.h"
#include "anim_test_support.h"
#include "test_support.h"

namespace kinema {
namespace KINEMA_UNITY_ID {

constexpr double kPi = 3.14159265358979323846;

Skeleton chain(int n) {
  Skeleton s;
  for (int i = 0; i < n; ++i) s.addJoint("j" + std::to_string(i), i - 1, Transform::fromTranslation({0, 0.5f, 0}));
  return s;
}

// A clip mixing every mode, keys at random times per channel.
Clip randomClip(int joints, int keys, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<float> val(-2, 2), gap(0.01f, 0.2f);
  const Interpolation vecModes[] = {Interpolation::Step, Interpolation::Linear, Interpolation::Hermite,
                                    Interpolation::CatmullRom, Interpolation::TCB, Interpolation::Bezier,
                                    Interpolation::Ease};
  const Interpolation rotModes[] = {Interpolation::Linear, Interpolation::Nlerp, Interpolation::Squad,
                                    Interpolation::Hermite, Interpolation::Step, Interpolation::Bezier};
  Clip clip;
  for (int j = 0; j < joints; ++j)
    for (ChannelTarget target : {ChannelTarget::Translation, ChannelTarget::Rotation}) {
      Channel c;
      c.joint = j;
      c.target = target;
      float t = gap(rng) - 0.1f;
      for (int k = 0; k < keys; ++k) {
        KeySettings s;
        if (target == ChannelTarget::Rotation) {
          s.interpolation = rotModes[rng() % 5];
          const glm::quat q = glm::normalize(glm::quat(val(rng), val(rng), val(rng), val(rng)));
          c.values.emplace_back(q.x, q.y, q.z, q.w);
        } else {
          s.interpolation = vecModes[rng() % 7];
          c.values.emplace_back(val(rng), val(rng), val(rng), 0.0f);
        }
        s.outTangent = glm::vec4(val(rng));
        s.tension = val(rng) / 4;
        c.times.push_back(t);
        c.keys.push_back(s);
        t += gap(rng);
      }
      clip.channels.push_back(c);
    }
  return clip;
}

bool samePose(const Pose& a, const Pose& b) {
  for (int i = 0; i < a.size(); ++i)
    if (a.local[i].translation != b.local[i].translation || a.local[i].rotation != b.local[i].rotation) return false;
  return true;
}

TEST(Sampling, PlaybackWithCursorsEqualsRandomAccess) {
  const Skeleton s = chain(6);
  const int cases = test::propertyCases(5);
  for (int c = 0; c < cases; ++c) {
    const Clip clip = randomClip(6, 40, 1234u + c);
    const Skeleton& sk = s;
    ASSERT_EQ(clip.validate(sk), "");
    SamplingCache cache;
    // Forward playback at 60 fps, a backward stretch and random jumps: identical results.
    std::vector<float> times;
    for (int f = -5; f < 60 * 5; ++f) times.push_back(f / 60.0f);
    for (int f = 100; f > 20; --f) times.push_back(f / 60.0f);
    std::mt19937 rng(c);
    for (int i = 0; i < 100; ++i) times.push_back(std::uniform_real_distribution<float>(-1, 6)(rng));
    for (float t : times) {
      Pose a = Pose::rest(sk), b = Pose::rest(sk);
      sampleClip(clip, t, a, cache);
      sampleClip(clip, t, b);
      ASSERT_TRUE(samePose(a, b)) << "case " << c << " t " << t;
    }
  }
}

TEST(Sampling, CursorAdvancesOneSegmentAtATime) {
  Channel c = test::scalarChannel({0, 1, 2, 3}, {0, 1, 2, 3}, Interpolation::Linear);
  int cursor = 0;
  EXPECT_EQ(upperKey(c, -1.0f, &cursor), 0);
  EXPECT_EQ(upperKey(c, 0.5f, &cursor), 1);
  EXPECT_EQ(cursor, 1);
  EXPECT_EQ(upperKey(c, 1.5f, &cursor), 2);
  EXPECT_EQ(upperKey(c, 3.0f, &cursor), 4);
  EXPECT_EQ(upperKey(c, 0.2f, &cursor), 1);  // a jump back: binary search
}

TEST(Sampling, EulerChannelsUnwrapAndConvert) {
  Channel e;
  e.joint = 0;
  e.target = ChannelTarget::Euler;
  e.eulerOrder = EulerOrder::ZXY;
  e.times = {0, 1};
  // 170 and -170 degrees about Z: unwrapped, the second becomes 190, and halfway is 180 (not 0).
  e.values = {{0, 0, static_cast<float>(170 * kPi / 180), 0}, {0, 0, static_cast<float>(-170 * kPi / 180), 0}};
  unwrapEulerAngles(e);
  EXPECT_NEAR(e.values[1].z, 190 * kPi / 180, 1e-5);
  Clip clip;
  clip.channels.push_back(e);
  const Skeleton s = chain(1);
  Pose p = Pose::rest(s);
  sampleClip(clip, 0.5f, p);
  EXPECT_NEAR(std::abs(p.local[0].rotation.z), 1.0, 1e-5);  // 180 deg about Z: (0,0,+-1,0)
  // Other angles go through eulerToQuat with the channel's order.
  clip.channels[0].values = {{0.3f, -0.2f, 0.1f, 0}, {0.3f, -0.2f, 0.1f, 0}};
  sampleClip(clip, 0.5f, p);
  const glm::quat q = eulerToQuat({0.3f, -0.2f, 0.1f}, EulerOrder::ZXY);
  EXPECT_NEAR(std::abs(glm::dot(q, p.local[0].rotation)), 1.0f, 1e-6f);
}

TEST(Sampling, ScalarChannelsAreReadButDoNotTouchThePose) {
  Clip clip;
  Channel c = test::scalarChannel({0, 2}, {1, 5}, Interpolation::Linear);
  c.property = "blink";
  clip.channels.push_back(c);
  const Skeleton s = chain(2);
  EXPECT_EQ(clip.validate(s), "");
  Pose p = Pose::rest(s);
  sampleClip(clip, 1.0f, p);
  EXPECT_TRUE(samePose(p, Pose::rest(s)));
  EXPECT_FLOAT_EQ(sampleChannel(clip.channels[0], 1.0f).x, 3.0f);
}

TEST(KeyEditing, InsertMoveDeleteKeepTheChannelSorted) {
  Channel c = test::scalarChannel({0, 1, 2}, {0, 10, 20}, Interpolation::Linear);
  EXPECT_EQ(insertKey(c, 1.5f, glm::vec4(15, 0, 0, 0)), 2);
  EXPECT_EQ(c.times, (std::vector<float>{0, 1, 1.5f, 2}));
  EXPECT_EQ(insertKey(c, 1.0f, glm::vec4(11, 0, 0, 0)), 1);  // same time: replaces
  EXPECT_EQ(c.keyCount(), 4);
  EXPECT_EQ(c.values[1].x, 11);
  EXPECT_EQ(moveKey(c, 0, 1.75f), 2);  // key 0 moves between 1.5 and 2
  EXPECT_EQ(c.times, (std::vector<float>{1, 1.5f, 1.75f, 2}));
  EXPECT_EQ(c.values[2].x, 0);
  EXPECT_EQ(moveKey(c, 2, 1.0f), 0);  // onto another key: replaces it
  EXPECT_EQ(c.times, (std::vector<float>{1, 1.5f, 2}));
  deleteKey(c, 1);
  EXPECT_EQ(c.times, (std::vector<float>{1, 2}));
  EXPECT_EQ(c.keys.size(), c.times.size());
  Clip clip;
  clip.channels.push_back(c);
  EXPECT_EQ(clip.validate(chain(1)), "");
  // The first key of an empty channel keeps its own settings.
  Channel empty;
  empty.target = ChannelTarget::Scalar;
  KeySettings tcb;
  tcb.interpolation = Interpolation::TCB;
  tcb.bias = 0.5f;
  insertKey(empty, 1.0f, glm::vec4(1.0f), tcb);
  insertKey(empty, 0.5f, glm::vec4(2.0f));  // takes the settings of the key after it
  ASSERT_EQ(empty.keys.size(), 2u);
  EXPECT_EQ(empty.keys[1].bias, 0.5f);
  EXPECT_EQ(empty.keys[0].interpolation, Interpolation::TCB);
}

TEST(ClipValidate, RejectsModesThatDoNotFitTheTarget) {
  const Skeleton s = chain(1);
  Clip clip;
  Channel r;
  r.joint = 0;
  r.target = ChannelTarget::Rotation;
  r.interpolation = Interpolation::TCB;
  r.times = {0};
  r.values = {{0, 0, 0, 1}};
  clip.channels.push_back(r);
  EXPECT_NE(clip.validate(s).find("tcb"), std::string::npos);
  clip.channels[0].interpolation = Interpolation::Bezier;  // quaternion F-curves: accepted
  EXPECT_EQ(clip.validate(s), "");
  clip.channels[0].target = ChannelTarget::Translation;
  clip.channels[0].interpolation = Interpolation::Squad;
  EXPECT_NE(clip.validate(s).find("squad"), std::string::npos);
  clip.channels[0].interpolation = Interpolation::Linear;
  clip.channels[0].keys.resize(1);
  clip.channels[0].keys[0].bias = NAN;
  EXPECT_NE(clip.validate(s).find("non-finite"), std::string::npos);
}

TEST(InsertKeyframe, KeysThePoseAndKeepsMotionSmooth) {
  const Skeleton s = chain(3);
  Clip clip;
  Pose pose = Pose::rest(s);
  InsertKeyframeJob job;
  job.joints = {1};
  for (auto [t, x] : {std::pair<float, float>{0, 0}, {2, 2}, {4, 0}}) {
    pose.local[1].translation.x = x;
    pose.local[1].rotation = axisAngle({0, 0, 1}, x);
    job.time = t;
    EXPECT_EQ(job.validate(s, pose), "");
    EXPECT_EQ(insertKeyframe(clip, job, pose), 2);
  }
  ASSERT_EQ(clip.channels.size(), 2u);
  EXPECT_EQ(clip.validate(s), "");
  const Channel& tr = clip.channels[0];
  EXPECT_EQ(tr.keyCount(), 3);
  EXPECT_EQ(tr.settings(1).interpolation, Interpolation::Bezier);
  // Keys are hit exactly, the curve is smooth through the middle key (auto-clamped handles).
  Pose p = Pose::rest(s);
  sampleClip(clip, 2.0f, p);
  EXPECT_EQ(p.local[1].translation.x, 2.0f);
  // Insert a key on the existing curve between keys: the motion stays C1 at the new key.
  sampleClip(clip, 1.0f, p);
  pose = p;
  job.time = 1.0f;
  insertKeyframe(clip, job, pose);
  const Channel& c = clip.channels[0];
  auto x = [&](double t) { return static_cast<double>(sampleChannel(c, static_cast<float>(t)).x); };
  const double h = 1e-3;
  EXPECT_NEAR((x(1) - x(1 - h)) / h, (x(1 + h) - x(1)) / h, 0.02);
  // Rotation keys are Bezier with auto-clamped handles (eased, as Blender's) and keep the
  // sign nearest the previous key.
  EXPECT_EQ(clip.channels[1].settings(0).interpolation, Interpolation::Bezier);
  EXPECT_EQ(clip.channels[1].settings(0).rightHandleType, HandleType::AutoClamped);
  pose.local[1].rotation = -axisAngle({0, 0, 1}, 0.1f);
  job.time = 5.0f;
  insertKeyframe(clip, job, pose);
  const Channel& rc = clip.channels[1];
  EXPECT_GT(glm::dot(rc.values[rc.keyCount() - 1], rc.values[rc.keyCount() - 2]), 0.0f);
  job.joints = {7};
  EXPECT_FALSE(job.validate(s, pose).empty());
}

}  // namespace
}  // namespace kinema
