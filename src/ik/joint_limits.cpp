#include "ik/joint_limits.h"

#include <algorithm>
#include <cmath>

namespace kinema {

namespace {

// Signed angle of a rotation about `axis` (the rotation must turn only about it).
float signedAngleAbout(const glm::quat& twist, const glm::vec3& axis) {
  const float s = glm::dot(glm::vec3(twist.x, twist.y, twist.z), axis);
  float a = 2.0f * std::atan2(s, twist.w);  // (-2pi, 2pi]
  if (a > glm::pi<float>()) a -= glm::two_pi<float>();
  if (a < -glm::pi<float>()) a += glm::two_pi<float>();
  return a;
}

// Rotation angle in [0, pi]; atan2 keeps small angles accurate where acos(w) would not.
float rotationAngle(const glm::quat& q) {
  return 2.0f * std::atan2(glm::length(glm::vec3(q.x, q.y, q.z)), std::abs(q.w));
}
float swingAngle(const glm::quat& swing) { return rotationAngle(swing); }

float outside(float v, float lo, float hi) { return v < lo ? lo - v : (v > hi ? v - hi : 0.0f); }

bool finite(float v) { return std::isfinite(v); }

}  // namespace

JointLimit JointLimit::hinge(const glm::vec3& axis, float minAngle, float maxAngle) {
  JointLimit l;
  l.type = JointLimitType::Hinge;
  l.axis = glm::normalize(axis);
  l.minAngle = minAngle;
  l.maxAngle = maxAngle;
  return l;
}

JointLimit JointLimit::cone(const glm::vec3& twistAxis, float coneAngle, float twistMin, float twistMax) {
  JointLimit l;
  l.type = JointLimitType::Cone;
  l.axis = glm::normalize(twistAxis);
  l.coneAngle = coneAngle;
  l.twistMin = twistMin;
  l.twistMax = twistMax;
  return l;
}

JointLimit JointLimit::euler(EulerOrder order, const glm::vec3& minAngles, const glm::vec3& maxAngles) {
  JointLimit l;
  l.type = JointLimitType::Euler;
  l.order = order;
  l.eulerMin = minAngles;
  l.eulerMax = maxAngles;
  return l;
}

const char* toString(JointLimitType type) {
  switch (type) {
    case JointLimitType::None: return "none";
    case JointLimitType::Hinge: return "hinge";
    case JointLimitType::Cone: return "cone";
    case JointLimitType::Euler: return "euler";
  }
  return "none";
}

std::string JointLimit::validate() const {
  switch (type) {
    case JointLimitType::None: return {};
    case JointLimitType::Hinge:
    case JointLimitType::Cone:
      if (!isFinite(axis) || std::abs(glm::length(axis) - 1.0f) > 1e-3f) return "axis must be a finite unit vector";
      if (type == JointLimitType::Hinge) {
        if (!finite(minAngle) || !finite(maxAngle)) return "hinge angles must be finite";
        if (minAngle > maxAngle) return "hinge min angle is greater than its max angle";
        if (minAngle < -glm::pi<float>() - 1e-4f || maxAngle > glm::pi<float>() + 1e-4f)
          return "hinge angles must lie in [-180, 180] degrees";
        return {};
      }
      if (!finite(coneAngle) || coneAngle < 0.0f || coneAngle > glm::pi<float>() + 1e-4f)
        return "cone angle must lie in [0, 180] degrees";
      if (!finite(twistMin) || !finite(twistMax)) return "twist angles must be finite";
      if (twistMin > twistMax) return "twist min is greater than twist max";
      return {};
    case JointLimitType::Euler:
      if (!isFinite(eulerMin) || !isFinite(eulerMax)) return "Euler ranges must be finite";
      for (int i = 0; i < 3; ++i)
        if (eulerMin[i] > eulerMax[i]) return "an Euler min angle is greater than its max angle";
      return {};
  }
  return "unknown limit type";
}

glm::quat applyJointLimit(const JointLimit& limit, const glm::quat& restRotation, const glm::quat& local) {
  if (!limit.active()) return local;
  const glm::quat d = safeNormalize(glm::conjugate(restRotation) * local);
  glm::quat limited = d;
  switch (limit.type) {
    case JointLimitType::None: break;
    case JointLimitType::Hinge: {
      // Dropping the swing projects onto the hinge; then clamp the angle.
      const float a = signedAngleAbout(swingTwist(d, limit.axis).twist, limit.axis);
      limited = glm::angleAxis(std::clamp(a, limit.minAngle, limit.maxAngle), limit.axis);
      break;
    }
    case JointLimitType::Cone: {
      const SwingTwist st = swingTwist(d, limit.axis);
      glm::quat swing = st.swing;
      const float sa = swingAngle(swing);
      if (sa > limit.coneAngle) {
        glm::vec3 sAxis;
        float angle;
        toAxisAngle(swing, sAxis, angle);
        swing = glm::angleAxis(limit.coneAngle, sAxis);
      }
      const float ta = std::clamp(signedAngleAbout(st.twist, limit.axis), limit.twistMin, limit.twistMax);
      limited = swing * glm::angleAxis(ta, limit.axis);
      break;
    }
    case JointLimitType::Euler: {
      const glm::vec3 e = quatToEuler(d, limit.order);
      limited = eulerToQuat(glm::clamp(e, limit.eulerMin, limit.eulerMax), limit.order);
      break;
    }
  }
  return safeNormalize(restRotation * limited);
}

float jointLimitViolation(const JointLimit& limit, const glm::quat& restRotation, const glm::quat& local) {
  if (!limit.active()) return 0.0f;
  const glm::quat d = safeNormalize(glm::conjugate(restRotation) * local);
  switch (limit.type) {
    case JointLimitType::None: return 0.0f;
    case JointLimitType::Hinge: {
      const SwingTwist st = swingTwist(d, limit.axis);
      const float a = signedAngleAbout(st.twist, limit.axis);
      return std::max(swingAngle(st.swing), outside(a, limit.minAngle, limit.maxAngle));
    }
    case JointLimitType::Cone: {
      const SwingTwist st = swingTwist(d, limit.axis);
      return std::max(outside(swingAngle(st.swing), 0.0f, limit.coneAngle),
                      outside(signedAngleAbout(st.twist, limit.axis), limit.twistMin, limit.twistMax));
    }
    case JointLimitType::Euler: {
      // Euler angles are not unique: measure the rotation distance to the clamped one.
      const glm::quat c = applyJointLimit(limit, glm::quat(1.0f, 0.0f, 0.0f, 0.0f), d);
      return rotationAngle(glm::conjugate(c) * d);
    }
  }
  return 0.0f;
}

}  // namespace kinema
