#include "core/rotation.h"

#include <algorithm>
#include <cctype>

namespace kinema {
namespace {

struct Axes {
  int i, j, k;  // axis indices in multiplication order
};

Axes axesOf(EulerOrder order) {
  switch (order) {
    case EulerOrder::XYZ: return {0, 1, 2};
    case EulerOrder::XZY: return {0, 2, 1};
    case EulerOrder::YXZ: return {1, 0, 2};
    case EulerOrder::YZX: return {1, 2, 0};
    case EulerOrder::ZXY: return {2, 0, 1};
    case EulerOrder::ZYX: return {2, 1, 0};
  }
  return {0, 1, 2};
}

glm::quat axisRotation(int axis, float angle) {
  glm::vec3 a(0.0f);
  a[axis] = 1.0f;
  return glm::angleAxis(angle, a);
}

}  // namespace

const char* toString(EulerOrder order) {
  switch (order) {
    case EulerOrder::XYZ: return "XYZ";
    case EulerOrder::XZY: return "XZY";
    case EulerOrder::YXZ: return "YXZ";
    case EulerOrder::YZX: return "YZX";
    case EulerOrder::ZXY: return "ZXY";
    case EulerOrder::ZYX: return "ZYX";
  }
  return "XYZ";
}

std::optional<EulerOrder> eulerOrderFromString(const std::string& s) {
  std::string u = s;
  std::transform(u.begin(), u.end(), u.begin(), [](unsigned char c) { return std::toupper(c); });
  for (EulerOrder o : {EulerOrder::XYZ, EulerOrder::XZY, EulerOrder::YXZ, EulerOrder::YZX,
                       EulerOrder::ZXY, EulerOrder::ZYX})
    if (u == toString(o)) return o;
  return std::nullopt;
}

EulerOrder reversed(EulerOrder order) {
  switch (order) {
    case EulerOrder::XYZ: return EulerOrder::ZYX;
    case EulerOrder::XZY: return EulerOrder::YZX;
    case EulerOrder::YXZ: return EulerOrder::ZXY;
    case EulerOrder::YZX: return EulerOrder::XZY;
    case EulerOrder::ZXY: return EulerOrder::YXZ;
    case EulerOrder::ZYX: return EulerOrder::XYZ;
  }
  return order;
}

glm::quat eulerToQuat(const glm::vec3& angles, EulerOrder order) {
  const Axes a = axesOf(order);
  return axisRotation(a.i, angles[a.i]) * axisRotation(a.j, angles[a.j]) *
         axisRotation(a.k, angles[a.k]);
}

glm::vec3 quatToEuler(const glm::quat& q, EulerOrder order) {
  // Work on the rotation matrix, indexed m(row, col). For R = Ri(a) Rj(b) Rk(c):
  // m(i,k) = s*sin(b), with s = +1 for cyclic orders (XYZ, YZX, ZXY) and -1 otherwise.
  // In double, normalised in double: near gimbal lock a and c come from matrix entries of
  // size |cos b|, so a float-normalised quaternion (|q| off by 1e-7, a matrix off
  // orthogonal by as much) moved a + c by 1e-7 / |cos b| -- 0.4 rad at 1e-6 from the lock.
  const glm::quat u = safeNormalize(q);
  const glm::dmat3 r = glm::mat3_cast(glm::normalize(glm::dquat(u.w, u.x, u.y, u.z)));
  auto m = [&](int row, int col) { return r[col][row]; };
  const Axes x = axesOf(order);
  const int i = x.i, j = x.j, k = x.k;
  const double s = ((j - i + 3) % 3 == 1) ? 1.0 : -1.0;
  // Row i is (cos b cos c, -+cos b sin c, +-sin b) up to the order's permutation, so
  // atan2(sin b, |cos b|) gives b accurately even where asin(sin b) would not (near +-pi/2
  // asin loses half the digits: a float sin b one ulp below 1 gave b off by 3e-4 rad).
  const double sb = s * m(i, k);
  const double cb = std::sqrt(m(i, i) * m(i, i) + m(i, j) * m(i, j));
  double a, b, c;
  b = std::atan2(sb, cb);
  // Below this |cos b| the split between a and c is float noise (and forcing c = 0 moves
  // the rotation by at most about pi * 1e-6 rad).
  if (cb > 1e-6) {
    a = std::atan2(-s * m(j, k), m(k, k));
    c = std::atan2(-s * m(i, j), m(i, i));
  } else {
    // Gimbal lock: only a +- c is determined; put it all in a.
    c = 0.0;
    a = std::atan2(s * m(k, j), m(j, j));
  }
  glm::vec3 out(0.0f);
  out[i] = static_cast<float>(a);
  out[j] = static_cast<float>(b);
  out[k] = static_cast<float>(c);
  return out;
}

glm::quat axisAngle(const glm::vec3& axis, float angle) {
  const float len = glm::length(axis);
  if (!(len > 0.0f) || !std::isfinite(len)) return glm::quat(1.0f, 0.0f, 0.0f, 0.0f);
  return glm::angleAxis(angle, axis / len);
}

void toAxisAngle(const glm::quat& qIn, glm::vec3& axis, float& angle) {
  glm::quat q = safeNormalize(qIn);
  if (q.w < 0.0f) q = -q;  // angle in [0, pi]
  const float s = std::sqrt(std::max(0.0f, q.x * q.x + q.y * q.y + q.z * q.z));
  angle = 2.0f * std::atan2(s, q.w);
  if (s < 1e-12f) {
    axis = glm::vec3(1.0f, 0.0f, 0.0f);
    angle = 0.0f;
  } else {
    axis = glm::vec3(q.x, q.y, q.z) / s;
  }
}

glm::quat fromToRotation(const glm::vec3& fromIn, const glm::vec3& toIn) {
  const float lf = glm::length(fromIn), lt = glm::length(toIn);
  if (!(lf > 0.0f) || !(lt > 0.0f)) return glm::quat(1.0f, 0.0f, 0.0f, 0.0f);
  const glm::vec3 from = fromIn / lf, to = toIn / lt;
  const float d = glm::dot(from, to);
  if (d < -0.999999f) {
    // Opposite: half a turn about any axis perpendicular to `from`.
    glm::vec3 axis = glm::cross(glm::vec3(1.0f, 0.0f, 0.0f), from);
    if (glm::dot(axis, axis) < 1e-6f) axis = glm::cross(glm::vec3(0.0f, 1.0f, 0.0f), from);
    return glm::angleAxis(glm::pi<float>(), glm::normalize(axis));
  }
  // Half-way quaternion: (1 + d, from x to) normalised is the rotation by the full angle.
  const glm::vec3 c = glm::cross(from, to);
  return glm::normalize(glm::quat(1.0f + d, c.x, c.y, c.z));
}

SwingTwist swingTwist(const glm::quat& qIn, const glm::vec3& twistAxis) {
  const glm::quat q = safeNormalize(qIn);
  const glm::vec3 v(q.x, q.y, q.z);
  const glm::vec3 p = glm::dot(v, twistAxis) * twistAxis;  // vector part along the axis
  glm::quat twist(q.w, p.x, p.y, p.z);
  const float len2 = glm::dot(twist, twist);
  if (len2 < 1e-12f)
    twist = glm::quat(1.0f, 0.0f, 0.0f, 0.0f);  // a pure half-turn swing: no twist
  else
    twist = twist * (1.0f / std::sqrt(len2));
  const glm::quat swing = q * glm::conjugate(twist);
  return {swing, twist};
}

glm::quat sameHemisphere(const glm::quat& q, const glm::quat& reference) {
  return glm::dot(q, reference) < 0.0f ? -q : q;
}

glm::quat slerpShortest(const glm::quat& a, const glm::quat& bIn, float t) {
  const glm::quat b = sameHemisphere(bIn, a);
  const float d = std::min(1.0f, glm::dot(a, b));
  if (d > 0.9995f) return glm::normalize(a + t * (b - a));
  const float theta = std::acos(d);
  const float s = std::sin(theta);
  return (std::sin((1.0f - t) * theta) / s) * a + (std::sin(t * theta) / s) * b;
}

glm::quat safeNormalize(const glm::quat& q) {
  // Divide by the largest component first, so tiny (denormal) and huge quaternions
  // normalise as accurately as ordinary ones instead of underflowing or overflowing.
  const float m = std::max(std::max(std::abs(q.x), std::abs(q.y)), std::max(std::abs(q.z), std::abs(q.w)));
  if (!(m > 0.0f) || !std::isfinite(m)) return glm::quat(1.0f, 0.0f, 0.0f, 0.0f);
  const glm::quat s(q.w / m, q.x / m, q.y / m, q.z / m);  // divide: 1/m overflows for denormal m
  if (!isFinite(s)) return glm::quat(1.0f, 0.0f, 0.0f, 0.0f);  // a NaN component
  return s * (1.0f / std::sqrt(glm::dot(s, s)));
}

}  // namespace kinema
