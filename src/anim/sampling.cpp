#include "anim/sampling.h"

#include <algorithm>
#include <cmath>

#include "anim/bezier_handles.h"
#include "anim/easing.h"
#include "anim/hermite.h"
#include "anim/quaternion_curves.h"
#include "anim/tcb_spline.h"

namespace kinema {

namespace {

// Normalises only quaternions measurably off unit length: keys from our loaders are unit
// already, and skipping the square root and division halves the cost of playback.
inline glm::quat unit(const glm::quat& q) {
  const float len2 = q.x * q.x + q.y * q.y + q.z * q.z + q.w * q.w;
  return std::abs(len2 - 1.0f) < 1e-6f ? q : safeNormalize(q);
}
inline glm::quat toQuat(const glm::vec4& v) { return unit(glm::quat(v.w, v.x, v.y, v.z)); }
glm::vec4 toVec(const glm::quat& q) { return {q.x, q.y, q.z, q.w}; }

glm::vec4 inTangentOf(const Channel& ch, int k) { return ch.keys.empty() ? glm::vec4(0.0f) : ch.keys[k].inTangent; }

glm::vec4 rotationSegment(const Channel& ch, const KeySettings& s, int lo, float time, float u) {
  const int hi = lo + 1;
  const glm::quat a = toQuat(ch.values[lo]), b = toQuat(ch.values[hi]);
  switch (s.interpolation) {
    case Interpolation::Nlerp: return toVec(nlerpShortest(a, b, u));
    case Interpolation::Squad: {
      const int n = ch.keyCount();
      const bool prev = lo > 0, next = hi + 1 < n;
      return toVec(squad(prev ? toQuat(ch.values[lo - 1]) : a, a, b, next ? toQuat(ch.values[hi + 1]) : b,
                         prev ? ch.times[lo - 1] : ch.times[lo], ch.times[lo], ch.times[hi],
                         next ? ch.times[hi + 1] : ch.times[hi], prev, next, u));
    }
    case Interpolation::Hermite:
      return toVec(gltfCubicRotation(ch.values[lo], s.outTangent, ch.values[hi], inTangentOf(ch, hi),
                                     ch.times[hi] - ch.times[lo], u));
    case Interpolation::Ease: return toVec(safeNormalize(slerpShortest(a, b, ease(s.easing, s.easingMode, u))));
    case Interpolation::Bezier: {
      // Blender's quaternion F-curves: each stored component a Bezier curve, then normalised.
      const glm::vec4 v = evaluateBezierSegment(ch, lo, time);
      return toVec(safeNormalize(glm::quat(v.w, v.x, v.y, v.z)));
    }
    default: return toVec(safeNormalize(slerpShortest(a, b, u)));
  }
}

glm::vec4 vectorSegment(const Channel& ch, const KeySettings& s, int lo, float time, float u) {
  const int hi = lo + 1;
  const glm::vec4 &a = ch.values[lo], &b = ch.values[hi];
  const float dt = ch.times[hi] - ch.times[lo];
  switch (s.interpolation) {
    case Interpolation::Hermite: return hermite(a, s.outTangent, b, inTangentOf(ch, hi), dt, u);
    case Interpolation::CatmullRom:
    case Interpolation::TCB: {
      const bool tcb = s.interpolation == Interpolation::TCB;
      glm::vec4 in0, out0, in1, out1;
      tcbTangents(ch, lo, tcb, in0, out0);
      tcbTangents(ch, hi, tcb, in1, out1);
      return hermite(a, out0, b, in1, dt, u);
    }
    case Interpolation::Bezier: return evaluateBezierSegment(ch, lo, time);
    case Interpolation::Ease: return glm::mix(a, b, ease(s.easing, s.easingMode, u));
    default: return glm::mix(a, b, u);
  }
}

void apply(const Channel& ch, const glm::vec4& v, Transform& t) {
  switch (ch.target) {
    case ChannelTarget::Translation: t.translation = glm::vec3(v); break;
    case ChannelTarget::Scale: t.scale = glm::vec3(v); break;
    case ChannelTarget::Rotation: t.rotation = glm::quat(v.w, v.x, v.y, v.z); break;  // unit already
    case ChannelTarget::Euler: t.rotation = eulerToQuat(glm::vec3(v), ch.eulerOrder); break;
    case ChannelTarget::Scalar: break;
  }
}

void sampleInto(const Clip& clip, float time, Pose& pose, int* cursors) {
  for (size_t c = 0; c < clip.channels.size(); ++c) {
    const Channel& ch = clip.channels[c];
    if (ch.target == ChannelTarget::Scalar || ch.joint < 0 || ch.joint >= pose.size() || ch.times.empty()) continue;
    apply(ch, sampleChannel(ch, time, cursors ? &cursors[c] : nullptr), pose.local[ch.joint]);
  }
}

}  // namespace

int upperKey(const Channel& ch, float time, int* cursor) {
  const int n = ch.keyCount();
  if (cursor) {
    // Same segment as last time, or the next one (sequential playback).
    for (int c = std::max(0, std::min(*cursor, n)), step = 0; step < 2 && c <= n; ++c, ++step) {
      const bool afterPrev = c == 0 || ch.times[c - 1] <= time;
      const bool beforeNext = c == n || time < ch.times[c];
      if (afterPrev && beforeNext) {
        *cursor = c;
        return c;
      }
      if (!afterPrev) break;
    }
  }
  const int hi = static_cast<int>(std::upper_bound(ch.times.begin(), ch.times.end(), time) - ch.times.begin());
  if (cursor) *cursor = hi;
  return hi;
}

glm::vec4 sampleChannel(const Channel& ch, float time, int* cursor) {
  const int n = ch.keyCount();
  if (n == 0) return ch.target == ChannelTarget::Rotation ? glm::vec4(0, 0, 0, 1) : glm::vec4(0.0f);
  const int hi = upperKey(ch, time, cursor);
  const bool rotation = ch.target == ChannelTarget::Rotation;
  auto key = [&](int k) { return rotation ? toVec(toQuat(ch.values[k])) : ch.values[k]; };
  if (hi == 0) return key(0);
  if (hi == n) return key(n - 1);
  const int lo = hi - 1;
  if (ch.times[lo] == time) return key(lo);
  const Interpolation interpolation = ch.keys.empty() ? ch.interpolation : ch.keys[lo].interpolation;
  if (interpolation == Interpolation::Step) return key(lo);
  const float u = (time - ch.times[lo]) / (ch.times[hi] - ch.times[lo]);
  // Imported motion (no per-key settings) takes this path without copying settings.
  if (ch.keys.empty() && interpolation == Interpolation::Linear)
    return rotation ? toVec(unit(slerpShortest(toQuat(ch.values[lo]), toQuat(ch.values[hi]), u)))
                    : glm::mix(ch.values[lo], ch.values[hi], u);
  const KeySettings s = ch.settings(lo);
  return rotation ? rotationSegment(ch, s, lo, time, u) : vectorSegment(ch, s, lo, time, u);
}

void sampleClip(const Clip& clip, float time, Pose& pose) { sampleInto(clip, time, pose, nullptr); }

void sampleClip(const Clip& clip, float time, Pose& pose, SamplingCache& cache) {
  cache.cursors.resize(clip.channels.size(), 0);
  sampleInto(clip, time, pose, cache.cursors.data());
}

}  // namespace kinema
