#include "deform/axis_deformers.h"

#include <algorithm>
#include <cmath>

namespace kinema {

const char* toString(AxisDeformerKind kind) {
  switch (kind) {
    case AxisDeformerKind::Bend: return "bend";
    case AxisDeformerKind::Twist: return "twist";
    case AxisDeformerKind::Taper: return "taper";
  }
  return "bend";
}

bool fromString(const std::string& s, AxisDeformerKind& out) {
  for (AxisDeformerKind k : {AxisDeformerKind::Bend, AxisDeformerKind::Twist, AxisDeformerKind::Taper})
    if (s == toString(k)) {
      out = k;
      return true;
    }
  return false;
}

const char* toString(DeformAxis axis) {
  switch (axis) {
    case DeformAxis::X: return "x";
    case DeformAxis::Y: return "y";
    case DeformAxis::Z: return "z";
  }
  return "y";
}

bool fromString(const std::string& s, DeformAxis& out) {
  for (DeformAxis a : {DeformAxis::X, DeformAxis::Y, DeformAxis::Z})
    if (s == toString(a)) {
      out = a;
      return true;
    }
  return false;
}

std::string AxisDeformer::validate() const {
  if (!isFinite(origin) || !std::isfinite(low) || !std::isfinite(high) || !std::isfinite(amount))
    return std::string(toString(kind)) + " deformer has a value that is not finite";
  if (!(low < high)) return std::string(toString(kind)) + " deformer's range is empty (low must be below high)";
  return "";
}

glm::vec3 applyAxisDeformer(const AxisDeformer& d, const glm::vec3& p) {
  const int ia = static_cast<int>(d.axis), ib = (ia + 1) % 3, ic = (ia + 2) % 3;
  const glm::vec3 q = p - d.origin;
  const float a = q[ia], b = q[ib], c = q[ic];
  const float range = d.high - d.low;
  const float h = std::clamp(a - d.low, 0.0f, range);
  const float f = h / range;
  float a2 = a, b2 = b, c2 = c;
  switch (d.kind) {
    case AxisDeformerKind::Twist: {
      // Right-handed about +axis: b turns towards c.
      const float angle = d.amount * f;
      const float cs = std::cos(angle), sn = std::sin(angle);
      b2 = cs * b - sn * c;
      c2 = sn * b + cs * c;
      break;
    }
    case AxisDeformerKind::Taper: {
      const float scale = 1.0f + (d.amount - 1.0f) * f;
      b2 = b * scale;
      c2 = c * scale;
      break;
    }
    case AxisDeformerKind::Bend: {
      if (a <= d.low) break;
      // Arc of curvature k = amount / H through the point (low, 0): a point at arc length h
      // and offset b from the centre line goes to low + (1/k - b) sin(theta) along the axis
      // and 1/k - (1/k - b) cos(theta) along b, theta = k h. Written with sin(theta)/k and
      // (1 - cos(theta))/k so a bend angle near zero stays exact (no 1/k).
      const float k = d.amount / range;
      const float theta = k * h;
      const float cs = std::cos(theta), sn = std::sin(theta);
      // sin(theta)/k = h sinc(theta); (1 - cos(theta))/k = h * 2 sin^2(theta/2) / theta.
      const float sinOverK = std::abs(theta) < 1e-4f ? h * (1.0f - theta * theta / 6.0f) : sn / k;
      const float halfSin = std::sin(0.5f * theta);
      const float versOverK = std::abs(theta) < 1e-4f ? h * theta * 0.5f : 2.0f * halfSin * halfSin / k;
      a2 = d.low + sinOverK - b * sn;
      b2 = versOverK + b * cs;
      // Past the range the rest follows the end tangent (cos, sin) rigidly.
      const float beyond = a - d.low - h;
      a2 += beyond * cs;
      b2 += beyond * sn;
      break;
    }
  }
  glm::vec3 out;
  out[ia] = a2;
  out[ib] = b2;
  out[ic] = c2;
  return out + d.origin;
}

}  // namespace kinema
