#include "anim/channel_modifiers.h"

#include <algorithm>
#include <cmath>

#include "anim/sampling.h"
#include "core/forward_kinematics.h"
#include "core/math.h"
#include "core/pose.h"
#include "core/skeleton.h"
#include "core/random.h"

namespace kinema {

namespace {

// The gradient at lattice point i, uniform in [-1, 1].
double gradient(uint64_t lattice, int64_t i) {
  const uint64_t h = mixBits(lattice ^ mixBits(static_cast<uint64_t>(i) * 0x9E3779B97F4A7C15ull));
  return static_cast<double>(h >> 11) * (2.0 / 9007199254740992.0) - 1.0;
}

// Perlin's 1D gradient noise with the quintic fade, scaled to [-1, 1]:
// |(1 - s) g0 u + s g1 (u - 1)| <= (1 - s) u + s (1 - u) <= 1/2 for |g| <= 1.
double gradientNoise(uint64_t lattice, double x) {
  x = std::clamp(x, -4.5e15, 4.5e15);  // past 2^52 a double has no fraction left anyway
  const double cell = std::floor(x);
  const double u = x - cell;
  const int64_t i = static_cast<int64_t>(cell);
  const double s = u * u * u * (u * (6.0 * u - 15.0) + 10.0);
  return 2.0 * ((1.0 - s) * gradient(lattice, i) * u + s * gradient(lattice, i + 1) * (u - 1.0));
}

glm::quat rotationVector(const glm::vec3& v) {
  const float angle = glm::length(v);
  if (angle < 1e-12f) return glm::quat(1, 0, 0, 0);
  return glm::angleAxis(angle, v / angle);
}

glm::quat asQuat(const glm::vec4& v) { return glm::quat(v.w, v.x, v.y, v.z); }
glm::vec4 asVec(const glm::quat& q) { return glm::vec4(q.x, q.y, q.z, q.w); }

glm::quat power(const glm::quat& q, int n) {
  glm::quat r(1, 0, 0, 0);
  const glm::quat step = n >= 0 ? q : glm::inverse(q);
  for (int k = 0; k < std::abs(n); ++k) r = glm::normalize(step * r);
  return r;
}

}  // namespace

bool NoiseModifier::operator==(const NoiseModifier& o) const {
  return strength == o.strength && scale == o.scale && phase == o.phase && octaves == o.octaves &&
         roughness == o.roughness && seed == o.seed;
}
bool CyclesModifier::operator==(const CyclesModifier& o) const {
  return before == o.before && after == o.after && beforeCount == o.beforeCount && afterCount == o.afterCount;
}
bool WaveModifier::operator==(const WaveModifier& o) const {
  return amplitude == o.amplitude && omega == o.omega && k == o.k && phi == o.phi && position == o.position;
}
bool ChannelModifier::operator==(const ChannelModifier& o) const {
  return kind == o.kind && enabled == o.enabled && components == o.components && noise == o.noise &&
         cycles == o.cycles && wave == o.wave;
}

const char* toString(CycleMode mode) {
  switch (mode) {
    case CycleMode::Hold: return "hold";
    case CycleMode::Repeat: return "repeat";
    case CycleMode::RepeatWithOffset: return "repeat_offset";
    case CycleMode::Mirror: return "mirror";
  }
  return "";
}
bool fromString(const std::string& s, CycleMode& out) {
  for (CycleMode m : {CycleMode::Hold, CycleMode::Repeat, CycleMode::RepeatWithOffset, CycleMode::Mirror})
    if (s == toString(m)) return out = m, true;
  return false;
}
const char* toString(ChannelModifierKind kind) {
  switch (kind) {
    case ChannelModifierKind::Noise: return "noise";
    case ChannelModifierKind::Cycles: return "cycles";
    case ChannelModifierKind::Wave: return "wave";
  }
  return "";
}
bool fromString(const std::string& s, ChannelModifierKind& out) {
  for (ChannelModifierKind k : {ChannelModifierKind::Noise, ChannelModifierKind::Cycles, ChannelModifierKind::Wave})
    if (s == toString(k)) return out = k, true;
  return false;
}

std::string ChannelModifier::validate() const {
  if (components < 1 || components > 15) return "the components mask must be 1 to 15 (bits x, y, z, w)";
  switch (kind) {
    case ChannelModifierKind::Noise:
      if (!std::isfinite(noise.strength) || noise.strength < 0) return "noise strength must be a finite number >= 0";
      if (!std::isfinite(noise.scale) || !(noise.scale > 0)) return "noise scale must be a finite number > 0 (seconds)";
      if (!std::isfinite(noise.phase)) return "noise phase must be finite";
      if (noise.octaves < 1 || noise.octaves > 8) return "noise octaves must be 1 to 8";
      if (!(noise.roughness >= 0.0f && noise.roughness <= 1.0f)) return "noise roughness must be in [0, 1]";
      return "";
    case ChannelModifierKind::Cycles:
      if (cycles.beforeCount < 0 || cycles.afterCount < 0) return "cycle counts must be >= 0 (0: forever)";
      return "";
    case ChannelModifierKind::Wave:
      if (!std::isfinite(wave.amplitude) || !std::isfinite(wave.omega) || !std::isfinite(wave.phi) || !isFinite(wave.k))
        return "wave amplitude, omega, k and phi must be finite";
      if (!isFinite(wave.position))
        return "wave position (the joint's rest position) must be finite";
      return "";
  }
  return "unknown modifier kind";
}

uint64_t noiseLattice(uint32_t seed, int joint, int component) {
  return mixBits(mixBits(static_cast<uint64_t>(seed) + 0x51ED270B27ull) ^
                 (static_cast<uint64_t>(static_cast<uint32_t>(joint)) << 8) ^ static_cast<uint64_t>(component));
}

float fractalNoise(const NoiseModifier& noise, uint64_t lattice, float time) {
  const double x = static_cast<double>(time) / noise.scale + noise.phase;
  double sum = 0.0, amplitudes = 0.0, amplitude = 1.0, frequency = 1.0;
  for (int o = 0; o < noise.octaves; ++o) {
    sum += amplitude * gradientNoise(mixBits(lattice + 0x632BE59BD9B4E019ull * static_cast<uint64_t>(o + 1)), frequency * x);
    amplitudes += amplitude;
    amplitude *= noise.roughness;
    frequency *= 2.0;
  }
  return static_cast<float>(sum / amplitudes);
}

std::string validateModifierStack(const std::vector<ChannelModifier>& stack) {
  int cycles = 0;
  for (size_t i = 0; i < stack.size(); ++i) {
    const ChannelModifier& m = stack[i];
    if (std::string bad = m.validate(); !bad.empty()) return "modifier " + std::to_string(i + 1) + ": " + bad;
    if (m.kind == ChannelModifierKind::Cycles && ++cycles > 1)
      return "modifier " + std::to_string(i + 1) + ": a channel takes one Cycles modifier";
  }
  return "";
}

std::string ModifiedChannelJob::validate() const {
  if (!channel) return "no channel";
  if (channel->times.empty() || channel->values.size() != channel->times.size()) return "the channel has no keys";
  return validateModifierStack(channel->modifiers);
}

glm::vec4 ModifiedChannelJob::evaluate(float time) const {
  const Channel& c = *channel;
  const std::vector<ChannelModifier>& modifiers = c.modifiers;
  const int joint = c.joint;
  const bool rotation = c.target == ChannelTarget::Rotation;
  // Invalid modifiers (a bad edit, a clip not yet validated) are skipped rather than
  // evaluated into NaN.
  auto active = [](const ChannelModifier& m) { return m.enabled && m.validate().empty(); };
  const CyclesModifier* cycles = nullptr;
  for (const ChannelModifier& m : modifiers)
    if (active(m) && m.kind == ChannelModifierKind::Cycles) {
      cycles = &m.cycles;
      break;
    }
  // The keyed curve, with time remapped into the keyed range by Cycles.
  glm::vec4 value;
  const float t0 = c.startTime(), t1 = c.endTime(), period = t1 - t0;
  const bool after = time > t1, before = time < t0;
  const CycleMode mode = !cycles ? CycleMode::Hold : after ? cycles->after : before ? cycles->before : CycleMode::Hold;
  if (mode == CycleMode::Hold || period <= 0.0f) {
    value = sampleChannel(c, time);
  } else {
    const int limit = after ? cycles->afterCount : cycles->beforeCount;
    const double d = after ? double(time) - t1 : double(t0) - time;
    double n = std::min(std::ceil(d / period), 1e15);  // beyond that float time has no resolution
    double local;
    if (limit > 0 && n > limit) {
      n = limit;
      local = after ? t1 : t0;  // the value holds at the last cycle's end
    } else {
      local = after ? double(time) - n * period : double(time) + n * period;
    }
    if (mode == CycleMode::Mirror && static_cast<long long>(n) % 2 == 1) local = double(t0) + t1 - local;
    value = sampleChannel(c, static_cast<float>(local));
    if (mode == CycleMode::RepeatWithOffset) {
      const int cyclesAway = static_cast<int>(std::min(n, 1e6)) * (after ? 1 : -1);
      if (rotation) {
        const glm::quat delta = glm::normalize(asQuat(c.values.back()) * glm::inverse(asQuat(c.values.front())));
        value = asVec(glm::normalize(power(delta, cyclesAway) * asQuat(value)));
      } else {
        value += static_cast<float>(cyclesAway) * (c.values.back() - c.values.front());
      }
    }
  }
  // The additive modifiers, in stack order.
  const int size = rotation ? 3 : c.valueSize();
  glm::vec4 added(0.0f);
  for (const ChannelModifier& m : modifiers) {
    if (m.kind == ChannelModifierKind::Cycles || !active(m)) continue;
    for (int k = 0; k < size; ++k) {
      if (!(m.components & (1u << k))) continue;
      if (m.kind == ChannelModifierKind::Noise)
        added[k] += m.noise.strength * fractalNoise(m.noise, noiseLattice(m.noise.seed, joint, k), time);
      else
        added[k] += m.wave.amplitude *
                    static_cast<float>(std::cos(double(m.wave.omega) * time - double(glm::dot(m.wave.k, m.wave.position)) + m.wave.phi));
    }
  }
  if (rotation) return asVec(glm::normalize(asQuat(value) * rotationVector(glm::vec3(added))));
  return value + added;
}

std::string BakeChannelModifiersJob::validate() const {
  if (std::string bad = source.validate(); !bad.empty()) return bad;
  if (!std::isfinite(start) || !std::isfinite(end) || end < start) return "the bake range must be finite with start <= end";
  if (!(framesPerSecond > 0.0) || !std::isfinite(framesPerSecond)) return "the bake rate must be > 0 frames per second";
  if ((double(end) - start) * framesPerSecond + 2 > maxKeys)
    return "the bake would make more than " + std::to_string(maxKeys) + " keys";
  return "";
}

bool BakeChannelModifiersJob::run(std::string& error) {
  output = Channel();
  if (error = validate(); !error.empty()) return false;
  const Channel& c = *source.channel;
  output.joint = c.joint;
  output.target = c.target;
  output.interpolation = Interpolation::Linear;
  output.eulerOrder = c.eulerOrder;
  output.property = c.property;
  const long long frames = static_cast<long long>(std::floor((double(end) - start) * framesPerSecond + 1e-6));
  for (long long f = 0; f <= frames; ++f) {
    const float t = static_cast<float>(start + f / framesPerSecond);
    if (!output.times.empty() && !(t > output.times.back())) continue;
    output.times.push_back(t);
  }
  if (output.times.back() < end - kKeyTimeTolerance) output.times.push_back(end);
  for (float t : output.times) output.values.push_back(source.evaluate(t));
  return true;
}

glm::vec4 sampleModifiedChannel(const Channel& channel, float time) {
  if (channel.modifiers.empty() || channel.times.empty()) return sampleChannel(channel, time);
  ModifiedChannelJob job;
  job.channel = &channel;
  return job.evaluate(time);
}

void resolveWavePositions(Clip& clip, const Skeleton& skeleton) {
  std::vector<glm::mat4> world;
  for (Channel& ch : clip.channels)
    for (ChannelModifier& m : ch.modifiers) {
      if (m.kind != ChannelModifierKind::Wave || ch.joint < 0 || ch.joint >= skeleton.size()) continue;
      if (world.empty()) world = computeWorld(skeleton, Pose::rest(skeleton));
      m.wave.position = glm::vec3(world[ch.joint][3]);
    }
}

bool hasActiveModifiers(const Channel& channel) {
  for (const ChannelModifier& m : channel.modifiers)
    if (m.enabled) return true;
  return false;
}

std::string bakeClipModifiers(const Clip& clip, double framesPerSecond, Clip& out) {
  out = clip;
  for (size_t c = 0; c < out.channels.size(); ++c) {
    Channel& ch = out.channels[c];
    if (!hasActiveModifiers(ch)) {
      ch.modifiers.clear();
      continue;
    }
    BakeChannelModifiersJob bake;
    bake.source.channel = &clip.channels[c];
    bake.start = 0.0f;
    bake.end = clip.duration();
    bake.framesPerSecond = framesPerSecond;
    std::string error;
    if (!bake.run(error)) return "channel " + std::to_string(c) + ": " + error;
    ch = std::move(bake.output);
  }
  return "";
}

bool hasChannelModifiers(const Clip& clip) {
  for (const Channel& ch : clip.channels)
    if (!ch.modifiers.empty()) return true;
  return false;
}

}  // namespace kinema
