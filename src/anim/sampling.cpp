#include "anim/sampling.h"

#include <algorithm>
#include <cmath>

#include "anim/bezier_handles.h"
#include "anim/channel_modifiers.h"
#include "anim/easing.h"
#include "anim/hermite.h"
#include "anim/quaternion_curves.h"
#include "anim/tcb_spline.h"
#include "anim/unit_slerp.h"

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

// A Linear segment from key lo to lo + 1 at fraction u: a straight line, or for rotations
// the shortest-arc slerp of the (normalised) keys.
inline glm::vec4 linearSegment(const Channel& ch, bool rotation, int lo, float u) {
  const glm::vec4 &a = ch.values[lo], &b = ch.values[lo + 1];
  if (!rotation) return glm::mix(a, b, u);
  if (isUnitLength(a) && isUnitLength(b)) return slerpUnitKeys(a, b, u);
  return toVec(unit(slerpShortest(toQuat(a), toQuat(b), u)));
}

inline Interpolation segmentInterpolation(const Channel& ch, int lo) {
  return ch.keys.empty() ? ch.interpolation : ch.keys[lo].interpolation;
}

// True when hi is upperKey's answer for `time` (the first key after it).
inline bool isUpperKey(const Channel& ch, int hi, float time) {
  const int n = ch.keyCount();
  return hi >= 0 && hi <= n && (hi == 0 || ch.times[hi - 1] <= time) && (hi == n || time < ch.times[hi]);
}

// upperKey, trying `guess` (another channel's answer: clips mostly share one key grid)
// before a binary search.
int upperKeyWithGuess(const Channel& ch, float time, int* cursor, int guess) {
  if (cursor) {
    // Same segment as last time, or the next one (sequential playback).
    if (isUpperKey(ch, *cursor, time)) return *cursor;
    if (isUpperKey(ch, *cursor + 1, time)) return ++*cursor;
  }
  if (isUpperKey(ch, guess, time)) {
    if (cursor) *cursor = guess;
    return guess;
  }
  return upperKey(ch, time, cursor);
}

// The channel's value at `time`, given hi = upperKey(ch, time).
glm::vec4 sampleAt(const Channel& ch, float time, int hi) {
  const int n = ch.keyCount();
  if (n == 0) return ch.target == ChannelTarget::Rotation ? glm::vec4(0, 0, 0, 1) : glm::vec4(0.0f);
  const bool rotation = ch.target == ChannelTarget::Rotation;
  auto key = [&](int k) { return rotation ? toVec(toQuat(ch.values[k])) : ch.values[k]; };
  if (hi == 0) return key(0);
  if (hi == n) return key(n - 1);
  const int lo = hi - 1;
  if (ch.times[lo] == time) return key(lo);
  const Interpolation interpolation = segmentInterpolation(ch, lo);
  if (interpolation == Interpolation::Step) return key(lo);
  const float u = (time - ch.times[lo]) / (ch.times[hi] - ch.times[lo]);
  // Imported motion and plain keys take this path without copying settings.
  if (interpolation == Interpolation::Linear) return linearSegment(ch, rotation, lo, u);
  const KeySettings s = ch.settings(lo);
  return rotation ? rotationSegment(ch, s, lo, time, u) : vectorSegment(ch, s, lo, time, u);
}

// How many channels ahead random access prefetches keys: enough to cover a memory access
// while the channels in between are sampled.
constexpr size_t kPrefetchChannelsAhead = 4;

