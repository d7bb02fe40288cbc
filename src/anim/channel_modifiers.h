#pragma once
// Evaluating and baking a channel's modifier stack (Channel::modifiers; the modifiers' data
// and meaning are in anim/channel_modifier.h). sampleClip and the playback path apply the
// stack through sampleModifiedChannel; sampleChannel stays the keyed curve alone.
#include <cstdint>
#include <string>
#include <vector>

#include "anim/clip.h"

namespace kinema {

struct Skeleton;

// Evaluates a channel with its modifier stack (channel->modifiers). Inputs are read only; no
// state between calls. The channel's joint mixes into the noise lattices, so joints sway
// apart; Wave reads x from the modifier (WaveModifier::position).
struct ModifiedChannelJob {
  const Channel* channel = nullptr;  // at least one key

  std::string validate() const;
  // The value at `time` (seconds, any finite time) in the channel's layout (sampleChannel's),
  // modifiers applied; rotations come back normalised.
  glm::vec4 evaluate(float time) const;
};

// The channel's value at `time` as a clip plays it: sampleChannel for a channel without
// modifiers, ModifiedChannelJob::evaluate otherwise (the stack need not be valid: invalid
// modifiers are skipped, so a bad edit never yields NaN).
glm::vec4 sampleModifiedChannel(const Channel& channel, float time);

// Sets x (WaveModifier::position) of every Wave modifier on the clip's joint channels to the
// joint's rest position in model space (the skeleton's rest pose through FK). Channels of
// joints outside the skeleton are left alone.
void resolveWavePositions(Clip& clip, const Skeleton& skeleton);

// True when any channel of the clip carries a modifier (enabled or not).
bool hasChannelModifiers(const Clip& clip);
// True when the channel has an enabled modifier: sampling it differs from its keys.
bool hasActiveModifiers(const Channel& channel);

// The raw fractal noise in [-1, 1] NoiseModifier describes (before `strength`).
float fractalNoise(const NoiseModifier& noise, uint64_t lattice, float time);
// The lattice a joint's component draws from (for fractalNoise).
uint64_t noiseLattice(uint32_t seed, int joint, int component);

// Bakes the stack into keys: one Linear key per frame from `start` to `end` (seconds; end
// included) at `framesPerSecond`, values from ModifiedChannelJob. The result has the
// channel's joint, target, Euler order and property, and no modifiers. Between frames the
// baked keys interpolate linearly (rotations: slerp), so they match the modified curve
// exactly at frame times and approximately in between.
struct BakeChannelModifiersJob {
  ModifiedChannelJob source;
  float start = 0.0f, end = 1.0f;       // finite, start <= end
  double framesPerSecond = 24.0;        // > 0
  int maxKeys = 1 << 20;

  Channel output;
  std::string validate() const;
  bool run(std::string& error);
};

// The clip as exporters write it (glTF; BVH samples sampleClip per frame anyway): each
// channel with an enabled modifier replaced by its bake at `framesPerSecond` over 0 ..
// clip.duration() (the range sampling and the CLI clamp time to), channels whose modifiers
// are all muted keep their keys and lose the stack, the rest are copied. Returns "" or what
// failed ("channel N: ..."), leaving `out` unspecified.
std::string bakeClipModifiers(const Clip& clip, double framesPerSecond, Clip& out);

}  // namespace kinema
