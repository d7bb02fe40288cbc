// The optional "pose" key of .kinema files (the editor's working pose): round trip bit for
// bit, absent means the rest pose, partial lists keep rest values, errors name the path.
#include <gtest/gtest.h>

#include <cstring>
#include <random>

#include "core/default_character.h"
#include "io/kinema_file.h"
#include "test_support.h"

namespace kinema {
namespace KINEMA_UNITY_ID {

TEST(KinemaFilePose, PoseRoundTripsBitForBit) {
  Scene scene;
  scene.skeleton = makeDefaultCharacter();
  std::mt19937 rng(7);
  std::uniform_real_distribution<float> u(-2.0f, 2.0f);
  scene.pose = Pose::rest(scene.skeleton);
  for (Transform& t : scene.pose.local) {
    t.rotation = test::randomRotation(rng);
    t.translation = {u(rng), u(rng), u(rng)};
    t.scale = {1.0f + 0.25f * u(rng), 1.0f, 0.5f};
  }
  const std::string text = toKinemaJson(scene);
  EXPECT_NE(text.find("\"pose\""), std::string::npos);
  Result<Scene> back = parseKinemaJson(text, "posed.kinema");
  ASSERT_TRUE(back) << back.error();
  ASSERT_EQ(back->pose.size(), scene.skeleton.size());
  for (int i = 0; i < scene.skeleton.size(); ++i)
    EXPECT_EQ(std::memcmp(&back->pose.local[i], &scene.pose.local[i], sizeof(Transform)), 0) << "joint " << i;
  // The rest pose itself is untouched by the pose.
  for (int i = 0; i < scene.skeleton.size(); ++i) EXPECT_EQ(back->skeleton.rest[i], scene.skeleton.rest[i]);
}

TEST(KinemaFilePose, AbsentPoseIsTheRestPoseAndNoKeyIsWritten) {
  Scene scene;
  scene.skeleton = makeDefaultCharacter();
  const std::string text = toKinemaJson(scene);
  EXPECT_EQ(text.find("\"pose\""), std::string::npos);
  Result<Scene> back = parseKinemaJson(text, "rest.kinema");
  ASSERT_TRUE(back) << back.error();
  EXPECT_TRUE(back->pose.local.empty());
}

TEST(KinemaFilePose, UnlistedJointsAndMembersKeepTheirRestValues) {
  const std::string text = R"({"format": "kinema", "version": 1,
    "skeleton": {"joints": [
      {"name": "a", "parent": -1, "translation": [1, 2, 3]},
      {"name": "b", "parent": 0, "translation": [0, 1, 0], "scale": [2, 2, 2]}]},
    "pose": [{"joint": "b", "rotation": [0, 0, 1, 0]}]})";
  Result<Scene> s = parseKinemaJson(text, "partial.kinema");
  ASSERT_TRUE(s) << s.error();
  ASSERT_EQ(s->pose.size(), 2);
  EXPECT_EQ(s->pose.local[0].translation, glm::vec3(1, 2, 3));           // unlisted joint: rest
  EXPECT_EQ(s->pose.local[1].translation, glm::vec3(0, 1, 0));           // unlisted member: rest
  EXPECT_EQ(s->pose.local[1].scale, glm::vec3(2, 2, 2));
  EXPECT_EQ(s->pose.local[1].rotation, glm::quat(0.0f, 0.0f, 0.0f, 1.0f));  // [x,y,z,w] = (0,0,1,0): w = 0, z = 1
}

TEST(KinemaFilePose, ErrorsNameTheJsonPath) {
  const std::string head = R"({"format": "kinema", "version": 1,
    "skeleton": {"joints": [{"name": "a", "parent": -1}]}, "pose": )";
  struct Case {
    const char* pose;
    const char* expected;
  } cases[] = {
      {R"({})", "p.kinema: pose: expected an array"},
      {R"([{"joint": "nope"}])", "p.kinema: pose[0].joint: no joint named 'nope'"},
      {R"([{"joint": "a"}, {"joint": "a"}])", "p.kinema: pose[1].joint: joint 'a' is listed twice"},
      {R"([{"joint": "a", "rotation": [0, 0, 0, 0]}])", "p.kinema: pose[0].rotation: zero quaternion"},
      {R"([{"joint": "a", "translation": [0, "x", 0]}])", "p.kinema: pose[0].translation[1]: expected a number"},
  };
  for (const Case& c : cases) {
    Result<Scene> s = parseKinemaJson(head + c.pose + "}", "p.kinema");
    ASSERT_FALSE(s) << c.pose;
    EXPECT_EQ(s.error().rfind(c.expected, 0), 0u) << s.error();
  }
}

}  // namespace
}  // namespace kinema
