#pragma once
// The slerp that sampling runs on (sampleClip, PlaybackSamplingJob): shortest-arc slerp of
// two unit quaternions stored as (x, y, z, w), with acos and sin replaced by a series where
// that is exact to float precision.
#include <algorithm>
#include <cmath>

#include "core/rotation.h"

namespace kinema {

// The weights sin((1 - u) theta) / sin(theta) and sin(u theta) / sin(theta) of a slerp with
// cos(theta) = x, as the series in (x - 1) of Eberly's "A fast and accurate algorithm for
// computing SLERP" (2011), cut after six terms: for x >= 0.8 (keys up to 74 degrees apart)
// it is within 2e-8 of the sines, with no acos, sin or division.
inline float slerpWeight(float u, float xm1) {
  const float u2 = u * u;
  float acc = 1.0f + (u2 / 78.0f - 6.0f / 13.0f) * xm1;
  acc = 1.0f + (u2 / 55.0f - 5.0f / 11.0f) * xm1 * acc;
  acc = 1.0f + (u2 / 36.0f - 4.0f / 9.0f) * xm1 * acc;
  acc = 1.0f + (u2 / 21.0f - 3.0f / 7.0f) * xm1 * acc;
  acc = 1.0f + (u2 / 10.0f - 2.0f / 5.0f) * xm1 * acc;
  acc = 1.0f + (u2 / 3.0f - 1.0f / 3.0f) * xm1 * acc;
  return u * acc;
}

// Below this cos(theta) the series is not exact and the sines are used.
constexpr float kSlerpSeriesMinCos = 0.8f;

inline bool isUnitLength(const glm::vec4& v) { return std::abs(glm::dot(v, v) - 1.0f) < 1e-6f; }

// slerpShortest of two unit quaternions (x, y, z, w), normalised, with the sines replaced by
// slerpWeight wherever it is exact to float precision. slerpShortest blends linearly above
// cos 0.9995 (within 5e-7 of the slerp there); the series stays on the slerp, and without
// that branch, which on motion capture goes either way from key to key.
inline glm::vec4 slerpUnitKeys(const glm::vec4& a, glm::vec4 b, float u) {
  float d = glm::dot(a, b);
  if (d < 0.0f) {
    b = -b;
    d = -d;
  }
  if (!(d >= kSlerpSeriesMinCos)) {
    const glm::quat q = slerpShortest(glm::quat(a.w, a.x, a.y, a.z), glm::quat(b.w, b.x, b.y, b.z), u);
    const float len2 = q.x * q.x + q.y * q.y + q.z * q.z + q.w * q.w;
    const glm::quat r = std::abs(len2 - 1.0f) < 1e-6f ? q : safeNormalize(q);
    return {r.x, r.y, r.z, r.w};
  }
  const float xm1 = std::min(d, 1.0f) - 1.0f;
  const glm::vec4 r = slerpWeight(1.0f - u, xm1) * a + slerpWeight(u, xm1) * b;
  // |r| is within 1e-7 of 1: one Newton step for 1 / |r| is exact to float precision.
  return r * (1.5f - 0.5f * glm::dot(r, r));
}

}  // namespace kinema
