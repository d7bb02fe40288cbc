// One frame rate through the files (issue 38): BVH keeps its Frame Time, glTF keeps a clip's
// rate in the animation's extras and the document's in the asset's, .kinema keeps both, and a
// foreign glTF counts on the grid its keys lie on.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "io/scene_files.h"
#include "test_support.h"

namespace kinema {
namespace KINEMA_UNITY_ID {

// A two-joint BVH of `frames` frames at `frameTime` seconds, the root moving 1 unit a frame.
std::string movingBvh(int frames, const char* frameTime) {
  std::string text =
      "HIERARCHY\nROOT Hips\n{\n  OFFSET 0 0 0\n  CHANNELS 6 Xposition Yposition Zposition Zrotation Xrotation Yrotation\n"
      "  JOINT Spine\n  {\n    OFFSET 0 1 0\n    CHANNELS 3 Zrotation Xrotation Yrotation\n"
      "    End Site\n    {\n      OFFSET 0 1 0\n    }\n  }\n}\nMOTION\nFrames: " +
      std::to_string(frames) + "\nFrame Time: " + frameTime + "\n";
  for (int f = 0; f < frames; ++f) text += std::to_string(f) + " 0 0 0 0 0 0 0 0\n";
  return text;
}

class FrameRateFiles : public ::testing::Test {
 protected:
  void SetUp() override { dir_ = test::makeTempDir(); }
  void TearDown() override { test::runCommand("rm -rf '" + dir_ + "'"); }
  std::string dir_;
};

TEST_F(FrameRateFiles, A120FpsBvhKeepsItsRateThroughGlbKinemaAndBack) {
  const std::string bvh = dir_ + "/fast.bvh";
  test::writeFile(bvh, movingBvh(241, "0.00833333"));
  Result<Scene> source = loadScene(bvh);
  ASSERT_TRUE(source.ok()) << source.error();
  ASSERT_NEAR(source->frameGrid(0).framesPerSecond(), 120.0, 1e-3);
  Scene scene = source.value();
  for (const char* step : {"/a.glb", "/b.kinema", "/c.gltf", "/d.bvh"}) {
    const std::string path = dir_ + step;
    ASSERT_EQ(saveScene(path, scene), "") << step;
    Result<Scene> back = loadScene(path);
    ASSERT_TRUE(back.ok()) << step << ": " << back.error();
    ASSERT_EQ(back->clips.size(), 1u) << step;
    // The file's own frame time, not a grid detected again (8.33333 ms is not 1/120 s exactly).
    EXPECT_NEAR(back->clips[0].frameTime, 0.00833333, 1e-12) << step;
    EXPECT_EQ(back->frameGrid(0).nearestFrame(back->clips[0].duration()), 240) << step;
    EXPECT_NEAR(back->frameGrid(0).frameToTime(240), 240 * 0.00833333, 1e-6) << step;
    scene = std::move(back.value());
  }
}

TEST_F(FrameRateFiles, TheDocumentsRateRoundTripsAndCountsClipsWithoutOne) {
  Scene scene;
  scene.skeleton.addJoint("root", -1, Transform::identity());
  scene.frameRate = 30.0;
  Clip clip;  // no rate of its own; its keys lie on the 30 fps grid only
  clip.channels.push_back(Channel(0, ChannelTarget::Translation, Interpolation::Linear, {0.0f, 0.1f, 0.7f},
                                  {glm::vec4(0.0f), glm::vec4(1.0f), glm::vec4(7.0f)}));
  scene.clips.push_back(clip);
  EXPECT_EQ(scene.frameGrid(0).nearestFrame(0.7), 21);
  for (const char* step : {"/a.kinema", "/b.glb"}) {
    const std::string path = dir_ + step;
    ASSERT_EQ(saveScene(path, scene), "") << step;
    Result<Scene> back = loadScene(path);
    ASSERT_TRUE(back.ok()) << step << ": " << back.error();
    EXPECT_EQ(back->frameRate, 30.0) << step;
    EXPECT_EQ(back->frameGrid(0).nearestFrame(0.7), 21) << step;
  }
  // The default rate is not written into .kinema files.
  scene.frameRate = kDefaultFrameRate;
  ASSERT_EQ(saveScene(dir_ + "/c.kinema", scene), "");
  EXPECT_EQ(test::readFile(dir_ + "/c.kinema").find("frame_rate"), std::string::npos);
}

TEST_F(FrameRateFiles, ABadFrameRateIsRefusedWithItsPlace) {
  const std::string path = dir_ + "/bad.kinema";
  test::writeFile(path, R"({"format":"kinema","version":1,"frame_rate":0,
    "skeleton":{"joints":[{"name":"Root","parent":-1,"translation":[0,0,0]}]},"clips":[]})");
  Result<Scene> bad = loadScene(path);
  ASSERT_FALSE(bad.ok());
  EXPECT_NE(bad.error().find("frame_rate"), std::string::npos) << bad.error();
  EXPECT_NE(bad.error().find("bad.kinema"), std::string::npos) << bad.error();
}

// A glTF whose writer kept no rate (no extras: as a foreign file) with keys every 1/30 s.
TEST_F(FrameRateFiles, AForeignGltfOnAThirtiethOfASecondGridCountsThirty) {
  Scene scene;
  scene.skeleton.addJoint("root", -1, Transform::identity());
  Clip clip;
  std::vector<float> times;
  std::vector<glm::vec4> values;
  for (int f = 0; f <= 60; ++f) times.push_back(static_cast<float>(f / 30.0)), values.push_back(glm::vec4(float(f)));
  clip.channels.push_back(Channel(0, ChannelTarget::Translation, Interpolation::Linear, times, values));
  scene.clips.push_back(clip);
  const std::string path = dir_ + "/foreign.gltf";
  ASSERT_EQ(saveScene(path, scene), "");
  // Written by another tool: no Kinema extras at all (the clip had no rate to write).
  nlohmann::json file = nlohmann::json::parse(test::readFile(path));
  ASSERT_EQ(file["animations"][0].count("extras"), 0u);
  file["asset"].erase("extras");
  test::writeFile(path, file.dump());
  Result<Scene> back = loadScene(path);
  ASSERT_TRUE(back.ok()) << back.error();
  EXPECT_EQ(back->clips[0].frameTime, 1.0 / 30.0);
  EXPECT_EQ(back->frameGrid(0).nearestFrame(1.0), 30);
}

TEST_F(FrameRateFiles, KhronosSamplesCountOnTheGridTheirKeysLieOn) {
  KINEMA_REQUIRE_SHARED_DATA();
  Result<Scene> cesium = loadScene(test::sharedDataDir() + "/gltf/CesiumMan.glb");
  ASSERT_TRUE(cesium.ok()) << cesium.error();
  EXPECT_EQ(cesium->clips[0].frameTime, 1.0 / 24.0);  // keys every 1/24 s from 1/24 to 2 s
  Result<Scene> fox = loadScene(test::sharedDataDir() + "/gltf/Fox.glb");
  ASSERT_TRUE(fox.ok()) << fox.error();
  ASSERT_EQ(fox->clips.size(), 3u);
  EXPECT_EQ(fox->clips[0].frameTime, 1.0 / 24.0);   // Survey
  EXPECT_EQ(fox->clips[2].frameTime, 1.0 / 120.0);  // Run: keys such as 0.8666667 s are 20.8 frames of 24
}

}  // namespace
}  // namespace kinema
