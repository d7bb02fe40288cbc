// `kinema retarget`: exit codes, one-line errors, nothing written on failure, the JSON
// report's shape, and that the saved file plays the clip on the target's skeleton.
#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>
#include <nlohmann/json.hpp>

#include "anim/sampling.h"
#include "core/default_character.h"
#include "core/forward_kinematics.h"
#include "io/kinema_file.h"
#include "io/scene_files.h"
#include "retarget/retarget_test_support.h"
#include "test_support.h"

namespace kinema::test {
namespace KINEMA_UNITY_ID {

class RetargetCli : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = makeTempDir();
    ASSERT_FALSE(dir_.empty());
    // A take on the default character's skeleton, saved as a source file.
    Scene scene;
    scene.skeleton = makeDefaultCharacter();
    std::mt19937 rng(11);
    scene.clips.push_back(makeSmoothTake(scene.skeleton, 40, rng, 0.3f));
    take_ = dir_ + "/take.kinema";
    ASSERT_EQ(saveKinemaFile(take_, scene), "");
  }
  void TearDown() override { std::system(("rm -rf '" + dir_ + "'").c_str()); }
  int kinema(const std::string& args) { return runCommand(std::string(KINEMA_BINARY) + " retarget " + args, &out_, &err_); }
  static int lines(const std::string& s) { return static_cast<int>(std::count(s.begin(), s.end(), '\n')); }
  bool exists(const std::string& path) { return std::ifstream(path).good(); }
  std::string dir_, take_, out_, err_;
};

TEST_F(RetargetCli, OntoTheDefaultCharacterWithReport) {
  const std::string out = dir_ + "/out.kinema";
  ASSERT_EQ(kinema("'" + take_ + "' --out '" + out + "' --fix-feet --reduce 0.005,1 --json"), 0) << err_;
  const nlohmann::json j = nlohmann::json::parse(out_);
  for (const char* key : {"source", "target", "out", "clip", "frames", "mapBy", "map", "humanoidBones", "unmapped",
                          "rootScale", "contacts", "footSkate", "keys", "reductionError"})
    EXPECT_TRUE(j.contains(key)) << key;
  EXPECT_TRUE(j["target"].is_null());
  EXPECT_EQ(j["frames"], 40);
  EXPECT_EQ(j["mapBy"], "names");
  EXPECT_EQ(j["map"]["UpperArm.L"], "UpperArm.L");
  EXPECT_EQ(j["humanoidBones"]["LeftUpperArm"]["target"], "UpperArm.L");
  EXPECT_TRUE(j["unmapped"]["source"].is_array());
  EXPECT_NE(std::find(j["unmapped"]["target"].begin(), j["unmapped"]["target"].end(), "HeadTop"),
            j["unmapped"]["target"].end());
  EXPECT_NEAR(j["rootScale"].get<double>(), 1.0, 1e-6);
  EXPECT_TRUE(j["contacts"]["left"].is_array());
  EXPECT_TRUE(j["footSkate"]["before"].is_number());
  EXPECT_LE(j["footSkate"]["after"].get<double>(), j["footSkate"]["before"].get<double>() + 1e-9);
  EXPECT_LT(j["keys"]["after"].get<int>(), j["keys"]["before"].get<int>());
  EXPECT_LE(j["reductionError"]["position"].get<double>(), 0.005);
  EXPECT_LE(j["reductionError"]["degrees"].get<double>(), 1.0 + 1e-6);
  // The file: the default character (with its body) playing one clip.
  const Result<Scene> saved = loadKinemaFile(out);
  ASSERT_TRUE(saved.ok()) << saved.error();
  EXPECT_EQ(saved->skeleton.names, makeDefaultCharacter().names);
  EXPECT_FALSE(saved->meshes.empty());
  ASSERT_EQ(saved->clips.size(), 1u);
}

TEST_F(RetargetCli, EveryOutputFormat) {
  for (const char* ext : {".glb", ".gltf", ".bvh"}) {
    const std::string out = dir_ + "/out" + ext;
    EXPECT_EQ(kinema("'" + take_ + "' --out '" + out + "' --in-place"), 0) << ext << ": " << err_;
    EXPECT_TRUE(exists(out)) << ext;
  }
}

