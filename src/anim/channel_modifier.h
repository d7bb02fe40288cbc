#pragma once
// The data of channel modifiers (a Channel's stack, anim/clip.h); their evaluation and baking
// are in anim/channel_modifiers.h.
#include <cstdint>
#include <string>
#include <vector>

#include <glm/vec3.hpp>

namespace kinema {

// Procedural modifiers on one animation channel, after Blender's F-curve modifiers (the
// seed's 16.6: waves and noise as functions of time). A stack is evaluated on top of the
// channel's keyed curve: Cycles modifiers change *which time of the keyed range* is sampled
// (and add the cycle offset), then Noise and Wave add their value in stack order.
// Values are in the channel's units (metres, scale factors, radians for Euler channels and
// for Rotation channels, where the added (x, y, z) is a rotation vector v applied in the
// joint's local frame after the keyed rotation: q * R(v), R(v) = |v| radians about v / |v|).
// Times in seconds. A stack holds at most one Cycles modifier (validateModifierStack).

// Fractal (fBm) 1D gradient noise per component: strength * sum_o r^o n(2^o (t / scale + phase))
// / sum_o r^o, with n the quintic-faded Perlin gradient noise scaled to [-1, 1]; so the added
// value never exceeds `strength` in magnitude. Each joint, component and seed draws its own
// lattice of gradients.
struct NoiseModifier {
  float strength = 1.0f;   // channel units, >= 0: the largest value it adds
  float scale = 1.0f;      // seconds per lattice cell of the first octave, > 0 (larger = slower)
  float phase = 0.0f;      // shift along the noise, in lattice cells (any finite number)
  int octaves = 1;         // 1 .. 8: each adds detail at twice the frequency
  float roughness = 0.5f;  // amplitude ratio between octaves, in [0, 1]
  uint32_t seed = 0;
  bool operator==(const NoiseModifier& o) const;
};

// Blender's Cycles modes before the first key and after the last.
enum class CycleMode { Hold, Repeat, RepeatWithOffset, Mirror };
const char* toString(CycleMode mode);
bool fromString(const std::string& s, CycleMode& out);

// Repeats the keyed range [first key, last key] before and after it. RepeatWithOffset
// shifts each repetition by the range's change (last value - first value; for rotations the
// rotation from the first key to the last), so a walk cycle keeps walking. A count of 0
// repeats forever; after `count` cycles the value holds.
struct CyclesModifier {
  CycleMode before = CycleMode::Repeat, after = CycleMode::Repeat;
  int beforeCount = 0, afterCount = 0;  // >= 0
  bool operator==(const CyclesModifier& o) const;
};

// The seed's travelling wave A cos(omega t - k . x + phi), x = the joint's rest position in
// model space (metres): joints along k swing one after another (a plant swaying in the wind).
// x is resolved when the wave is attached (resolveWavePositions, the .kinema reader when the
// file gives none, the editor's Add Modifier) and stored here, so a clip samples without its
// skeleton (sampleClip's contract); it is saved with the wave. Changing the rest pose later
// keeps the stored x until resolveWavePositions runs again.
struct WaveModifier {
  float amplitude = 0.1f;         // channel units
  float omega = 6.283185307f;     // angular frequency, radians per second
  glm::vec3 k{0.0f};              // wave vector, radians per metre
  float phi = 0.0f;               // phase, radians
  glm::vec3 position{0.0f};       // x: the joint's rest position, model space, metres
  bool operator==(const WaveModifier& o) const;
};

enum class ChannelModifierKind { Noise, Cycles, Wave };
const char* toString(ChannelModifierKind kind);
bool fromString(const std::string& s, ChannelModifierKind& out);

struct ChannelModifier {
  ChannelModifierKind kind = ChannelModifierKind::Noise;
  bool enabled = true;  // a muted modifier stays in the stack and changes nothing
  // Which of the channel's components (bit 0 = x, 1 = y, 2 = z, 3 = w) Noise and Wave change;
  // rotation channels read bits 0..2 as the axes of the added rotation vector.
  uint32_t components = 0x7;
  NoiseModifier noise;
  CyclesModifier cycles;
  WaveModifier wave;
  bool operator==(const ChannelModifier& o) const;
  bool operator!=(const ChannelModifier& o) const { return !(*this == o); }
  std::string validate() const;  // finite parameters in their ranges, components in 1..15
};

// Empty when every modifier is valid and at most one is a Cycles modifier; otherwise what is
// wrong ("modifier N: ...", N from 1).
std::string validateModifierStack(const std::vector<ChannelModifier>& stack);

}  // namespace kinema
