// Channel modifiers on a clip: sampleClip and the playback fast path apply each channel's
// stack, leave unmodified channels alone, and keep them on the grids; Wave's x resolved
// from the skeleton; Clip::validate checks the stacks.
#include <gtest/gtest.h>

#include <cmath>

#include "anim/channel_modifiers.h"
#include "anim/playback_sampling_job.h"
#include "anim/sampling.h"
#include "core/skeleton.h"
#include "test_support.h"

namespace kinema {
namespace KINEMA_UNITY_ID {

ChannelModifier noise(float strength, float scale, int octaves, uint32_t seed) {
  ChannelModifier m;
  m.kind = ChannelModifierKind::Noise;
  m.noise.strength = strength;
  m.noise.scale = scale;
  m.noise.octaves = octaves;
  m.noise.seed = seed;
  return m;
}

// Six joints; translation channels on joints 0..4 share one key grid (a playback grid),
// joint 5 has a rotation channel. Joint 2's translation carries noise.
Clip gridClip() {
  Clip clip;
  const std::vector<float> times = {0.0f, 0.5f, 1.0f, 2.0f};
  for (int j = 0; j < 5; ++j) {
    std::vector<glm::vec4> values;
    for (float t : times) values.emplace_back(0.1f * j + t, -t, 0.5f * t * t, 0.0f);
    clip.channels.emplace_back(j, ChannelTarget::Translation, Interpolation::Linear, times, values);
  }
  const glm::quat a = glm::angleAxis(0.2f, glm::vec3(0, 1, 0)), b = glm::angleAxis(1.1f, glm::vec3(0, 1, 0));
  clip.channels.emplace_back(5, ChannelTarget::Rotation, Interpolation::Linear, std::vector<float>{0.0f, 2.0f},
                             std::vector<glm::vec4>{{a.x, a.y, a.z, a.w}, {b.x, b.y, b.z, b.w}});
  clip.channels[2].modifiers = {noise(0.25f, 0.4f, 3, 11)};
  return clip;
}

TEST(ChannelModifierSampling, SampleClipAddsTheNoiseToTheModifiedChannelOnly) {
  const Clip clip = gridClip();
  int moved = 0;
  for (int i = 0; i <= 80; ++i) {
    const float t = 0.025f * i;
    Pose pose{std::vector<Transform>(6)};
    sampleClip(clip, t, pose);
    for (int j = 0; j < 5; ++j) {
      const glm::vec3 keyed(sampleChannel(clip.channels[j], t));
      if (j != 2) {
        EXPECT_EQ(pose.local[j].translation, keyed) << j;  // untouched, bit for bit
        continue;
      }
      // The keyed curve plus strength x the fractal noise of (seed, joint 2, component k).
      for (int k = 0; k < 3; ++k) {
        const float expected = keyed[k] + 0.25f * fractalNoise(clip.channels[2].modifiers[0].noise, noiseLattice(11, 2, k), t);
        EXPECT_NEAR(pose.local[j].translation[k], expected, 1e-6f) << t;
      }
      moved += glm::length(pose.local[j].translation - keyed) > 1e-3f;
    }
  }
  EXPECT_GT(moved, 60);  // the noise is really there
}

TEST(ChannelModifierSampling, PlaybackPathMatchesSampleClipAndKeepsTheGrid) {
  Clip clip = gridClip();
  ChannelModifier cycles;
  cycles.kind = ChannelModifierKind::Cycles;
  cycles.cycles.after = CycleMode::RepeatWithOffset;
  ChannelModifier wave;
  wave.kind = ChannelModifierKind::Wave;
  wave.wave.amplitude = 0.3f;
  wave.wave.k = glm::vec3(0, 2, 0);
  wave.wave.position = glm::vec3(0, 0.7f, 0);
  // The rotation channel ends at 1 s: cycles repeat it over the clip's last second.
  clip.channels[5].times = {0.0f, 1.0f};
  clip.channels[5].modifiers = {cycles, wave};
  const PlaybackClip playback = PlaybackClip::build(clip, 6);
  // The four unmodified translations still share one grid; the two modified channels are
  // sampled one by one.
  ASSERT_EQ(playback.grids.size(), 1u);
  EXPECT_EQ(playback.grids[0].translationBlocks, 1);
  ASSERT_EQ(playback.channels.size(), 2u);
  EXPECT_EQ(playback.channels[0].modifiers.size(), 1u);
  EXPECT_EQ(playback.channels[1].modifiers.size(), 2u);
  PlaybackContext context;
  for (int i = -10; i <= 100; ++i) {
    const float t = 0.025f * i;
    Pose a{std::vector<Transform>(6)}, b{std::vector<Transform>(6)};
    sampleClip(clip, t, a);
    ASSERT_TRUE(samplePlayback(playback, t, b, context));
    for (int j = 0; j < 6; ++j) {
      EXPECT_VEC3_NEAR(a.local[j].translation, b.local[j].translation, 1e-6f);
      EXPECT_SAME_ROTATION(a.local[j].rotation, b.local[j].rotation, 1e-6f);
    }
  }
  // After the keyed second the offset cycle keeps turning (0.9 rad per cycle about y), then
  // the wave turns about x, y and z by 0.3 cos(2 pi t - 1.4) each.
  Pose pose{std::vector<Transform>(6)};
  sampleClip(clip, 1.5f, pose);
  const float w = 0.3f * std::cos(6.283185307f * 1.5f - 1.4f);
  const glm::vec3 v(w);
  const glm::quat expected =
      glm::angleAxis(0.2f + 0.9f + 0.45f, glm::vec3(0, 1, 0)) * glm::angleAxis(glm::length(v), glm::normalize(v));
  EXPECT_SAME_ROTATION(pose.local[5].rotation, expected, 1e-5f);
}

TEST(ChannelModifierSampling, ClipsWithoutModifiersBuildTheSamePlaybackClip) {
  Clip clip = gridClip();
  clip.channels[2].modifiers.clear();
  const PlaybackClip playback = PlaybackClip::build(clip, 6);
  ASSERT_EQ(playback.grids.size(), 1u);
  EXPECT_EQ(playback.grids[0].translationBlocks, 2);  // all five translations on the grid
  EXPECT_EQ(playback.channels.size(), 1u);             // the lone rotation (too few for a grid)
  EXPECT_FALSE(hasChannelModifiers(clip));
}

TEST(ChannelModifierSampling, MutedAndInvalidModifiersChangeNothing) {
  Clip clip = gridClip();
  clip.channels[2].modifiers[0].enabled = false;
  Pose pose{std::vector<Transform>(6)};
  sampleClip(clip, 0.7f, pose);
  EXPECT_EQ(pose.local[2].translation, glm::vec3(sampleChannel(clip.channels[2], 0.7f)));
  clip.channels[2].modifiers[0].enabled = true;
  clip.channels[2].modifiers[0].noise.scale = 0.0f;  // invalid: would divide by zero
  sampleClip(clip, 0.7f, pose);
  EXPECT_EQ(pose.local[2].translation, glm::vec3(sampleChannel(clip.channels[2], 0.7f)));
  EXPECT_FALSE(hasActiveModifiers(Channel()));
}

TEST(ChannelModifierSampling, WavePositionsAreTheJointsRestPositionsInModelSpace) {
  Skeleton s;
  // Root at (0, 1, 0) turned 90 degrees about z; the child 0.3 m along the root's x axis,
  // which the turn points up: model position (0, 1.3, 0).
  Transform root = Transform::fromTranslation({0, 1, 0});
  root.rotation = glm::angleAxis(1.5707963f, glm::vec3(0, 0, 1));
  s.addJoint("root", -1, root);
  s.addJoint("tip", 0, Transform::fromTranslation({0.3f, 0, 0}));
  Clip clip;
  clip.channels.emplace_back(1, ChannelTarget::Euler, Interpolation::Linear, std::vector<float>{0.0f},
                             std::vector<glm::vec4>{glm::vec4(0.0f)});
  clip.channels.emplace_back(0, ChannelTarget::Translation, Interpolation::Linear, std::vector<float>{0.0f},
                             std::vector<glm::vec4>{glm::vec4(0.0f)});
  ChannelModifier wave;
  wave.kind = ChannelModifierKind::Wave;
  clip.channels[0].modifiers = {wave, noise(0.1f, 1.0f, 1, 0)};
  clip.channels[1].modifiers = {wave};
  resolveWavePositions(clip, s);
  EXPECT_VEC3_NEAR(clip.channels[0].modifiers[0].wave.position, glm::vec3(0, 1.3f, 0), 1e-6f);
  EXPECT_VEC3_NEAR(clip.channels[1].modifiers[0].wave.position, glm::vec3(0, 1, 0), 1e-6f);
  EXPECT_EQ(clip.channels[0].modifiers[1].wave.position, glm::vec3(0.0f));  // noise: untouched
  EXPECT_EQ(clip.validate(s), "");
}

TEST(ChannelModifierSampling, ValidateNamesTheChannelAndTheModifier) {
  Skeleton s;
  for (int j = 0; j < 6; ++j) s.addJoint("j" + std::to_string(j), j - 1, Transform());
  Clip clip = gridClip();
  EXPECT_EQ(clip.validate(s), "");
  clip.channels[2].modifiers[0].noise.octaves = 9;
  EXPECT_EQ(clip.validate(s), "channel 2 modifier 1: noise octaves must be 1 to 8");
  ChannelModifier cycles;
  cycles.kind = ChannelModifierKind::Cycles;
  clip.channels[2].modifiers = {cycles, cycles};
  EXPECT_EQ(clip.validate(s), "channel 2 modifier 2: a channel takes one Cycles modifier");
}

TEST(ChannelModifierSampling, BakeClipModifiersKeepsPlainChannelsAndMatchesAtFrames) {
  Clip clip = gridClip();
  clip.channels[0].modifiers = {noise(0.2f, 1.0f, 1, 1)};
  clip.channels[0].modifiers[0].enabled = false;
  Clip baked;
  ASSERT_EQ(bakeClipModifiers(clip, 30.0, baked), "");
  ASSERT_EQ(baked.channels.size(), clip.channels.size());
  EXPECT_FALSE(hasChannelModifiers(baked));
  EXPECT_EQ(baked.channels[0].times, clip.channels[0].times);  // only muted: keys kept
  EXPECT_EQ(baked.channels[1].values, clip.channels[1].values);
  ASSERT_EQ(baked.channels[2].keyCount(), 61);  // 0 .. 2 s at 30 fps
  for (int f = 0; f <= 60; ++f) {
    const float t = f / 30.0f;
    Pose a{std::vector<Transform>(6)}, b{std::vector<Transform>(6)};
    sampleClip(clip, t, a);
    sampleClip(baked, t, b);
    EXPECT_VEC3_NEAR(a.local[2].translation, b.local[2].translation, 1e-6f);
  }
}

}  // namespace
}  // namespace kinema
