#pragma once
#include <optional>
#include <string>

#include "core/math.h"

namespace kinema {

// Euler axis orders, named in the order the rotations are *multiplied*:
// XYZ means R = Rx(x) * Ry(y) * Rz(z). Read as intrinsic rotations (about the body's
// moving axes) that is "first X, then Y, then Z"; read as extrinsic rotations (about
// the fixed world axes) it is "first Z, then Y, then X". BVH channel lists use exactly
// this convention: "Zrotation Xrotation Yrotation" is ZXY, R = Rz * Rx * Ry.
enum class EulerOrder { XYZ, XZY, YXZ, YZX, ZXY, ZYX };

const char* toString(EulerOrder order);
std::optional<EulerOrder> eulerOrderFromString(const std::string& s);  // "XYZ", "zxy", ...
// The order whose intrinsic reading equals `order` read extrinsically (its reverse).
EulerOrder reversed(EulerOrder order);

// angles.x, .y, .z are the angles about X, Y and Z (radians), whatever the order.
glm::quat eulerToQuat(const glm::vec3& angles, EulerOrder order);
// Inverse of eulerToQuat. The middle angle lies in [-pi/2, pi/2]; at gimbal lock
// (middle angle = +-pi/2) the third angle is set to 0 and the first takes the rest.
glm::vec3 quatToEuler(const glm::quat& q, EulerOrder order);

// Rotation by `angle` radians about `axis` (normalised here; a zero axis gives identity).
glm::quat axisAngle(const glm::vec3& axis, float angle);
// Axis (unit) and angle in [0, pi] of a rotation; identity gives axis (1,0,0), angle 0.
void toAxisAngle(const glm::quat& q, glm::vec3& axis, float& angle);

// The shortest rotation taking direction `from` onto direction `to` (neither needs to be
// unit). Opposite directions turn by pi about an axis perpendicular to `from`.
glm::quat fromToRotation(const glm::vec3& from, const glm::vec3& to);

// q = swing * twist, where twist rotates about `twistAxis` (unit) and swing about an
// axis perpendicular to it. Used for joint limits (cone + twist).
struct SwingTwist {
  glm::quat swing;
  glm::quat twist;
};
SwingTwist swingTwist(const glm::quat& q, const glm::vec3& twistAxis);

// q or -q, whichever lies in the same hemisphere as `reference` (dot >= 0), so that
// interpolating from `reference` takes the shortest arc.
glm::quat sameHemisphere(const glm::quat& q, const glm::quat& reference);
// Spherical interpolation along the shortest arc; falls back to normalised lerp when
// the two rotations are nearly equal.
glm::quat slerpShortest(const glm::quat& a, const glm::quat& b, float t);
// Normalises q; a zero or non-finite quaternion becomes identity.
glm::quat safeNormalize(const glm::quat& q);
// The rotation of an affine matrix (a world or local transform): its 3x3 part with each
// column's scale divided out (a zero column is left as it is), as a unit quaternion
// (safeNormalize: identity for a degenerate matrix). Inline: the IK solvers read it per joint
// on every solve.
inline glm::quat rotationOf(const glm::mat4& m) {
  glm::mat3 r(m);
  for (int c = 0; c < 3; ++c) {
    const float length = glm::length(r[c]);
    if (length > 0.0f) r[c] /= length;
  }
  return safeNormalize(glm::quat_cast(r));
}

}  // namespace kinema
