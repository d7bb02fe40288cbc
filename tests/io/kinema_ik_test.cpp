// The optional "ik" key of .kinema files: limits and targets round-trip; files without
// it still load; errors name the JSON path.
#include <gtest/gtest.h>

#include "core/default_character.h"
#include "io/kinema_file.h"
#include "test_support.h"

namespace kinema {
namespace KINEMA_UNITY_ID {

TEST(KinemaFileIk, LimitsAndTargetsRoundTrip) {
  Scene scene;
  scene.skeleton = makeDefaultCharacter();
  const int n = scene.skeleton.size();
  const int elbow = scene.skeleton.find("LowerArm.L"), shoulder = scene.skeleton.find("UpperArm.L");
  const int hand = scene.skeleton.find("Hand.L");
  ASSERT_GE(elbow, 0);
  ASSERT_GE(hand, 0);
  scene.ik.setLimit(n, elbow, JointLimit::hinge({0, 1, 0}, 0.0f, 2.5f));
  scene.ik.setLimit(n, shoulder, JointLimit::cone({1, 0, 0}, 1.2f, -0.5f, 0.5f));
  scene.ik.setLimit(n, hand, JointLimit::euler(EulerOrder::ZXY, {-0.1f, -0.2f, -0.3f}, {0.1f, 0.2f, 0.3f}));
  IkTarget t;
  t.effector = hand;
  t.root = shoulder;
  t.position = {0.6f, 1.2f, 0.3f};
  t.hasOrientation = true;
  t.orientation = glm::angleAxis(0.5f, glm::vec3(0, 0, 1));
  t.hasPole = true;
  t.pole = {0.4f, 1.4f, -1.0f};
  t.weight = 2.0f;
  scene.ik.targets.push_back(t);
  const std::string text = toKinemaJson(scene);
  EXPECT_NE(text.find("\"ik\""), std::string::npos);
  Result<Scene> back = parseKinemaJson(text, "rig.kinema");
  ASSERT_TRUE(back) << back.error();
  const IkRig& r = back->ik;
  ASSERT_EQ(r.limits.size(), static_cast<size_t>(n));
  EXPECT_EQ(r.limits[elbow].type, JointLimitType::Hinge);
  EXPECT_NEAR(r.limits[elbow].maxAngle, 2.5f, 1e-5f);
  EXPECT_EQ(r.limits[shoulder].type, JointLimitType::Cone);
  EXPECT_NEAR(r.limits[shoulder].coneAngle, 1.2f, 1e-5f);
  EXPECT_NEAR(r.limits[shoulder].twistMin, -0.5f, 1e-5f);
  EXPECT_EQ(r.limits[hand].order, EulerOrder::ZXY);
  EXPECT_VEC3_NEAR(r.limits[hand].eulerMax, glm::vec3(0.1f, 0.2f, 0.3f), 1e-5f);
  EXPECT_FALSE(r.limits[0].active());
  ASSERT_EQ(r.targets.size(), 1u);
  EXPECT_EQ(r.targets[0].effector, hand);
  EXPECT_EQ(r.targets[0].root, shoulder);
  EXPECT_VEC3_NEAR(r.targets[0].position, t.position, 1e-6f);
  EXPECT_SAME_ROTATION(r.targets[0].orientation, t.orientation, 1e-6f);
  EXPECT_TRUE(r.targets[0].hasPole);
  EXPECT_FLOAT_EQ(r.targets[0].weight, 2.0f);
}

TEST(KinemaFileIk, FilesWithoutIkLoadAndDoNotGainTheKey) {
  Scene scene;
  scene.skeleton = makeDefaultCharacter();
  const std::string text = toKinemaJson(scene);
  EXPECT_EQ(text.find("\"ik\""), std::string::npos);
  Result<Scene> back = parseKinemaJson(text, "plain.kinema");
  ASSERT_TRUE(back) << back.error();
  EXPECT_TRUE(back->ik.empty());
}

TEST(KinemaFileIk, ErrorsNameTheJsonPath) {
  const std::string head = R"({"format":"kinema","version":1,"skeleton":{"joints":[{"name":"a","parent":-1},{"name":"b","parent":0}]},)";
  Result<Scene> r = parseKinemaJson(head + R"("ik":{"limits":[{"joint":"b","type":"spring"}]}})", "x.kinema");
  ASSERT_FALSE(r);
  EXPECT_NE(r.error().find("x.kinema: ik.limits[0].type"), std::string::npos) << r.error();
  r = parseKinemaJson(head + R"("ik":{"limits":[{"joint":"b","type":"hinge","axis":[0,0,1],"min_deg":10,"max_deg":-10}]}})", "x.kinema");
  ASSERT_FALSE(r);
  EXPECT_NE(r.error().find("ik.limits[0]"), std::string::npos) << r.error();
  r = parseKinemaJson(head + R"("ik":{"targets":[{"effector":"zz","position":[0,0,0]}]}})", "x.kinema");
  ASSERT_FALSE(r);
  EXPECT_NE(r.error().find("ik.targets[0].effector"), std::string::npos) << r.error();
}

// The editor's per-target options (solver, chain length, pinned, active) travel with the
// rig; a target without them reads as the defaults when another target has some.
TEST(KinemaFileIk, TargetOptionsRoundTrip) {
  const std::string head = R"({"format":"kinema","version":1,"skeleton":{"joints":[{"name":"a","parent":-1},{"name":"b","parent":0},{"name":"c","parent":1}]},)";
  Result<Scene> r = parseKinemaJson(head + R"("ik":{"targets":[{"effector":"c","position":[1,0,0]},)" +
                                        R"({"effector":"b","position":[0,1,0],"solver":"two-bone","chain_length":2,"pinned":true,"active":false}]}})",
                                    "o.kinema");
  ASSERT_TRUE(r) << r.error();
  ASSERT_EQ(r->ik.targetOptions.size(), 2u);
  EXPECT_EQ(r->ik.targetOptions[0].solver, IkSolver::JacobianDls);
  EXPECT_EQ(r->ik.targetOptions[0].chainLength, 0);
  EXPECT_FALSE(r->ik.targetOptions[0].pinned);
  EXPECT_TRUE(r->ik.targetOptions[0].active);
  EXPECT_EQ(r->ik.targetOptions[1].solver, IkSolver::TwoBone);
  EXPECT_EQ(r->ik.targetOptions[1].chainLength, 2);
  EXPECT_TRUE(r->ik.targetOptions[1].pinned);
  EXPECT_FALSE(r->ik.targetOptions[1].active);
  Result<Scene> back = parseKinemaJson(toKinemaJson(r.value()), "o2.kinema");
  ASSERT_TRUE(back) << back.error();
  ASSERT_EQ(back->ik.targetOptions.size(), 2u);
  EXPECT_EQ(back->ik.targetOptions[1].solver, IkSolver::TwoBone);
  EXPECT_EQ(back->ik.targetOptions[1].chainLength, 2);
  EXPECT_TRUE(back->ik.targetOptions[1].pinned);
  EXPECT_FALSE(back->ik.targetOptions[1].active);

  for (const char* bad : {R"("solver":"magic")", R"("chain_length":-1)", R"("chain_length":1.5)", R"("pinned":1)"}) {
    r = parseKinemaJson(head + R"("ik":{"targets":[{"effector":"c","position":[1,0,0],)" + bad + "}]}}", "x.kinema");
    ASSERT_FALSE(r) << bad;
    EXPECT_NE(r.error().find("x.kinema: ik.targets[0]."), std::string::npos) << r.error();
  }
}

}  // namespace
}  // namespace kinema
