#include "ik/joint_limits.h"

#include <gtest/gtest.h>

#include "test_support.h"

namespace kinema {
namespace KINEMA_UNITY_ID {

const glm::quat kId(1.0f, 0.0f, 0.0f, 0.0f);
constexpr float kDeg = glm::pi<float>() / 180.0f;

TEST(JointLimits, HingeClampsAngleAndDropsSwing) {
  const JointLimit l = JointLimit::hinge({0, 0, 1}, -30 * kDeg, 60 * kDeg);
  EXPECT_SAME_ROTATION(applyJointLimit(l, kId, glm::angleAxis(100 * kDeg, glm::vec3(0, 0, 1))),
                       glm::angleAxis(60 * kDeg, glm::vec3(0, 0, 1)), 1e-6f);
  EXPECT_SAME_ROTATION(applyJointLimit(l, kId, glm::angleAxis(-50 * kDeg, glm::vec3(0, 0, 1))),
                       glm::angleAxis(-30 * kDeg, glm::vec3(0, 0, 1)), 1e-6f);
  // Swing about X is removed; the 20 degrees about Z stay (Rz * Rx: twist about Z is 20).
  const glm::quat q = glm::angleAxis(20 * kDeg, glm::vec3(0, 0, 1)) * glm::angleAxis(40 * kDeg, glm::vec3(1, 0, 0));
  EXPECT_SAME_ROTATION(applyJointLimit(l, kId, q), glm::angleAxis(20 * kDeg, glm::vec3(0, 0, 1)), 1e-5f);
  EXPECT_NEAR(jointLimitViolation(l, kId, glm::angleAxis(100 * kDeg, glm::vec3(0, 0, 1))), 40 * kDeg, 1e-5f);
}

TEST(JointLimits, LimitsAreRelativeToTheRestRotation) {
  const glm::quat rest = glm::angleAxis(90 * kDeg, glm::vec3(0, 1, 0));
  const JointLimit l = JointLimit::hinge({0, 0, 1}, 0.0f, 10 * kDeg);
  const glm::quat local = rest * glm::angleAxis(30 * kDeg, glm::vec3(0, 0, 1));
  EXPECT_SAME_ROTATION(applyJointLimit(l, rest, local), rest * glm::angleAxis(10 * kDeg, glm::vec3(0, 0, 1)), 1e-6f);
  EXPECT_EQ(jointLimitViolation(l, rest, rest), 0.0f);
}

TEST(JointLimits, ConeClampsSwingAndTwistSeparately) {
  const JointLimit l = JointLimit::cone({0, 1, 0}, 45 * kDeg, -10 * kDeg, 10 * kDeg);
  // swing 80 about X after a twist of 30 about Y: q = swing * twist.
  const glm::quat q = glm::angleAxis(80 * kDeg, glm::vec3(1, 0, 0)) * glm::angleAxis(30 * kDeg, glm::vec3(0, 1, 0));
  const glm::quat want = glm::angleAxis(45 * kDeg, glm::vec3(1, 0, 0)) * glm::angleAxis(10 * kDeg, glm::vec3(0, 1, 0));
  EXPECT_SAME_ROTATION(applyJointLimit(l, kId, q), want, 1e-5f);
  EXPECT_NEAR(jointLimitViolation(l, kId, q), 35 * kDeg, 1e-4f);
  // Inside: unchanged.
  const glm::quat inside = glm::angleAxis(30 * kDeg, glm::vec3(0, 0, 1));
  EXPECT_SAME_ROTATION(applyJointLimit(l, kId, inside), inside, 1e-6f);
}

TEST(JointLimits, EulerClampsEachAngle) {
  const JointLimit l = JointLimit::euler(EulerOrder::XYZ, glm::vec3(-0.3f), glm::vec3(0.3f));
  const glm::quat q = eulerToQuat({0.5f, 0.2f, -1.0f}, EulerOrder::XYZ);
  EXPECT_SAME_ROTATION(applyJointLimit(l, kId, q), eulerToQuat({0.3f, 0.2f, -0.3f}, EulerOrder::XYZ), 1e-5f);
}

TEST(JointLimits, ValidateNamesTheProblem) {
  EXPECT_NE(JointLimit::hinge({0, 0, 1}, 1.0f, -1.0f).validate(), "");
  EXPECT_NE(JointLimit::cone({0, 1, 0}, 4.0f, 0.0f, 0.0f).validate(), "");
  EXPECT_EQ(JointLimit::cone({0, 1, 0}, 1.0f, -0.5f, 0.5f).validate(), "");
}

}  // namespace
}  // namespace kinema