void sampleInto(const Clip& clip, float time, Pose& pose, int* cursors) {
  const unsigned joints = static_cast<unsigned>(pose.size());
  Transform* out = pose.local.data();
  const Channel* channels = clip.channels.data();
  const size_t count = clip.channels.size();
  int guess = -1;  // the previous channel's upper key
  for (size_t c = 0; c < count; ++c) {
    const Channel& ch = channels[c];
    const float* times = ch.times.data();
    const int n = ch.keyCount();
    if (ch.target == ChannelTarget::Scalar || static_cast<unsigned>(ch.joint) >= joints || n == 0) continue;
    if (!ch.modifiers.empty()) {  // procedural channels: the keyed curve, then the stack
      applyChannelValue(ch, sampleModifiedChannel(ch, time), out[ch.joint]);
      continue;
    }
    int* cursor = cursors ? cursors + c : nullptr;
    // Strictly inside the segment before key hi: playback's cursor, or at random times the
    // previous channel's answer, usually is. (On a key, sampleAt returns the key itself.)
    int hi = cursor ? *cursor : guess;
    bool inside = hi > 0 && hi < n && times[hi - 1] < time && time < times[hi];
    if (!inside) {
      hi = upperKeyWithGuess(ch, time, cursor, guess);
      inside = hi > 0 && hi < n && times[hi - 1] != time;
    }
    guess = hi;
    if (!cursors && c + kPrefetchChannelsAhead < count) {
      // Random access runs on cache misses: fetch the keys a few channels ahead now.
      const Channel& ahead = channels[c + kPrefetchChannelsAhead];
      if (hi > 0 && hi < ahead.keyCount()) {
        __builtin_prefetch(ahead.times.data() + hi - 1);
        __builtin_prefetch(ahead.values.data() + hi - 1);
        __builtin_prefetch(ahead.values.data() + hi);
      }
    }
    Transform& t = out[ch.joint];
    if (inside && segmentInterpolation(ch, hi - 1) == Interpolation::Linear) {
      // The common case (imported motion, plain keys): straight to the pose.
      const int lo = hi - 1;
      const float u = (time - times[lo]) / (times[hi] - times[lo]);
      const glm::vec4 &a = ch.values[lo], &b = ch.values[hi];
      switch (ch.target) {
        case ChannelTarget::Translation: t.translation = glm::mix(glm::vec3(a), glm::vec3(b), u); continue;
        case ChannelTarget::Scale: t.scale = glm::mix(glm::vec3(a), glm::vec3(b), u); continue;
        case ChannelTarget::Rotation: {
          const glm::vec4 q = isUnitLength(a) && isUnitLength(b) ? slerpUnitKeys(a, b, u) : linearSegment(ch, true, lo, u);
          t.rotation = glm::quat(q.w, q.x, q.y, q.z);
          continue;
        }
        default: break;
      }
    }
    applyChannelValue(ch, sampleAt(ch, time, hi), t);
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
  return sampleAt(ch, time, ch.times.empty() ? 0 : upperKey(ch, time, cursor));
}

glm::vec4 sampleChannelReference(const Channel& ch, float time) {
  const int n = ch.keyCount();
  if (n == 0) return ch.target == ChannelTarget::Rotation ? glm::vec4(0, 0, 0, 1) : glm::vec4(0.0f);
  const int hi = static_cast<int>(std::upper_bound(ch.times.begin(), ch.times.end(), time) - ch.times.begin());
  const bool rotation = ch.target == ChannelTarget::Rotation;
  auto key = [&](int k) { return rotation ? toVec(toQuat(ch.values[k])) : ch.values[k]; };
  if (hi == 0) return key(0);
  if (hi == n) return key(n - 1);
  const int lo = hi - 1;
  if (ch.times[lo] == time) return key(lo);
  const Interpolation interpolation = segmentInterpolation(ch, lo);
  if (interpolation == Interpolation::Step) return key(lo);
  const float u = (time - ch.times[lo]) / (ch.times[hi] - ch.times[lo]);
  const KeySettings s = ch.settings(lo);
  return rotation ? rotationSegment(ch, s, lo, time, u) : vectorSegment(ch, s, lo, time, u);
}

void sampleClip(const Clip& clip, float time, Pose& pose) { sampleInto(clip, time, pose, nullptr); }

void sampleClip(const Clip& clip, float time, Pose& pose, SamplingCache& cache) {
  cache.cursors.resize(clip.channels.size(), 0);
  sampleInto(clip, time, pose, cache.cursors.data());
}

}  // namespace kinema
