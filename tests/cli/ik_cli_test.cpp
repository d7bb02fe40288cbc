// `kinema ik` on a real BVH skeleton from ../shared/data/bvh.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "test_support.h"

namespace kinema {
namespace KINEMA_UNITY_ID {

using Json = nlohmann::json;

std::string bvh() { return test::sharedDataDir() + "/bvh/games105_walk60.bvh"; }

Json runJson(const std::string& args, int* rc = nullptr) {
  std::string out, err;
  const int code = test::runCommand(std::string(KINEMA_BINARY) + " " + args, &out, &err);
  if (rc) *rc = code;
  return code == 0 ? Json::parse(out) : Json();
}

glm::vec3 positionOf(const Json& joints, const std::string& name) {
  for (const Json& j : joints)
    if (j["name"] == name) return {j["world"][12].get<float>(), j["world"][13].get<float>(), j["world"][14].get<float>()};
  ADD_FAILURE() << "no joint " << name;
  return glm::vec3(0.0f);
}

TEST(IkCommand, ReachesATargetOnARealSkeletonAndKeepsTheRest) {
  KINEMA_REQUIRE_SHARED_DATA();
  const Json base = runJson("pose " + bvh() + " --frame 0 --json");
  const glm::vec3 hand = positionOf(base["joints"], "lWrist");
  const glm::vec3 target = hand + glm::vec3(0.05f, 0.1f, -0.05f);
  const std::string t = std::to_string(target.x) + "," + std::to_string(target.y) + "," + std::to_string(target.z);
  for (const char* solver : {"ccd", "fabrik", "jacobian-pinv", "jacobian-dls", "jacobian-sdls", "two-bone"}) {
    const Json out = runJson("ik " + bvh() + " --frame 0 --effector lWrist --target " + t + " --root lShoulder --solver " +
                             solver + " --tolerance 0.0005 --json");
    ASSERT_TRUE(out.is_object()) << solver;
    EXPECT_EQ(out["solver"], solver);
    EXPECT_TRUE(out["converged"].get<bool>()) << solver << " error " << out["error"];
    EXPECT_LE(glm::length(positionOf(out["joints"], "lWrist") - target), 0.0006f) << solver;
    // The IK root and everything outside its sub-tree stay where the pose put them.
    for (const char* still : {"lShoulder", "RootJoint", "rWrist", "lToeJoint"})
      EXPECT_VEC3_NEAR(positionOf(out["joints"], still), positionOf(base["joints"], still), 1e-5f);
    // Bone lengths along the arm are unchanged.
    const glm::vec3 s0 = positionOf(base["joints"], "lShoulder"), e0 = positionOf(base["joints"], "lElbow");
    const glm::vec3 s1 = positionOf(out["joints"], "lShoulder"), e1 = positionOf(out["joints"], "lElbow");
    EXPECT_NEAR(glm::length(e1 - s1), glm::length(e0 - s0), 1e-5f);
  }
}

TEST(IkCommand, TwoEffectorGroupsAndTrace) {
  KINEMA_REQUIRE_SHARED_DATA();
  const Json base = runJson("pose " + bvh() + " --frame 0 --json");
  const glm::vec3 l = positionOf(base["joints"], "lWrist") + glm::vec3(0.0f, 0.1f, 0.0f);
  const glm::vec3 r = positionOf(base["joints"], "rWrist") + glm::vec3(0.0f, 0.1f, 0.0f);
  auto fmt = [](const glm::vec3& v) { return std::to_string(v.x) + "," + std::to_string(v.y) + "," + std::to_string(v.z); };
  const Json out = runJson("ik " + bvh() + " --frame 0 --solver jacobian-dls --max-iterations 300 --effector lWrist --target " +
                           fmt(l) + " --root pelvis_lowerback --effector rWrist --target " + fmt(r) +
                           " --root pelvis_lowerback --trace --json");
  ASSERT_TRUE(out.is_object());
  EXPECT_TRUE(out["converged"].get<bool>()) << out["error"];
  EXPECT_LE(glm::length(positionOf(out["joints"], "lWrist") - l), 1.1e-3f);
  EXPECT_LE(glm::length(positionOf(out["joints"], "rWrist") - r), 1.1e-3f);
  ASSERT_TRUE(out["trace"].is_array());
  ASSERT_FALSE(out["trace"].empty());
  EXPECT_EQ(out["trace"][0]["positions"].size(), out["trace_joints"].size());
  EXPECT_EQ(out["trace"].back()["iteration"], out["iterations"]);
}

TEST(IkCommand, BadInputExitsOneAndBadUsageTwo) {
  KINEMA_REQUIRE_SHARED_DATA();
  int rc = 0;
  std::string out, err;
  rc = test::runCommand(std::string(KINEMA_BINARY) + " ik " + bvh() + " --effector lWrist --target nan,0,0 --json", &out, &err);
  EXPECT_EQ(rc, 1);
  EXPECT_NE(err.find("finite"), std::string::npos) << err;
  rc = test::runCommand(std::string(KINEMA_BINARY) + " ik " + bvh() + " --effector nobody --target 0,0,0", &out, &err);
  EXPECT_EQ(rc, 1);
  EXPECT_NE(err.find("nobody"), std::string::npos) << err;
  rc = test::runCommand(std::string(KINEMA_BINARY) + " ik " + bvh() + " --effector lWrist --target 1,2", &out, &err);
  EXPECT_EQ(rc, 2);
  rc = test::runCommand(std::string(KINEMA_BINARY) + " ik " + bvh() + " --effector lWrist --target 0,0,0 --solver magic", &out, &err);
  EXPECT_EQ(rc, 2);
  rc = test::runCommand(std::string(KINEMA_BINARY) + " ik " + bvh() + " --effector lWrist --target 0,0,0 --root rWrist", &out, &err);
  EXPECT_EQ(rc, 1);
  EXPECT_NE(err.find("not an ancestor"), std::string::npos) << err;
}

}  // namespace
}  // namespace kinema
