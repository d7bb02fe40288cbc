#include "anim/bezier_handles.h"

#include <algorithm>
#include <cmath>

namespace kinema {

namespace {

// Slope through the neighbours (per component) for Auto handles at an interior key.
glm::vec4 chordSlope(const Channel& ch, int k) {
  return (ch.values[k + 1] - ch.values[k - 1]) / (ch.times[k + 1] - ch.times[k - 1]);
}

// AutoClamped: flat where the key is a local extremum (or equals a neighbour), and the
// slope limited to three times the smaller neighbouring secant, which keeps both inner
// control values between the segment's end values: no overshoot between keys.
glm::vec4 clampedSlope(const Channel& ch, int k) {
  glm::vec4 slope = chordSlope(ch, k);
  const glm::vec4 a = (ch.values[k] - ch.values[k - 1]) / (ch.times[k] - ch.times[k - 1]);
  const glm::vec4 b = (ch.values[k + 1] - ch.values[k]) / (ch.times[k + 1] - ch.times[k]);
  for (int i = 0; i < 4; ++i) {
    if (a[i] * b[i] <= 0.0f) {
      slope[i] = 0.0f;
      continue;
    }
    const float limit = 3.0f * std::min(std::abs(a[i]), std::abs(b[i]));
    slope[i] = std::copysign(std::min(std::abs(slope[i]), limit), slope[i]);
  }
  return slope;
}

void side(const Channel& ch, int k, bool right, const KeySettings& s, float& dt, glm::vec4& dv) {
  const HandleType type = right ? s.rightHandleType : s.leftHandleType;
  const int n = ch.keyCount();
  const int neighbour = right ? k + 1 : k - 1;
  const bool hasNeighbour = neighbour >= 0 && neighbour < n;
  if (type == HandleType::Free || type == HandleType::Aligned) {
    dt = right ? s.rightHandleTime : s.leftHandleTime;
    dv = right ? s.rightHandleValue : s.leftHandleValue;
    return;
  }
  if (!hasNeighbour) {
    // The outer handle of an end key (never evaluated: extrapolation is constant) mirrors
    // the inner one through the key, as Blender draws it; a lone key has none.
    const int inner = right ? k - 1 : k + 1;
    if (inner < 0 || inner >= n) {
      dt = 0.0f;
      dv = glm::vec4(0.0f);
      return;
    }
    side(ch, k, !right, s, dt, dv);
    dt = -dt;
    dv = -dv;
    return;
  }
  const float span = ch.times[neighbour] - ch.times[k];  // negative on the left
  dt = span / 3.0f;
  if (type == HandleType::Vector) {
    dv = (ch.values[neighbour] - ch.values[k]) / 3.0f;
    return;
  }
  if (k == 0 || k == n - 1) {
    dv = glm::vec4(0.0f);
    return;
  }
  dv = (type == HandleType::Auto ? chordSlope(ch, k) : clampedSlope(ch, k)) * dt;
}

float bezier(float a, float b, float c, float d, float s) {
  const float r = 1.0f - s;
  return r * r * r * a + 3 * r * r * s * b + 3 * r * s * s * c + s * s * s * d;
}

}  // namespace

BezierHandles effectiveHandles(const Channel& ch, int k) {
  const KeySettings s = ch.settings(k);
  BezierHandles h;
  side(ch, k, false, s, h.leftTime, h.leftValue);
  side(ch, k, true, s, h.rightTime, h.rightValue);
  return h;
}

float solveBezierParameter(float x0, float x1, float x2, float x3, float x) {
  float lo = 0.0f, hi = 1.0f;
  float s = (x3 > x0) ? (x - x0) / (x3 - x0) : 0.0f;
  for (int i = 0; i < 30; ++i) {
    const float f = bezier(x0, x1, x2, x3, s) - x;
    if (std::abs(f) <= 1e-7f * std::max(1.0f, std::abs(x3 - x0))) return s;
    if (f > 0) hi = s; else lo = s;
    const float r = 1.0f - s;
    const float d = 3 * r * r * (x1 - x0) + 6 * r * s * (x2 - x1) + 3 * s * s * (x3 - x2);
    float next = d > 0 ? s - f / d : -1.0f;
    // Newton can leave the bracket where the curve is flat in time; bisect there.
    if (!(next > lo && next < hi)) next = 0.5f * (lo + hi);
    s = next;
  }
  return s;
}

glm::vec4 evaluateBezierSegment(const Channel& ch, int k, float t) {
  const BezierHandles a = effectiveHandles(ch, k), b = effectiveHandles(ch, k + 1);
  const float x0 = ch.times[k], x3 = ch.times[k + 1], len = x3 - x0;
  float right = std::max(0.0f, a.rightTime), left = std::max(0.0f, -b.leftTime);
  glm::vec4 rv = a.rightValue, lv = b.leftValue;
  if (right + left > len) {
    // Shorten both handles by the same factor, keeping their directions.
    const float f = len / (right + left);
    rv *= right > 0 ? f : 1.0f;
    lv *= left > 0 ? f : 1.0f;
    right *= f;
    left *= f;
  }
  const float s = solveBezierParameter(x0, x0 + right, x3 - left, x3, t);
  const glm::vec4 p0 = ch.values[k], p3 = ch.values[k + 1];
  const glm::vec4 p1 = p0 + rv, p2 = p3 + lv;
  const float r = 1.0f - s;
  return (r * r * r) * p0 + (3 * r * r * s) * p1 + (3 * r * s * s) * p2 + (s * s * s) * p3;
}

}  // namespace kinema
