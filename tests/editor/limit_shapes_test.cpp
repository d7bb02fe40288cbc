// Joint-limit drawing geometry from src/ik/joint_limits.h limits.
#include "editor/viewport/limit_shapes.h"
#include "test_support.h"

namespace kinema::test {
namespace KINEMA_UNITY_ID {

constexpr float kPi = 3.14159265358979f;

TEST(LimitShapes, ConeRimLiesAtTheConeAngleAndSizeFromTheJoint) {
  LimitShapeJob job;
  job.limit = JointLimit::cone({0, 1, 0}, kPi / 3, 0, 0);
  job.jointPosition = {1, 0, 0};
  job.size = 2;
  LimitShape shape;
  ASSERT_TRUE(job.run(shape));
  ASSERT_EQ(shape.rims.size(), 1u);  // no twist range: no twist arc
  const LimitShape::Polyline& rim = shape.rims[0];
  EXPECT_TRUE(rim.closed);
  EXPECT_EQ(rim.points.size(), 32u);
  for (const glm::vec3& p : rim.points) {
    // 60 degrees from +Y at distance 2: height 2 cos 60 = 1, radius 2 sin 60 = sqrt 3.
    EXPECT_NEAR(p.y, 1.0f, 1e-5f);
    EXPECT_NEAR(glm::length(glm::vec2(p.x - 1, p.z)), std::sqrt(3.0f), 1e-5f);
  }
  ASSERT_EQ(shape.spokes.size(), 16u);  // 8 spokes from the joint
  for (size_t k = 0; k < shape.spokes.size(); k += 2) {
    EXPECT_VEC3_NEAR(shape.spokes[k], job.jointPosition, 0.0f);
    EXPECT_NEAR(glm::length(shape.spokes[k + 1] - job.jointPosition), 2.0f, 1e-5f);
  }
}

TEST(LimitShapes, RestFrameTurnsTheShape) {
  LimitShapeJob job;
  job.limit = JointLimit::cone({0, 1, 0}, kPi / 2, 0, 0);  // a half space: the rim is a great circle
  job.restFrameWorld = glm::angleAxis(kPi / 2, glm::vec3(0, 0, 1));  // rest Y -> world -X
  LimitShape shape;
  ASSERT_TRUE(job.run(shape));
  for (const glm::vec3& p : shape.rims[0].points) {
    EXPECT_NEAR(p.x, 0.0f, 1e-5f);  // perpendicular to the world axis (-1, 0, 0)
    EXPECT_NEAR(glm::length(p), 1.0f, 1e-5f);
  }
}

TEST(LimitShapes, ConeTwistArcSpansTheTwistRange) {
  LimitShapeJob job;
  job.limit = JointLimit::cone({0, 1, 0}, kPi / 4, -kPi / 2, kPi / 2);
  job.size = 2;
  LimitShape shape;
  ASSERT_TRUE(job.run(shape));
  ASSERT_EQ(shape.rims.size(), 2u);
  const LimitShape::Polyline& twist = shape.rims[1];
  EXPECT_FALSE(twist.closed);
  EXPECT_EQ(twist.points.size(), 17u);  // half a turn of 32 segments, plus the end point
  for (const glm::vec3& p : twist.points) {
    EXPECT_NEAR(p.y, 1.0f, 1e-5f);                              // halfway along the axis
    EXPECT_NEAR(glm::length(glm::vec2(p.x, p.z)), 0.5f, 1e-5f);  // a quarter of the size
  }
  EXPECT_NEAR(glm::length(twist.points.front() - twist.points.back()), 1.0f, 1e-5f);  // 180 degrees apart
  EXPECT_EQ(shape.spokes.size(), 16u + 4u);
}

// Hinge about X from 0 to 90 degrees, bone along +Y: the bone sweeps from +Y to X x Y = +Z.
TEST(LimitShapes, HingeArcSweepsTheBoneAboutTheAxis) {
  LimitShapeJob job;
  job.limit = JointLimit::hinge({1, 0, 0}, 0, kPi / 2);
  job.restBoneDirection = {0, 3, 0};
  LimitShape shape;
  ASSERT_TRUE(job.run(shape));
  ASSERT_EQ(shape.rims.size(), 1u);
  const LimitShape::Polyline& arc = shape.rims[0];
  EXPECT_VEC3_NEAR(arc.points.front(), glm::vec3(0, 1, 0), 1e-6f);
  EXPECT_VEC3_NEAR(arc.points.back(), glm::vec3(0, 0, 1), 1e-6f);
  EXPECT_EQ(arc.points.size(), 9u);
  for (const glm::vec3& p : arc.points) {
    EXPECT_NEAR(p.x, 0.0f, 1e-6f);
    EXPECT_NEAR(glm::length(p), 1.0f, 1e-5f);
  }
  EXPECT_EQ(shape.spokes.size(), 4u);  // joint -> both ends
}

TEST(LimitShapes, EulerGivesOneArcPerLimitedAxis) {
  LimitShapeJob job;
  job.limit = JointLimit::euler(EulerOrder::XYZ, {-0.5f, 0, 0}, {0.5f, 0, 1});
  LimitShape shape;
  ASSERT_TRUE(job.run(shape));
  ASSERT_EQ(shape.rims.size(), 2u);  // Y has no range
  EXPECT_EQ(shape.rims[0].axis, 0);
  EXPECT_EQ(shape.rims[1].axis, 2);
  for (const glm::vec3& p : shape.rims[1].points) EXPECT_NEAR(p.z, 0.0f, 1e-6f);  // arc about Z
}

TEST(LimitShapes, NoLimitDrawsNothingAndBadInputsAreRefused) {
  LimitShapeJob job;
  LimitShape shape;
  ASSERT_TRUE(job.run(shape));
  EXPECT_TRUE(shape.rims.empty() && shape.spokes.empty());
  job.limit = JointLimit::cone({0, 1, 0}, 0.5f, 0, 0);
  job.size = 0;
  EXPECT_FALSE(job.validate().empty());
  EXPECT_FALSE(job.run(shape));
  job.size = 1;
  job.jointPosition.x = std::nanf("");
  EXPECT_FALSE(job.validate().empty());
  job.jointPosition.x = 0;
  job.limit.coneAngle = 4.0f;  // > pi
  EXPECT_FALSE(job.validate().empty());
}

}  // namespace
}  // namespace kinema::test
