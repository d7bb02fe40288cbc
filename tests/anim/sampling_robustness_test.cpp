// Sampling never emits NaN (issue 11): random clips in every interpolation mode, with
// degenerate keys mixed in (identical and opposite rotations, zero and tiny values, keys
// 1e-6 s apart, tangents and handles at odd angles), sampled at random, exact-key and
// out-of-range times. Every valid clip must give finite values and unit rotations.
#include <cmath>
#include <random>

#include "anim/clip.h"
#include "anim/sampling.h"
#include "test_support.h"

namespace kinema {
namespace KINEMA_UNITY_ID {

struct Gen {
  std::mt19937 rng;
  float uniform(float a, float b) { return std::uniform_real_distribution<float>(a, b)(rng); }
  int pick(int n) { return std::uniform_int_distribution<int>(0, n - 1)(rng); }

  // Ordinary numbers most of the time, degenerate ones often enough to matter.
  float value() {
    switch (pick(8)) {
      case 0: return 0.0f;
      case 1: return 1e-30f * uniform(-1, 1);  // denormal-adjacent
      case 2: return 1e6f * uniform(-1, 1);
      default: return uniform(-3, 3);
    }
  }
  glm::vec4 vec() { return {value(), value(), value(), 0.0f}; }
  glm::vec4 rotation(const glm::vec4* previous) {
    if (previous && pick(4) == 0) return *previous;   // the same key twice
    if (previous && pick(4) == 0) return -*previous;  // the same rotation, opposite sign
    const glm::quat q = test::randomRotation(rng);
    return {q.x, q.y, q.z, q.w};
  }
};

Channel randomChannel(Gen& g) {
  Channel ch;
  ch.joint = 0;
  const ChannelTarget targets[] = {ChannelTarget::Translation, ChannelTarget::Rotation, ChannelTarget::Scale,
                                   ChannelTarget::Euler};
  ch.target = targets[g.pick(4)];
  ch.eulerOrder = static_cast<EulerOrder>(g.pick(6));
  const int keys = 1 + g.pick(6);
  float t = g.uniform(-2, 2);
  for (int k = 0; k < keys; ++k) {
    ch.times.push_back(t);
    const float gaps[] = {1e-6f, 1e-3f, 0.5f, 1.0f, 1e3f};
    const float next = t + gaps[g.pick(5)] * g.uniform(1.0f, 2.0f);
    t = next > t ? next : std::nextafter(t, INFINITY);  // 1e-6 s is below float spacing past 8 s
    ch.values.push_back(ch.target == ChannelTarget::Rotation ? g.rotation(k ? &ch.values.back() : nullptr) : g.vec());
    KeySettings s;
    const Interpolation all[] = {Interpolation::Step,  Interpolation::Linear, Interpolation::Hermite,
                                 Interpolation::CatmullRom, Interpolation::TCB, Interpolation::Bezier,
                                 Interpolation::Ease,  Interpolation::Nlerp,  Interpolation::Squad};
    do s.interpolation = all[g.pick(9)];
    while (ch.target == ChannelTarget::Rotation
               ? !(s.interpolation == Interpolation::Step || s.interpolation == Interpolation::Linear ||
                   s.interpolation == Interpolation::Nlerp || s.interpolation == Interpolation::Squad ||
                   s.interpolation == Interpolation::Hermite || s.interpolation == Interpolation::Ease ||
                   s.interpolation == Interpolation::Bezier)
               : (s.interpolation == Interpolation::Nlerp || s.interpolation == Interpolation::Squad));
    s.easing = static_cast<EasingFunction>(g.pick(10));
    s.easingMode = static_cast<EasingMode>(g.pick(3));
    s.tension = g.uniform(-1, 1), s.continuity = g.uniform(-1, 1), s.bias = g.uniform(-1, 1);
    if (g.pick(4) == 0) s.tension = 1.0f;  // tension 1: zero tangents
    s.inTangent = g.vec(), s.outTangent = g.vec();
    s.leftHandleType = static_cast<HandleType>(g.pick(5));
    s.rightHandleType = static_cast<HandleType>(g.pick(5));
    s.leftHandleTime = g.pick(4) == 0 ? 0.0f : -g.uniform(0, 2);  // zero-length handles too
    s.rightHandleTime = g.pick(4) == 0 ? 0.0f : g.uniform(0, 2);
    s.leftHandleValue = g.vec(), s.rightHandleValue = g.vec();
    ch.keys.push_back(s);
  }
  return ch;
}

TEST(SamplingRobustness, ValidClipsNeverGiveNanOrNonUnitRotations) {
  Skeleton skeleton;
  skeleton.addJoint("a", -1, Transform::identity());
  const int cases = test::propertyCases(100000);
  Gen g{std::mt19937(20261122u)};
  int sampled = 0;
  for (int c = 0; c < cases; ++c) {
    Clip clip;
    clip.channels.push_back(randomChannel(g));
    ASSERT_EQ(clip.validate(skeleton), "") << "case " << c;
    const Channel& ch = clip.channels[0];
    std::vector<float> times = {ch.times.front() - 1.0f, ch.times.back() + 1.0f, -INFINITY, INFINITY, -1e30f, 1e30f};
    for (float t : ch.times) times.push_back(t);
    for (int i = 0; i < 4; ++i) times.push_back(g.uniform(ch.times.front(), ch.times.back()));
    for (size_t k = 0; k + 1 < ch.times.size(); ++k)  // just inside each segment
      times.push_back(std::nextafter(ch.times[k], ch.times[k + 1]));
    for (float t : times) {
      Pose pose = Pose::rest(skeleton);
      sampleClip(clip, t, pose);
      const Transform& x = pose.local[0];
      ASSERT_TRUE(x.isFinite()) << "case " << c << " target " << toString(ch.target) << " time " << t
                                << " interpolation " << toString(ch.settings(0).interpolation);
      ASSERT_NEAR(glm::length(x.rotation), 1.0f, 1e-4f) << "case " << c << " time " << t;
      ++sampled;
    }
    // A NaN time has no meaning, but it must not crash (the CLI and editor never pass one).
    Pose pose = Pose::rest(skeleton);
    sampleClip(clip, NAN, pose);
  }
  EXPECT_GT(sampled, cases * 10);
}

}  // namespace
}  // namespace kinema