TEST_F(RetargetCli, UsageErrorsExitTwo) {
  const std::string out = dir_ + "/out.kinema";
  EXPECT_EQ(kinema("'" + take_ + "' --out '" + dir_ + "/out.obj'"), 2);
  EXPECT_EQ(lines(err_), 1) << err_;
  EXPECT_NE(err_.find("see --help"), std::string::npos);
  EXPECT_EQ(kinema("'" + take_ + "' --out '" + out + "' --reduce fast"), 2);
  EXPECT_EQ(lines(err_), 1) << err_;
  EXPECT_EQ(kinema("'" + take_ + "'"), 2);  // no --out
  EXPECT_EQ(kinema("'" + take_ + "' --out '" + out + "' --wobble"), 2);
  EXPECT_FALSE(exists(out));
}

TEST_F(RetargetCli, BadInputExitsOneWithOneLineAndWritesNothing) {
  const std::string out = dir_ + "/out.kinema";
  auto expectBad = [&](const std::string& args, const std::string& mention) {
    EXPECT_EQ(kinema(args + " --out '" + out + "'"), 1) << args;
    EXPECT_EQ(lines(err_), 1) << err_;
    EXPECT_NE(err_.find(mention), std::string::npos) << err_;
    EXPECT_FALSE(exists(out)) << args;
  };
  expectBad("'" + dir_ + "/missing.bvh'", "missing.bvh");
  expectBad("'" + take_ + "' --reduce -1", "--reduce");
  expectBad("'" + take_ + "' --clip 5", "--clip 5");
  expectBad("'" + take_ + "' --clip nope", "--clip nope");
  writeFile(dir_ + "/map.json", R"({"Hips": "Hips", "Spine": "NoSuchJoint"})");
  expectBad("'" + take_ + "' --map '" + dir_ + "/map.json'", "map.json: \"Spine\"");
  writeFile(dir_ + "/bad.json", "{\"Hips\": ");
  expectBad("'" + take_ + "' --map '" + dir_ + "/bad.json'", "bad.json: not valid JSON: line 1");
  // A source without motion, and a skeleton that is no humanoid (one chain).
  Scene still;
  still.skeleton = makeDefaultCharacter();
  ASSERT_EQ(saveKinemaFile(dir_ + "/still.kinema", still), "");
  expectBad("'" + dir_ + "/still.kinema'", "still.kinema: has no clip");
  Scene rope;
  rope.skeleton.addJoint("a", -1, Transform::fromTranslation({0, 1, 0}));
  rope.skeleton.addJoint("b", 0, Transform::fromTranslation({0, 1, 0}));
  ASSERT_EQ(saveKinemaFile(dir_ + "/rope.kinema", rope), "");
  expectBad("'" + take_ + "' '" + dir_ + "/rope.kinema'", "rope.kinema: no humanoid found");
  // Zero-length legs: the default character squashed flat.
  Scene flat;
  flat.skeleton = makeDefaultCharacter();
  for (Transform& t : flat.skeleton.rest) t.translation.y = 0.0f;
  ASSERT_EQ(saveKinemaFile(dir_ + "/flat.kinema", flat), "");
  EXPECT_EQ(kinema("'" + take_ + "' '" + dir_ + "/flat.kinema' --out '" + out + "'"), 1);
  EXPECT_EQ(lines(err_), 1) << err_;
  EXPECT_FALSE(exists(out));
  // A hand-written map whose hierarchy is upside down.
  writeFile(dir_ + "/upside.json", R"({"UpperArm.L": "LowerArm.L", "LowerArm.L": "UpperArm.L"})");
  expectBad("'" + take_ + "' --map '" + dir_ + "/upside.json'", "incompatible skeletons");
}

TEST_F(RetargetCli, HandWrittenMapWithCanonicalNames) {
  writeFile(dir_ + "/map.json", R"({"LeftUpperArm": "UpperArm.L", "LowerArm.L": "LeftLowerArm", "Hips": "Hips"})");
  ASSERT_EQ(kinema("'" + take_ + "' --map '" + dir_ + "/map.json' --out '" + dir_ + "/o.kinema' --json"), 0) << err_;
  const nlohmann::json j = nlohmann::json::parse(out_);
  EXPECT_EQ(j["mapBy"], "file");
  EXPECT_EQ(j["map"].size(), 3u);
  EXPECT_EQ(j["map"]["LowerArm.L"], "LowerArm.L");
}

