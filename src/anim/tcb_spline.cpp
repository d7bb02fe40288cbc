#include "anim/tcb_spline.h"

namespace kinema {

namespace {

// Tangents of an interior key (0 < k < n-1).
void interior(const Channel& ch, int k, bool useKeyTcb, glm::vec4& in, glm::vec4& out) {
  float T = 0, C = 0, B = 0;
  if (useKeyTcb && !ch.keys.empty()) {
    T = ch.keys[k].tension;
    C = ch.keys[k].continuity;
    B = ch.keys[k].bias;
  }
  const glm::vec4 a = ch.values[k] - ch.values[k - 1];
  const glm::vec4 b = ch.values[k + 1] - ch.values[k];
  const float span = ch.times[k + 1] - ch.times[k - 1];
  out = ((1 - T) * (1 + C) * (1 + B) * a + (1 - T) * (1 - C) * (1 - B) * b) / span;
  in = ((1 - T) * (1 - C) * (1 + B) * a + (1 - T) * (1 + C) * (1 - B) * b) / span;
}

}  // namespace

void tcbTangents(const Channel& ch, int k, bool useKeyTcb, glm::vec4& in, glm::vec4& out) {
  const int n = ch.keyCount();
  if (n < 2) {
    in = out = glm::vec4(0.0f);
    return;
  }
  if (k > 0 && k < n - 1) {
    interior(ch, k, useKeyTcb, in, out);
    return;
  }
  // Natural end: zero second derivative at the end key of a Hermite segment whose other
  // tangent is the neighbour's.
  glm::vec4 nin, nout;
  if (k == 0) {
    const float dt = ch.times[1] - ch.times[0];
    const glm::vec4 chord = (ch.values[1] - ch.values[0]) / dt;
    if (n == 2) {
      in = out = chord;
      return;
    }
    interior(ch, 1, useKeyTcb, nin, nout);
    in = out = 1.5f * chord - 0.5f * nin;
    return;
  }
  const float dt = ch.times[n - 1] - ch.times[n - 2];
  const glm::vec4 chord = (ch.values[n - 1] - ch.values[n - 2]) / dt;
  if (n == 2) {
    in = out = chord;
    return;
  }
  interior(ch, n - 2, useKeyTcb, nin, nout);
  in = out = 1.5f * chord - 0.5f * nout;
}

}  // namespace kinema
