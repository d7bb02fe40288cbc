// `kinema simulate` on a file's crowds: a .kinema out gets one clip per member that replays
// the crowd (members apart by the separation distance, hips at the character's height); a
// glTF out one skinned character per member ("crowd_0007/Hips"); the JSON report names each
// crowd and its members; BVH and other files' characters in a .kinema out are refused in one
// line with nothing written.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <nlohmann/json.hpp>

#include "anim/sampling.h"
#include "io/image.h"
#include "io/kinema_file.h"
#include "io/scene_files.h"
#include "scene/default_character_scene.h"
#include "cli/simulate_cli_fixture.h"
#include "test_support.h"

namespace kinema::test {
namespace KINEMA_UNITY_ID {

// The default character (skinned) with a 1 s walk at 30 fps that moves its hips 1.2 m along
// +Z and swings its upper legs; one crowd of `members` of itself around a sphere.
Scene crowdFile(int members) {
  Scene scene = makeDefaultCharacterScene();
  const Skeleton& s = scene.skeleton;
  Clip clip;
  clip.name = "walk";
  clip.frameTime = 1.0 / 30.0;
  const int hips = s.find("Hips");
  const glm::vec3 rest = s.rest[hips].translation;
  clip.channels.emplace_back(hips, ChannelTarget::Translation, Interpolation::Linear, std::vector<float>{0.0f, 1.0f},
                             std::vector<glm::vec4>{{rest, 0}, {rest + glm::vec3(0, 0, 1.2f), 0}});
  const glm::quat a = glm::angleAxis(0.5f, glm::vec3(1, 0, 0)), b = glm::angleAxis(-0.5f, glm::vec3(1, 0, 0));
  clip.channels.emplace_back(s.find("UpperLeg.L"), ChannelTarget::Rotation, Interpolation::Linear,
                             std::vector<float>{0.0f, 0.5f, 1.0f},
                             std::vector<glm::vec4>{{a.x, a.y, a.z, a.w}, {b.x, b.y, b.z, b.w}, {a.x, a.y, a.z, a.w}});
  scene.clips.push_back(clip);
  CrowdSettings crowd;
  crowd.members = members;
  crowd.seed = 11;
  crowd.spawnCentre = glm::vec3(-6, 0, 0);
  crowd.boids.hasGoal = true;
  crowd.boids.goal = glm::vec3(8, 0, 0);
  crowd.boids.spheres.push_back({glm::vec3(1, 0, 0), 1.5f});
  scene.simulation.crowds.push_back(crowd);
  return scene;
}

class CrowdCli : public test::SimulateCliFixture {
};

TEST_F(CrowdCli, AKinemaOutGetsAClipPerMemberThatReplaysTheCrowd) {
  const Scene scene = crowdFile(10);
  const std::string in = save(scene, "crowd.kinema"), out = dir_ + "/baked.kinema";
  ASSERT_EQ(kinema("'" + in + "' --frames 0:45 --out '" + out + "' --json"), 0) << err_;
  const nlohmann::json j = nlohmann::json::parse(out_);
  ASSERT_EQ(j["parts"].size(), 1u);
  const nlohmann::json& part = j["parts"][0];
  EXPECT_EQ(part["kind"], "crowd");
  EXPECT_EQ(part["name"], "crowd");
  EXPECT_EQ(part["members"], 10);
  EXPECT_EQ(part["clip"], "walk");
  EXPECT_EQ(part["frames"], nlohmann::json::array({0, 45}));
  ASSERT_EQ(part["clips"].size(), 10u);
  EXPECT_EQ(part["clips"][7], "crowd_0007");

  Result<Scene> back = loadScene(out);
  ASSERT_TRUE(back) << back.error();
  ASSERT_EQ(back->clips.size(), 11u);  // the walk, then a clip per member
  EXPECT_EQ(back->clips[8].name, "crowd_0007");
  EXPECT_EQ(back->simulation.crowds.size(), 1u) << "the settings stay in the file";
  const int hips = scene.skeleton.find("Hips");
  const float height = scene.skeleton.rest[hips].translation.y;
  const float separation = scene.simulation.crowds[0].boids.separationDistance;
  for (int f = 0; f <= 45; f += 5) {
    std::vector<glm::vec3> at;
    for (int m = 0; m < 10; ++m) {
      const Clip& c = back->clips[1 + m];
      Pose pose = Pose::rest(back->skeleton);
      sampleClip(c, ownFrameGrid(c).frameToTime(f), pose);
      // The walk's drift is taken out: the hips keep the character's height, on the ground plane.
      EXPECT_NEAR(pose.local[hips].translation.y, height, 1e-4f);
      at.push_back(pose.local[hips].translation);
    }
    for (int a = 0; a < 10; ++a)
      for (int b = a + 1; b < 10; ++b) EXPECT_GE(glm::distance(at[a], at[b]), separation) << "frame " << f;
  }
}

TEST_F(CrowdCli, AGlbOutHasASkinnedCharacterPerMember) {
  const Scene scene = crowdFile(6);
  const std::string in = save(scene, "crowd.kinema"), out = dir_ + "/crowd.glb";
  ASSERT_EQ(kinema("'" + in + "' --frames 0:20 --out '" + out + "' --json"), 0) << err_;
  const nlohmann::json j = nlohmann::json::parse(out_);
  ASSERT_EQ(j["parts"][0]["characters"].size(), 6u);
  Result<Scene> back = loadScene(out);
  ASSERT_TRUE(back) << back.error();
  const int joints = scene.skeleton.size();
  EXPECT_EQ(back->skeleton.size(), 6 * joints + 1) << "six characters and the obstacles' joint";
  EXPECT_GE(back->skeleton.find("crowd_0005/Hips"), 0);
  EXPECT_GE(back->skeleton.find("crowd_obstacles"), 0);
  EXPECT_EQ(back->skins.size(), 6 * scene.skins.size());
  EXPECT_EQ(back->meshInstances.size(), 6 * scene.meshInstances.size() + 1);
  EXPECT_EQ(back->meshes.size(), scene.meshes.size() + 1) << "the body is written once, shown six times; the sphere";
  ASSERT_EQ(back->clips.size(), 1u);
  // Every member's hips move: the glTF clip carries each member's keys.
  for (int m = 0; m < 6; ++m) {
    const int h = back->skeleton.find("crowd_000" + std::to_string(m) + "/Hips");
    ASSERT_GE(h, 0);
    EXPECT_TRUE(std::any_of(back->clips[0].channels.begin(), back->clips[0].channels.end(),
                            [&](const Channel& c) { return c.joint == h && c.target == ChannelTarget::Translation; }));
  }
}

TEST_F(CrowdCli, BvhAndOtherFilesCharactersInAKinemaOutAreRefused) {
  Scene scene = crowdFile(4);
  const std::string in = save(scene, "crowd.kinema");
  EXPECT_NE(kinema("'" + in + "' --out '" + dir_ + "/x.bvh'"), 0);
  EXPECT_NE(err_.find("BVH file holds one skeleton"), std::string::npos) << err_;
  EXPECT_EQ(std::count(err_.begin(), err_.end(), '\n'), 1) << err_;
  EXPECT_FALSE(exists(dir_ + "/x.bvh"));

  // A crowd of another file's character: its member clips cannot go into this skeleton...
  const std::string character = save(crowdFile(1), "walker.kinema");
  scene.simulation.crowds[0].character = "walker.kinema";  // relative to the crowd's file
  const std::string other = save(scene, "other.kinema");
  EXPECT_NE(kinema("'" + other + "' --out '" + dir_ + "/y.kinema'"), 0);
  EXPECT_NE(err_.find("its character is another file"), std::string::npos) << err_;
  EXPECT_FALSE(exists(dir_ + "/y.kinema"));
  // ...but go out as characters of their own.
  ASSERT_EQ(kinema("'" + other + "' --frames 0:10 --out '" + dir_ + "/y.glb'"), 0) << err_;
  Result<Scene> back = loadScene(dir_ + "/y.glb");
  ASSERT_TRUE(back) << back.error();
  EXPECT_GE(back->skeleton.find("crowd_0003/Hips"), 0);
  // A missing character file is one line naming the crowd.
  scene.simulation.crowds[0].character = "nowhere.kinema";
  const std::string missing = save(scene, "missing.kinema");
  EXPECT_NE(kinema("'" + missing + "' --out '" + dir_ + "/z.glb'"), 0);
  EXPECT_NE(err_.find("crowd 'crowd': character:"), std::string::npos) << err_;
  EXPECT_FALSE(exists(dir_ + "/z.glb"));
}

}  // namespace
}  // namespace kinema::test