TEST_F(RetargetCli, SharedTakesOntoTheDefaultCharacter) {
  KINEMA_REQUIRE_SHARED_DATA();
  for (const char* file : {"bvh/cmu_01_01_first720.bvh", "bvh/games105_walk60.bvh", "bvh/mocapbank_test.bvh",
                           "gltf/CesiumMan.glb"}) {
    ASSERT_EQ(kinema("'" + sharedDataDir() + "/" + file + "' --out '" + dir_ + "/o.glb' --fix-feet --json"), 0)
        << file << ": " << err_;
    const nlohmann::json j = nlohmann::json::parse(out_);
    EXPECT_GE(j["map"].size(), 15u) << file;
    EXPECT_LE(j["footSkate"]["after"].get<double>(), j["footSkate"]["before"].get<double>() + 1e-9) << file;
  }
}

// Planted feet land on the character's floor: over each shared take retargeted onto the
// default character, the lowest foot or toe joint comes exactly as low as the character's
// rest feet (1e-4 of its height). Scaling the hips about the origin instead left the CMU
// take's feet 10 cm above it, and the hip-height ratio alone 5 cm.
TEST_F(RetargetCli, PlantedFeetLandOnTheCharactersFloor) {
  KINEMA_REQUIRE_SHARED_DATA();
  const Skeleton character = makeDefaultCharacter();
  const std::vector<glm::mat4> rest = computeWorld(character, Pose::rest(character));
  std::vector<int> feet;
  for (int j = 0; j < character.size(); ++j)
    if (character.names[j].rfind("Foot.", 0) == 0 || character.names[j].rfind("Toe.", 0) == 0) feet.push_back(j);
  ASSERT_GE(feet.size(), 2u);
  float restLowest = 1e9f, top = -1e9f;
  for (int j : feet) restLowest = std::min(restLowest, rest[j][3].y);
  for (const glm::mat4& w : rest) top = std::max(top, w[3].y);
  for (const char* file : {"bvh/cmu_01_01_first720.bvh", "bvh/games105_walk60.bvh", "bvh/mocapbank_test.bvh"}) {
    SCOPED_TRACE(file);
    const std::string out = dir_ + "/floor.kinema";
    ASSERT_EQ(kinema("'" + sharedDataDir() + "/" + file + "' --out '" + out + "'"), 0) << err_;
    const Result<Scene> scene = loadScene(out);
    ASSERT_TRUE(scene.ok()) << scene.error();
    ASSERT_EQ(scene->skeleton.names, character.names);
    ASSERT_FALSE(scene->clips.empty());
    const Clip& clip = scene->clips[0];
    float lowest = 1e9f;
    for (long long f = 0, n = ownFrameGrid(clip).nearestFrame(clip.duration()); f <= n; ++f) {
      Pose pose = Pose::rest(scene->skeleton);
      sampleClip(clip, ownFrameGrid(clip).frameToTime(f), pose);
      const std::vector<glm::mat4> world = computeWorld(scene->skeleton, pose);
      for (int j : feet) lowest = std::min(lowest, world[j][3].y);
    }
    EXPECT_NEAR(lowest, restLowest, 1e-4f * (top - restLowest));
  }
}

// Issue 38's report: frame 240 of a 120 fps take, retargeted and saved as glTF (which keeps no
// rate of its own), is the take's 2.0 s, not 240 frames at a fallback rate.
TEST_F(RetargetCli, TheOutputKeepsTheSourcesFrameRate) {
  KINEMA_REQUIRE_SHARED_DATA();
  const std::string source = sharedDataDir() + "/bvh/cmu_01_01_first720.bvh";
  const std::string target = sharedDataDir() + "/gltf/CesiumMan.glb";
  for (const char* ext : {".glb", ".kinema"}) {
    const std::string out = dir_ + "/onto" + ext;
    ASSERT_EQ(kinema("'" + source + "' '" + target + "' --out '" + out + "'"), 0) << err_;
    std::string json;
    ASSERT_EQ(runCommand(std::string(KINEMA_BINARY) + " pose '" + source + "' --frame 240 --json", &json), 0);
    const double sourceTime = nlohmann::json::parse(json)["time"].get<double>();
    EXPECT_NEAR(sourceTime, 240 * 0.0083333, 1e-9);  // the file's Frame Time
    ASSERT_EQ(runCommand(std::string(KINEMA_BINARY) + " pose '" + out + "' --frame 240 --json", &json), 0);
    EXPECT_DOUBLE_EQ(nlohmann::json::parse(json)["time"].get<double>(), sourceTime) << ext;
    Result<Scene> back = loadScene(out);
    ASSERT_TRUE(back.ok()) << back.error();
    EXPECT_NEAR(back->clips[0].frameTime, 0.0083333, 1e-12) << ext;
  }
}

}  // namespace
}  // namespace kinema::test
