#include "anim/playback_sampling_job.h"

#include <algorithm>
#include <cmath>
#include <cstddef>

#include "anim/channel_modifiers.h"
#include "anim/sampling.h"
#include "anim/unit_slerp.h"

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

namespace kinema {

namespace {

// Rotations are written as four floats x, y, z, w (glm's default storage), vectors as three.
static_assert(sizeof(glm::quat) == 16 && sizeof(glm::vec3) == 12, "glm types are plain floats");

// True when hi is the first key after `time` (0: before the first key, n: at or after the last).
inline bool isUpperKey(const float* times, int n, int hi, float time) {
  return hi >= 0 && hi <= n && (hi == 0 || times[hi - 1] <= time) && (hi == n || time < times[hi]);
}

// The first key after `time`: the cursor's segment or the next one (playback), else a
// binary search.
int upperKeyOf(const std::vector<float>& times, float time, int& cursor) {
  const int n = static_cast<int>(times.size());
  const float* t = times.data();
  if (isUpperKey(t, n, cursor, time)) return cursor;
  if (isUpperKey(t, n, cursor + 1, time)) return ++cursor;
  cursor = static_cast<int>(std::upper_bound(times.begin(), times.end(), time) - times.begin());
  return cursor;
}

// slerpWeight's coefficients for one u, the same for every lane: u2 / (n (2n+1)) - n / (2n+1).
struct SeriesCoefficients {
  float c[6];
  float u;
};
SeriesCoefficients seriesCoefficients(float u) {
  const float u2 = u * u;
  return {{u2 / 78.0f - 6.0f / 13.0f, u2 / 55.0f - 5.0f / 11.0f, u2 / 36.0f - 4.0f / 9.0f, u2 / 21.0f - 3.0f / 7.0f,
           u2 / 10.0f - 2.0f / 5.0f, u2 / 3.0f - 1.0f / 3.0f},
          u};
}

#if defined(__SSE2__)

struct SeriesVectors {
  __m128 c[6];
  __m128 u;
  explicit SeriesVectors(const SeriesCoefficients& s) : u(_mm_set1_ps(s.u)) {
    for (int i = 0; i < 6; ++i) c[i] = _mm_set1_ps(s.c[i]);
  }
};

// slerpWeight on four lanes, operation for operation (same rounding).
inline __m128 seriesWeight(const SeriesVectors& s, __m128 xm1) {
  const __m128 one = _mm_set1_ps(1.0f);
  __m128 acc = _mm_add_ps(one, _mm_mul_ps(s.c[0], xm1));
  for (int i = 1; i < 6; ++i) acc = _mm_add_ps(one, _mm_mul_ps(_mm_mul_ps(s.c[i], xm1), acc));
  return _mm_mul_ps(s.u, acc);
}

inline void store3(glm::vec3& v, __m128 xyz_) {
  float* p = &v.x;
  _mm_storel_pi(reinterpret_cast<__m64*>(p), xyz_);
  _mm_store_ss(p + 2, _mm_movehl_ps(xyz_, xyz_));
}

inline __m128 select(__m128 mask, __m128 ifTrue, __m128 ifFalse) {
  return _mm_or_ps(_mm_and_ps(mask, ifTrue), _mm_andnot_ps(mask, ifFalse));
}

// Rows longer than this (floats; 64 KiB) are read with software prefetches kPrefetchFloatsAhead
// floats ahead on each of the two rows: a jump to a random time in a clip too large for the
// caches (10,000 joints: 280 KiB a row) then keeps many cache-line fetches in flight, where
// the hardware prefetcher, which restarts at every 4 KiB page, keeps few.
constexpr int kPrefetchRowFloats = 16384;
constexpr int kPrefetchFloatsAhead = 512;  // 2 KiB

// One grid at fraction u between rows lo and lo + 1 (Interpolate), or row lo itself.
template <bool Interpolate, bool Prefetch>
void sampleGrid(const PlaybackGrid& g, int lo, float u, Transform* out) {
  const float* a = g.rows.data() + static_cast<size_t>(lo) * g.rowFloats;
  const float* b = a + g.rowFloats;
  // The prefetches stop short of the rows' end (they never fault, but need not run past).
  const float* prefetchEnd = a + (g.rowFloats > kPrefetchFloatsAhead ? g.rowFloats - kPrefetchFloatsAhead : 0);
  auto prefetch = [&]() {
    if (!Prefetch || a >= prefetchEnd) return;
    _mm_prefetch(reinterpret_cast<const char*>(a + kPrefetchFloatsAhead), _MM_HINT_T0);
    if (Interpolate) _mm_prefetch(reinterpret_cast<const char*>(b + kPrefetchFloatsAhead), _MM_HINT_T0);
  };
  const int* joint = g.joints.data();
  const float* linear = g.linear.data();
  const uint8_t* hasStep = g.blockHasStep.data();
  const __m128 one = _mm_set1_ps(1.0f);
  const __m128 U = _mm_set1_ps(u);
  const int vectorBlocks = g.translationBlocks + g.scaleBlocks;
  for (int block = 0; block < vectorBlocks; ++block, a += 12, b += 12, joint += 4, linear += 4) {
    prefetch();
    __m128 x = _mm_loadu_ps(a), y = _mm_loadu_ps(a + 4), z = _mm_loadu_ps(a + 8), w = _mm_setzero_ps();
    if (Interpolate) {
      // glm::mix: a (1 - u) + b u; Step lanes take u = 0, which gives a exactly.
      const __m128 ul = hasStep[block] ? _mm_mul_ps(U, _mm_loadu_ps(linear)) : U;
      const __m128 ol = _mm_sub_ps(one, ul);
      x = _mm_add_ps(_mm_mul_ps(x, ol), _mm_mul_ps(_mm_loadu_ps(b), ul));
      y = _mm_add_ps(_mm_mul_ps(y, ol), _mm_mul_ps(_mm_loadu_ps(b + 4), ul));
      z = _mm_add_ps(_mm_mul_ps(z, ol), _mm_mul_ps(_mm_loadu_ps(b + 8), ul));
    }
    _MM_TRANSPOSE4_PS(x, y, z, w);
    if (block < g.translationBlocks) {
      store3(out[joint[0]].translation, x);
      store3(out[joint[1]].translation, y);
      store3(out[joint[2]].translation, z);
      store3(out[joint[3]].translation, w);
    } else {
      store3(out[joint[0]].scale, x);
      store3(out[joint[1]].scale, y);
      store3(out[joint[2]].scale, z);
      store3(out[joint[3]].scale, w);
    }
  }
  const SeriesVectors w0(seriesCoefficients(1.0f - u)), w1(seriesCoefficients(u));
  const __m128 signBit = _mm_set1_ps(-0.0f), minCos = _mm_set1_ps(kSlerpSeriesMinCos);
  const __m128 half = _mm_set1_ps(0.5f), threeHalves = _mm_set1_ps(1.5f);
  for (int block = vectorBlocks; block < g.blockCount(); ++block, a += 16, b += 16, joint += 4, linear += 4) {
    prefetch();
    const __m128 ax = _mm_loadu_ps(a), ay = _mm_loadu_ps(a + 4), az = _mm_loadu_ps(a + 8), aw = _mm_loadu_ps(a + 12);
    __m128 x = ax, y = ay, z = az, w = aw;
    if (Interpolate) {
      // slerpUnitKeys on four lanes: the shorter arc (b or -b), the series weights, one
      // Newton step to unit length.
      __m128 bx = _mm_loadu_ps(b), by = _mm_loadu_ps(b + 4), bz = _mm_loadu_ps(b + 8), bw = _mm_loadu_ps(b + 12);
      __m128 d = _mm_add_ps(_mm_add_ps(_mm_mul_ps(ax, bx), _mm_mul_ps(ay, by)),
                            _mm_add_ps(_mm_mul_ps(az, bz), _mm_mul_ps(aw, bw)));
      const __m128 sign = _mm_and_ps(d, signBit);
      d = _mm_xor_ps(d, sign);
      bx = _mm_xor_ps(bx, sign), by = _mm_xor_ps(by, sign), bz = _mm_xor_ps(bz, sign), bw = _mm_xor_ps(bw, sign);
      const int wide = _mm_movemask_ps(_mm_cmpnge_ps(d, minCos));  // keys over 74 degrees apart (or NaN)
      const __m128 xm1 = _mm_sub_ps(_mm_min_ps(d, one), one);
      const __m128 s0 = seriesWeight(w0, xm1), s1 = seriesWeight(w1, xm1);
      x = _mm_add_ps(_mm_mul_ps(s0, ax), _mm_mul_ps(s1, bx));
      y = _mm_add_ps(_mm_mul_ps(s0, ay), _mm_mul_ps(s1, by));
      z = _mm_add_ps(_mm_mul_ps(s0, az), _mm_mul_ps(s1, bz));
      w = _mm_add_ps(_mm_mul_ps(s0, aw), _mm_mul_ps(s1, bw));
      const __m128 len2 =
          _mm_add_ps(_mm_add_ps(_mm_mul_ps(x, x), _mm_mul_ps(y, y)), _mm_add_ps(_mm_mul_ps(z, z), _mm_mul_ps(w, w)));
      const __m128 scale = _mm_sub_ps(threeHalves, _mm_mul_ps(half, len2));
      x = _mm_mul_ps(x, scale), y = _mm_mul_ps(y, scale), z = _mm_mul_ps(z, scale), w = _mm_mul_ps(w, scale);
      if (wide) {
        // Rare on motion: those lanes take the exact sines, one at a time.
        alignas(16) float r[16];
        _mm_store_ps(r, x), _mm_store_ps(r + 4, y), _mm_store_ps(r + 8, z), _mm_store_ps(r + 12, w);
        for (int l = 0; l < 4; ++l) {
          if (!(wide & (1 << l))) continue;
          const glm::vec4 q = slerpUnitKeys({a[l], a[4 + l], a[8 + l], a[12 + l]}, {b[l], b[4 + l], b[8 + l], b[12 + l]}, u);
          r[l] = q.x, r[4 + l] = q.y, r[8 + l] = q.z, r[12 + l] = q.w;
        }
        x = _mm_load_ps(r), y = _mm_load_ps(r + 4), z = _mm_load_ps(r + 8), w = _mm_load_ps(r + 12);
      }
      if (hasStep[block]) {
        const __m128 isLinear = _mm_cmpneq_ps(_mm_loadu_ps(linear), _mm_setzero_ps());
        x = select(isLinear, x, ax), y = select(isLinear, y, ay), z = select(isLinear, z, az), w = select(isLinear, w, aw);
      }
    }
    _MM_TRANSPOSE4_PS(x, y, z, w);
    _mm_storeu_ps(&out[joint[0]].rotation.x, x);
    _mm_storeu_ps(&out[joint[1]].rotation.x, y);
    _mm_storeu_ps(&out[joint[2]].rotation.x, z);
    _mm_storeu_ps(&out[joint[3]].rotation.x, w);
  }
}

#else

// The same, one lane at a time.
template <bool Interpolate, bool /*Prefetch*/>
void sampleGrid(const PlaybackGrid& g, int lo, float u, Transform* out) {
  const float* a = g.rows.data() + static_cast<size_t>(lo) * g.rowFloats;
  const float* b = a + g.rowFloats;
  const int vectorBlocks = g.translationBlocks + g.scaleBlocks;
  for (int block = 0; block < g.blockCount(); ++block) {
    const bool rotation = block >= vectorBlocks;
    for (int l = 0; l < 4; ++l) {
      const int lane = 4 * block + l;
      Transform& t = out[g.joints[lane]];
      const bool linear = Interpolate && g.linear[lane] != 0.0f;
      if (rotation) {
        const glm::vec4 qa(a[l], a[4 + l], a[8 + l], a[12 + l]);
        const glm::vec4 q = linear ? slerpUnitKeys(qa, {b[l], b[4 + l], b[8 + l], b[12 + l]}, u) : qa;
        t.rotation = glm::quat(q.w, q.x, q.y, q.z);
      } else {
        const glm::vec3 va(a[l], a[4 + l], a[8 + l]);
        const glm::vec3 v = linear ? glm::mix(va, glm::vec3(b[l], b[4 + l], b[8 + l]), u) : va;
        (block < g.translationBlocks ? t.translation : t.scale) = v;
      }
    }
    a += rotation ? 16 : 12;
    b += rotation ? 16 : 12;
  }
}

#endif

void sampleGridAt(const PlaybackGrid& g, float time, int& cursor, Transform* out) {
  const int n = g.keyCount();
  const int hi = upperKeyOf(g.times, time, cursor);
  if (g.rowFloats > kPrefetchRowFloats) {
    if (hi == 0) return sampleGrid<false, true>(g, 0, 0.0f, out);
    if (hi == n) return sampleGrid<false, true>(g, n - 1, 0.0f, out);
    const int lo = hi - 1;
    const float* t = g.times.data();
    if (t[lo] == time) return sampleGrid<false, true>(g, lo, 0.0f, out);
    return sampleGrid<true, true>(g, lo, (time - t[lo]) / (t[hi] - t[lo]), out);
  }
  if (hi == 0) return sampleGrid<false, false>(g, 0, 0.0f, out);
  if (hi == n) return sampleGrid<false, false>(g, n - 1, 0.0f, out);
  const int lo = hi - 1;
  const float* t = g.times.data();
  if (t[lo] == time) return sampleGrid<false, false>(g, lo, 0.0f, out);  // on a key: the key itself
  sampleGrid<true, false>(g, lo, (time - t[lo]) / (t[hi] - t[lo]), out);
}

}  // namespace

std::string PlaybackSamplingJob::validate() const {
  if (!clip) return "playback sampling: no clip";
  if (!context) return "playback sampling: no context";
  if (!std::isfinite(time)) return "playback sampling: time is not finite";
  if (outputCount < clip->jointCount)
    return "playback sampling: output holds " + std::to_string(outputCount) + " transforms, the clip animates " +
           std::to_string(clip->jointCount) + " joints";
  if (outputCount > 0 && !output) return "playback sampling: no output";
  return {};
}

bool PlaybackSamplingJob::run() const {
  if (!validate().empty()) return false;
  PlaybackContext& c = *context;
  if (c.gridCursors.size() != clip->grids.size()) c.gridCursors.resize(clip->grids.size(), 0);
  if (c.channelCursors.size() != clip->channels.size()) c.channelCursors.resize(clip->channels.size(), 0);
  for (size_t g = 0; g < clip->grids.size(); ++g) sampleGridAt(clip->grids[g], time, c.gridCursors[g], output);
  for (size_t i = 0; i < clip->channels.size(); ++i) {
    const Channel& ch = clip->channels[i];
    const glm::vec4 v = ch.modifiers.empty() ? sampleChannel(ch, time, &c.channelCursors[i]) : sampleModifiedChannel(ch, time);
    applyChannelValue(ch, v, output[ch.joint]);
  }
  return true;
}

bool samplePlayback(const PlaybackClip& clip, float time, Pose& pose, PlaybackContext& context) {
  PlaybackSamplingJob job;
  job.clip = &clip;
  job.context = &context;
  job.time = time;
  job.output = pose.local.data();
  job.outputCount = pose.size();
  return job.run();
}

}  // namespace kinema
