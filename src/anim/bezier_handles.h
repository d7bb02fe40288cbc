#pragma once
#include "anim/clip.h"

namespace kinema {

// A key's Bezier handles as used for evaluation, relative to the key: time offsets
// (left <= 0 <= right) and value offsets.
struct BezierHandles {
  float leftTime = 0.0f, rightTime = 0.0f;
  glm::vec4 leftValue{0.0f}, rightValue{0.0f};
};

// Free and Aligned handles come from the key; Vector, Auto and AutoClamped handles are
// computed from the neighbouring keys (Blender's meaning, see HandleType). End keys with
// Auto or AutoClamped handles are flat, as in Blender with constant extrapolation; their
// outer computed handle (used by no segment) is the inner one mirrored through the key.
BezierHandles effectiveHandles(const Channel& channel, int key);

// The value of the Bezier segment from key k to key k+1 at time t (inside the segment).
// Handles that reach past the other key in time are shortened proportionally (as Blender
// does) so that time is monotonic along the curve; then the curve's time polynomial is
// solved for t (Newton-Raphson with a bisection fallback) and the value read there.
glm::vec4 evaluateBezierSegment(const Channel& channel, int k, float t);

// The cubic Bezier parameter s in [0, 1] at which x(s) = x, for control abscissae
// x0 <= x1, x2 <= x3 with x(s) monotonic.
float solveBezierParameter(float x0, float x1, float x2, float x3, float x);

}  // namespace kinema
