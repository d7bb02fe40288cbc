// Channel modifiers: noise (deterministic, bounded, continuous), cycles (with offset and
// mirror), the seed's travelling wave, stacking and baking.
#include <gtest/gtest.h>

#include <cmath>

#include "anim/sampling.h"
#include "anim/channel_modifiers.h"
#include "test_support.h"

namespace kinema {
namespace KINEMA_UNITY_ID {

Channel flatTranslation() { return Channel(0, ChannelTarget::Translation, Interpolation::Linear, {0.0f, 10.0f}, {glm::vec4(0.0f), glm::vec4(0.0f)}); }

ChannelModifier noise(float strength, float scale, int octaves, uint32_t seed) {
  ChannelModifier m;
  m.kind = ChannelModifierKind::Noise;
  m.noise.strength = strength;
  m.noise.scale = scale;
  m.noise.octaves = octaves;
  m.noise.seed = seed;
  return m;
}

// The channel with `stack` on joint `joint`, its waves' x set to `rest`.
Channel withStack(Channel c, const std::vector<ChannelModifier>& stack, int joint = 0, glm::vec3 rest = glm::vec3(0.0f)) {
  c.joint = joint;
  c.modifiers = stack;
  for (ChannelModifier& m : c.modifiers) m.wave.position = rest;
  return c;
}

glm::vec4 evaluate(const Channel& c, const std::vector<ChannelModifier>& stack, float t, int joint = 0,
                   glm::vec3 rest = glm::vec3(0.0f)) {
  const Channel modified = withStack(c, stack, joint, rest);
  ModifiedChannelJob job;
  job.channel = &modified;
  EXPECT_EQ(job.validate(), "");
  return job.evaluate(t);
}

TEST(NoiseModifier, DeterministicPerSeedAndDifferentAcrossSeedsAndJoints) {
  const Channel c = flatTranslation();
  const std::vector<ChannelModifier> a = {noise(0.5f, 0.7f, 3, 7)}, b = {noise(0.5f, 0.7f, 3, 8)};
  int differ = 0, jointsDiffer = 0;
  for (int i = 0; i < 200; ++i) {
    const float t = 0.05f * i;
    EXPECT_EQ(evaluate(c, a, t), evaluate(c, a, t));  // bit for bit
    differ += evaluate(c, a, t) != evaluate(c, b, t);
    jointsDiffer += evaluate(c, a, t, 0) != evaluate(c, a, t, 1);
  }
  EXPECT_GT(differ, 190);
  EXPECT_GT(jointsDiffer, 190);
}

TEST(NoiseModifier, StaysWithinItsStrengthAndUsesIt) {
  const Channel c = flatTranslation();
  for (int octaves : {1, 4, 8}) {
    const std::vector<ChannelModifier> stack = {noise(0.3f, 0.5f, octaves, 3)};
    float largest = 0.0f;
    const int samples = std::max(2000, test::propertyCases(20000));  // cheap: never fewer
    for (int i = 0; i < samples; ++i) {
      const glm::vec4 v = evaluate(c, stack, -50.0f + 100.0f * i / samples);
      for (int k = 0; k < 3; ++k) {
        EXPECT_LE(std::abs(v[k]), 0.3f + 1e-6f);
        largest = std::max(largest, std::abs(v[k]));
      }
      EXPECT_EQ(v.w, 0.0f);  // w is not a translation component
    }
    EXPECT_GT(largest, 0.1f) << octaves;  // it does move the channel
  }
}

TEST(NoiseModifier, ContinuousWithItsDerivativeBounded) {
  // Per octave n(x) = 2((1 - s) g0 u + s g1 (u - 1)), |g| <= 1, s the quintic fade (s' <= 15/8):
  // |n'| <= 2 (s' (u + 1 - u) + (1 - s) + s) <= 2 (15/8 + 1) = 5.75 per lattice cell. Octave o
  // runs 2^o cells per `scale` seconds with amplitude r^o, so
  // |dv/dt| <= strength * 5.75 * sum(r^o 2^o) / (scale * sum(r^o)).
  const Channel c = flatTranslation();
  for (int octaves : {1, 3}) {
    const float strength = 0.4f, scale = 0.25f, r = 0.5f;
    double num = 0, den = 0;
    for (int o = 0; o < octaves; ++o) num += std::pow(r, o) * std::pow(2.0, o), den += std::pow(r, o);
    const double bound = strength * 5.75 * num / (scale * den);
    const std::vector<ChannelModifier> stack = {noise(strength, scale, octaves, 11)};
    const float dt = 1e-3f;
    double steepest = 0.0;
    glm::vec4 previous = evaluate(c, stack, 0.0f);
    const int samples = std::max(2000, test::propertyCases(20000));  // cheap: never fewer
    for (int i = 1; i <= samples; ++i) {
      const glm::vec4 v = evaluate(c, stack, i * dt);
      for (int k = 0; k < 3; ++k) steepest = std::max(steepest, double(std::abs(v[k] - previous[k])) / dt);
      previous = v;
    }
    EXPECT_LE(steepest, bound * 1.01) << octaves;  // 1 % for float rounding over dt
    EXPECT_GT(steepest, 0.05 * bound) << octaves;
  }
}

TEST(NoiseModifier, RotationChannelsTurnByAtMostTheStrengthPerAxis) {
  const glm::quat keyed = glm::angleAxis(0.7f, glm::normalize(glm::vec3(1, 2, 3)));
  const Channel c(0, ChannelTarget::Rotation, Interpolation::Linear, {0.0f, 1.0f},
                  {glm::vec4(keyed.x, keyed.y, keyed.z, keyed.w), glm::vec4(keyed.x, keyed.y, keyed.z, keyed.w)});
  const std::vector<ChannelModifier> stack = {noise(0.2f, 0.5f, 2, 1)};
  for (int i = 0; i < 500; ++i) {
    const glm::vec4 v = evaluate(c, stack, 0.01f * i);
    const glm::quat q(v.w, v.x, v.y, v.z);
    EXPECT_NEAR(glm::length(v), 1.0f, 1e-5f);
    // The turn from the keyed rotation is a rotation vector of components within +-0.2.
    const float angle = 2.0f * std::acos(std::min(1.0f, std::abs(glm::dot(q, keyed))));
    EXPECT_LE(angle, 0.2f * std::sqrt(3.0f) + 1e-4f);
  }
}

Channel rampKeys() {
  // Keys at 1, 2, 3 s: x goes 1 -> 4 -> 2, y stays 5.
  return Channel(0, ChannelTarget::Translation, Interpolation::Linear, {1.0f, 2.0f, 3.0f},
                 {glm::vec4(1, 5, 0, 0), glm::vec4(4, 5, 0, 0), glm::vec4(2, 5, 0, 0)});
}

ChannelModifier cycles(CycleMode before, CycleMode after, int beforeCount = 0, int afterCount = 0) {
  ChannelModifier m;
  m.kind = ChannelModifierKind::Cycles;
  m.cycles.before = before;
  m.cycles.after = after;
  m.cycles.beforeCount = beforeCount;
  m.cycles.afterCount = afterCount;
  return m;
}

TEST(CyclesModifier, RepeatWithOffsetReproducesTheKeyedRangeShifted) {
  const Channel c = rampKeys();
  const std::vector<ChannelModifier> stack = {cycles(CycleMode::RepeatWithOffset, CycleMode::RepeatWithOffset)};
  // Period 2 s, change per cycle (2 - 1, 0, 0) = (1, 0, 0).
  for (int i = 0; i <= 40; ++i) {
    const float t = 1.0f + 0.05f * i;  // inside the keyed range
    const glm::vec4 keyed = sampleChannel(c, t);
    for (int n : {-3, -1, 1, 2, 5}) {
      const glm::vec4 v = evaluate(c, stack, t + 2.0f * n);
      EXPECT_NEAR(v.x, keyed.x + n * 1.0f, 1e-4f) << t << " + " << n << " cycles";
      EXPECT_NEAR(v.y, 5.0f, 1e-5f);
    }
  }
  // Plain repeat: the same values, unshifted.
  const std::vector<ChannelModifier> repeat = {cycles(CycleMode::Repeat, CycleMode::Repeat)};
  EXPECT_NEAR(evaluate(c, repeat, 1.5f + 6.0f).x, 2.5f, 1e-4f);
  EXPECT_NEAR(evaluate(c, repeat, 1.5f - 4.0f).x, 2.5f, 1e-4f);
}

TEST(CyclesModifier, MirrorCountsAndHold) {
  const Channel c = rampKeys();
  const std::vector<ChannelModifier> mirror = {cycles(CycleMode::Mirror, CycleMode::Mirror)};
  for (float d : {0.25f, 0.5f, 1.5f}) {
    EXPECT_NEAR(evaluate(c, mirror, 3.0f + d).x, sampleChannel(c, 3.0f - d).x, 1e-4f);  // reflected after the end
    EXPECT_NEAR(evaluate(c, mirror, 1.0f - d).x, sampleChannel(c, 1.0f + d).x, 1e-4f);  // and before the start
  }
  // Two cycles after the end, then the value holds; Hold before = the first key's value.
  const std::vector<ChannelModifier> limited = {cycles(CycleMode::Hold, CycleMode::Repeat, 0, 2)};
  EXPECT_NEAR(evaluate(c, limited, 6.5f).x, sampleChannel(c, 2.5f).x, 1e-4f);  // in the second cycle
  EXPECT_NEAR(evaluate(c, limited, 9.0f).x, 2.0f, 1e-4f);                      // held at the end
  EXPECT_NEAR(evaluate(c, limited, -4.0f).x, 1.0f, 1e-4f);
  // A muted modifier changes nothing.
  std::vector<ChannelModifier> muted = {cycles(CycleMode::Repeat, CycleMode::Repeat)};
  muted[0].enabled = false;
  EXPECT_NEAR(evaluate(c, muted, 4.5f).x, 2.0f, 1e-5f);
}

TEST(CyclesModifier, RotationOffsetComposesTheRangesTurn) {
  const glm::quat q0 = glm::angleAxis(0.1f, glm::vec3(0, 1, 0)), q1 = glm::angleAxis(0.6f, glm::vec3(0, 1, 0));
  const Channel c(0, ChannelTarget::Rotation, Interpolation::Linear, {0.0f, 1.0f},
                  {glm::vec4(q0.x, q0.y, q0.z, q0.w), glm::vec4(q1.x, q1.y, q1.z, q1.w)});
  const std::vector<ChannelModifier> stack = {cycles(CycleMode::RepeatWithOffset, CycleMode::RepeatWithOffset)};
  // About one axis: the angle keeps growing by 0.5 rad per cycle.
  const glm::vec4 v = evaluate(c, stack, 2.5f);
  EXPECT_SAME_ROTATION(glm::quat(v.w, v.x, v.y, v.z), glm::angleAxis(0.35f + 1.0f, glm::vec3(0, 1, 0)), 1e-5f);
}

TEST(WaveModifier, TheSeedsTravellingWave) {
  const Channel c(0, ChannelTarget::Euler, Interpolation::Linear, {0.0f}, {glm::vec4(0.1f, 0.0f, 0.0f, 0.0f)});
  ChannelModifier w;
  w.kind = ChannelModifierKind::Wave;
  w.components = 0x1;  // x only
  w.wave.amplitude = 0.3f;
  w.wave.omega = 2.0f;
  w.wave.k = glm::vec3(0.0f, 1.5f, 0.0f);
  w.wave.phi = 0.25f;
  const std::vector<ChannelModifier> stack = {w};
  for (float y : {0.0f, 1.0f, 2.0f})
    for (float t : {0.0f, 0.3f, 1.7f}) {
      const glm::vec4 v = evaluate(c, stack, t, 0, glm::vec3(4.0f, y, -2.0f));
      EXPECT_NEAR(v.x, 0.1f + 0.3f * std::cos(2.0f * t - 1.5f * y + 0.25f), 1e-5f);
      EXPECT_EQ(v.y, 0.0f);
    }
  // A joint 1 m higher lags by k / omega = 0.75 s.
  EXPECT_NEAR(evaluate(c, stack, 1.75f, 0, glm::vec3(0, 1, 0)).x, evaluate(c, stack, 1.0f, 0, glm::vec3(0)).x, 1e-5f);
}

TEST(ChannelModifiers, StackAddsAndBakeMatchesEvaluation) {
  const Channel c = rampKeys();
  ChannelModifier w;
  w.kind = ChannelModifierKind::Wave;
  w.wave.amplitude = 0.2f;
  const std::vector<ChannelModifier> n = {noise(0.3f, 0.5f, 2, 4)}, wave = {w};
  const std::vector<ChannelModifier> both = {cycles(CycleMode::Repeat, CycleMode::Repeat), noise(0.3f, 0.5f, 2, 4), w};
  for (float t : {1.2f, 2.9f}) {  // inside the range cycles do nothing; the additions sum
    const glm::vec4 sum = evaluate(c, n, t) + evaluate(c, wave, t) - sampleChannel(c, t);
    EXPECT_VEC3_NEAR(glm::vec3(evaluate(c, both, t)), glm::vec3(sum), 1e-5f);
  }
  BakeChannelModifiersJob bake;
  const Channel modified = withStack(c, both);
  bake.source.channel = &modified;
  bake.start = 0.0f;
  bake.end = 5.0f;
  bake.framesPerSecond = 10.0;
  std::string error;
  ASSERT_TRUE(bake.run(error)) << error;
  ASSERT_EQ(bake.output.keyCount(), 51);
  EXPECT_EQ(bake.output.target, ChannelTarget::Translation);
  for (int k = 0; k < bake.output.keyCount(); ++k) {
    EXPECT_NEAR(bake.output.times[k], 0.1f * k, 1e-5f);
    // Sampling the baked keys at a frame gives the modified curve there.
    EXPECT_VEC3_NEAR(glm::vec3(sampleChannel(bake.output, bake.output.times[k])),
                     glm::vec3(evaluate(c, both, bake.output.times[k])), 1e-6f);
  }
  bake.end = -1.0f;
  EXPECT_FALSE(bake.run(error));
}

}  // namespace
}  // namespace kinema
