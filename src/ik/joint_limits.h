#pragma once
#include <string>

#include "core/math.h"
#include "core/rotation.h"

namespace kinema {

// How far a joint may turn away from its rest orientation. Limits act on the pose's
// rotation relative to the rest rotation, d = inverse(rest) * local, expressed in the
// joint's rest frame (Blender's IK limits are relative to the rest pose the same way).
enum class JointLimitType { None, Hinge, Cone, Euler };

struct JointLimit {
  JointLimitType type = JointLimitType::None;
  // Hinge: the only axis the joint turns about. Cone: the twist axis (the bone's
  // direction in the rest frame), around which the swing cone is centred. Unit length.
  glm::vec3 axis{0.0f, 1.0f, 0.0f};
  float minAngle = 0.0f;  // hinge angle range, radians, about `axis`
  float maxAngle = 0.0f;
  float coneAngle = 0.0f;  // cone: largest swing away from `axis`, radians in [0, pi]
  float twistMin = 0.0f;   // cone: twist range about `axis`, radians
  float twistMax = 0.0f;
  EulerOrder order = EulerOrder::XYZ;  // Euler: per-axis ranges, radians
  glm::vec3 eulerMin{0.0f};
  glm::vec3 eulerMax{0.0f};

  static JointLimit hinge(const glm::vec3& axis, float minAngle, float maxAngle);
  static JointLimit cone(const glm::vec3& twistAxis, float coneAngle, float twistMin, float twistMax);
  static JointLimit euler(EulerOrder order, const glm::vec3& minAngles, const glm::vec3& maxAngles);

  bool active() const { return type != JointLimitType::None; }
  // Empty when the limit is usable; otherwise what is wrong (non-finite numbers,
  // zero axis, min > max, cone angle outside [0, pi]).
  std::string validate() const;
};

const char* toString(JointLimitType type);

// The rotation nearest-in-parameters to `local` that the limit allows: hinge keeps the
// twist about its axis and clamps it; cone clamps the swing angle and the twist
// separately; Euler clamps each angle. Returns the (unit) limited local rotation.
glm::quat applyJointLimit(const JointLimit& limit, const glm::quat& restRotation, const glm::quat& local);

// How far `local` lies outside the limit, in radians (0 when inside).
float jointLimitViolation(const JointLimit& limit, const glm::quat& restRotation, const glm::quat& local);

}  // namespace kinema
