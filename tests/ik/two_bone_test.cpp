// Two-bone analytic IK against the closed form of seed 002 (planar x_e, y_e formulas).
#include <gtest/gtest.h>

#include "ik/ik_solver.h"
#include "ik_test_chains.h"
#include "test_support.h"

namespace kinema {
namespace KINEMA_UNITY_ID {

using test::planarArm;
using test::wrap;
using test::zAngle;

TEST(TwoBone, PlanarClosedFormBothElbows) {
  const float l1 = 1.2f, l2 = 0.8f;
  const Skeleton s = planarArm(l1, l2);
  for (const glm::vec2 t : {glm::vec2(1.1f, 0.9f), glm::vec2(-0.5f, 1.4f), glm::vec2(0.7f, -0.3f)}) {
    // x_e = l1 cos t1 + l2 cos(t1 + t2), y_e = l1 sin t1 + l2 sin(t1 + t2), solved by hand:
    const float c2 = (t.x * t.x + t.y * t.y - l1 * l1 - l2 * l2) / (2.0f * l1 * l2);
    for (float sign : {1.0f, -1.0f}) {
      const float t2 = sign * std::acos(c2);
      const float t1 = std::atan2(t.y, t.x) - std::atan2(l2 * std::sin(t2), l1 + l2 * std::cos(t2));
      const glm::vec3 elbow(l1 * std::cos(t1), l1 * std::sin(t1), 0.0f);
      Pose pose = Pose::rest(s);
      pose.local[1].rotation = glm::angleAxis(0.2f, glm::vec3(0, 0, 1));  // a bend to start from
      IkProblem p;
      p.skeleton = &s;
      p.pose = &pose;
      IkTarget target;
      target.effector = 2;
      target.position = glm::vec3(t, 0.0f);
      target.hasPole = true;
      target.pole = elbow * 3.0f;  // beyond the wanted elbow: selects this solution
      p.targets.push_back(target);
      const IkResult r = solveTwoBone(p, IkSettings{});
      ASSERT_TRUE(r.message.empty()) << r.message;
      EXPECT_TRUE(r.converged);
      EXPECT_NEAR(wrap(zAngle(pose.local[0].rotation) - t1), 0.0f, 1e-4f) << "t1 for sign " << sign;
      EXPECT_NEAR(wrap(zAngle(pose.local[1].rotation) - t2), 0.0f, 1e-4f) << "t2 for sign " << sign;
      EXPECT_VEC3_NEAR(test::worldPosition(s, pose, 1), elbow, 1e-5f);
      EXPECT_VEC3_NEAR(test::worldPosition(s, pose, 2), glm::vec3(t, 0.0f), 1e-5f);
    }
  }
}

TEST(TwoBone, UnreachableStraightensTowardsTargetAndSaysSo) {
  const Skeleton s = planarArm(1.0f, 1.0f);
  Pose pose = Pose::rest(s);
  pose.local[1].rotation = glm::angleAxis(1.0f, glm::vec3(0, 0, 1));
  IkProblem p;
  p.skeleton = &s;
  p.pose = &pose;
  p.targets.push_back({});
  p.targets[0].effector = 2;
  p.targets[0].position = glm::vec3(0.0f, 3.0f, 4.0f);  // 5 away, reach 2
  const IkResult r = solveTwoBone(p, IkSettings{});
  EXPECT_FALSE(r.converged);
  EXPECT_NEAR(r.error, 3.0f, 1e-5f);
  EXPECT_VEC3_NEAR(test::worldPosition(s, pose, 2), glm::vec3(0.0f, 1.2f, 1.6f), 1e-5f);
  EXPECT_VEC3_NEAR(test::worldPosition(s, pose, 1), glm::vec3(0.0f, 0.6f, 0.8f), 1e-5f);
}

TEST(TwoBone, SoftenStopsShortOfFullExtension) {
  const Skeleton s = planarArm(1.0f, 1.0f);
  Pose pose = Pose::rest(s);
  pose.local[1].rotation = glm::angleAxis(1.0f, glm::vec3(0, 0, 1));
  IkProblem p;
  p.skeleton = &s;
  p.pose = &pose;
  p.targets.push_back({});
  p.targets[0].effector = 2;
  p.targets[0].position = glm::vec3(2.0f, 0.0f, 0.0f);  // exactly at full reach
  IkSettings settings;
  settings.twoBoneSoften = 0.1f;
  solveTwoBone(p, settings);
  // da = 1.9; softened = 1.9 + 0.1 * (1 - e^-1) by the soft-IK formula.
  EXPECT_NEAR(glm::length(test::worldPosition(s, pose, 2)), 1.9f + 0.1f * (1.0f - std::exp(-1.0f)), 1e-5f);
}

TEST(TwoBone, IntermediateJointsStayRigid) {
  // shoulder -> upper-twist -> elbow -> fore-twist -> hand: the twist joints do not turn.
  Skeleton s;
  s.addJoint("shoulder", -1, Transform::identity());
  s.addJoint("upper", 0, Transform::fromTranslation({0.5f, 0.0f, 0.0f}));
  s.addJoint("elbow", 1, Transform::fromTranslation({0.5f, 0.2f, 0.0f}));
  s.addJoint("fore", 2, Transform::fromTranslation({0.4f, 0.0f, 0.0f}));
  s.addJoint("hand", 3, Transform::fromTranslation({0.4f, 0.0f, 0.1f}));
  Pose pose = Pose::rest(s);
  pose.local[1].rotation = glm::angleAxis(0.3f, glm::normalize(glm::vec3(1, 1, 0)));
  pose.local[3].rotation = glm::angleAxis(-0.4f, glm::vec3(1, 0, 0));
  const Pose before = pose;
  IkProblem p;
  p.skeleton = &s;
  p.pose = &pose;
  IkTarget t;
  t.effector = 4;
  t.mid = 2;
  t.root = 0;
  t.position = glm::vec3(0.6f, 0.9f, 0.3f);
  p.targets.push_back(t);
  const IkResult r = solveTwoBone(p, IkSettings{});
  ASSERT_TRUE(r.message.empty()) << r.message;
  EXPECT_TRUE(r.converged) << r.error;
  EXPECT_VEC3_NEAR(test::worldPosition(s, pose, 4), t.position, 1e-5f);
  EXPECT_EQ(pose.local[1].rotation, before.local[1].rotation);
  EXPECT_EQ(pose.local[3].rotation, before.local[3].rotation);
  EXPECT_LE(test::boneLengthChange(s, before, pose), 1e-5f);
}

TEST(TwoBone, OrientationTargetSetsTheEffectorsWorldRotation) {
  const Skeleton s = planarArm(1.0f, 1.0f);
  Pose pose = Pose::rest(s);
  pose.local[1].rotation = glm::angleAxis(0.5f, glm::vec3(0, 0, 1));
  IkProblem p;
  p.skeleton = &s;
  p.pose = &pose;
  IkTarget t;
  t.effector = 2;
  t.position = glm::vec3(1.0f, 1.0f, 0.0f);
  t.hasOrientation = true;
  t.orientation = glm::angleAxis(0.7f, glm::normalize(glm::vec3(1, 2, 3)));
  p.targets.push_back(t);
  solveTwoBone(p, IkSettings{});
  const glm::mat4 w = computeWorld(s, pose)[2];
  EXPECT_SAME_ROTATION(glm::quat_cast(glm::mat3(w)), t.orientation, 1e-5f);
  EXPECT_VEC3_NEAR(glm::vec3(w[3]), t.position, 1e-5f);
}

TEST(TwoBone, NeedsAMiddleJoint) {
  const Skeleton s = planarArm(1.0f, 1.0f);
  Pose pose = Pose::rest(s);
  IkProblem p;
  p.skeleton = &s;
  p.pose = &pose;
  p.targets.push_back({});
  p.targets[0].effector = 1;  // only one bone above it
  const IkResult r = solveTwoBone(p, IkSettings{});
  EXPECT_NE(r.message.find("root"), std::string::npos) << r.message;
}

}  // namespace
}  // namespace kinema