namespace kinema::test {
namespace KINEMA_UNITY_ID {

// --render draws the crowd: the members and the sphere, where `kinema render` of the same file
// draws the file's own character alone; so the two pictures of frame 1 differ in many pixels.
TEST_F(CrowdCli, RenderDrawsTheMembers) {
  const Scene scene = crowdFile(4);
  const std::string in = save(scene, "crowd.kinema");
  ASSERT_EQ(kinema("'" + in + "' --frames 0:1 --render '" + dir_ + "/frames' --size 200x150 --camera 0,60,20"), 0) << err_;
  for (int f = 0; f <= 1; ++f) {
    char name[32];
    std::snprintf(name, sizeof name, "/frames/frame_%04d.png", f);
    EXPECT_TRUE(exists(dir_ + name)) << name;
  }
  ASSERT_EQ(runCommand(std::string(KINEMA_BINARY) + " render '" + in + "' --frame 1 --size 200x150 --camera 0,60,20 --out '" +
                           dir_ + "/alone.png'",
                       &out_, &err_),
            0)
      << err_;
  Result<Image> crowd = loadPng(dir_ + "/frames/frame_0001.png"), alone = loadPng(dir_ + "/alone.png");
  ASSERT_TRUE(crowd && alone);
  ASSERT_EQ(crowd->rgba.size(), alone->rgba.size());
  size_t differing = 0;
  for (size_t i = 0; i + 3 < crowd->rgba.size(); i += 4)
    differing += std::abs(int(crowd->rgba[i]) - int(alone->rgba[i])) + std::abs(int(crowd->rgba[i + 1]) - int(alone->rgba[i + 1])) > 40;
  EXPECT_GT(differing, 200u) << "four members and a sphere are drawn, not the file's one character";
}

}  // namespace
}  // namespace kinema::test
