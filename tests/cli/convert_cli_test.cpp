// `kinema convert`: exit codes, one-line errors, warnings for what the target cannot hold,
// the progress line, and the previous file left alone when a conversion fails.
#include <gtest/gtest.h>

#include "io/bvh.h"
#include "io/kinema_file.h"
#include "io/sample_scene.h"
#include "test_support.h"

namespace kinema::test {
namespace KINEMA_UNITY_ID {

class ConvertCli : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = makeTempDir();
    ASSERT_FALSE(dir_.empty());
  }
  void TearDown() override { std::system(("rm -rf '" + dir_ + "'").c_str()); }
  int kinema(const std::string& args) { return runCommand(std::string(KINEMA_BINARY) + " " + args, &out_, &err_); }
  static int lines(const std::string& s) { return static_cast<int>(std::count(s.begin(), s.end(), '\n')); }
  std::string dir_, out_, err_;
};

TEST_F(ConvertCli, DefaultCharacterToEveryFormat) {
  const std::string in = std::string(KINEMA_SOURCE_DIR) + "/assets/default_character.kinema";
  for (const char* ext : {".gltf", ".glb", ".bvh", ".kinema"}) {
    const std::string out = dir_ + "/character" + ext;
    EXPECT_EQ(kinema("convert '" + in + "' '" + out + "'"), 0) << ext << ": " << err_;
    EXPECT_FALSE(readFile(out).empty()) << ext;
  }
  EXPECT_EQ(readFile(dir_ + "/character.glb").substr(0, 4), "glTF");
  // The .kinema copy reads back with the same joints.
  const Result<Scene> copy = loadKinemaFile(dir_ + "/character.kinema");
  ASSERT_TRUE(copy.ok()) << copy.error();
  const Result<Scene> original = loadKinemaFile(in);
  EXPECT_EQ(copy->skeleton.names, original->skeleton.names);
}

TEST_F(ConvertCli, UsageErrorsExitTwoWithOneLine) {
  const std::string in = std::string(KINEMA_SOURCE_DIR) + "/assets/default_character.kinema";
  EXPECT_EQ(kinema("convert '" + in + "' '" + dir_ + "/out.obj'"), 2);
  EXPECT_EQ(lines(err_), 1) << err_;
  EXPECT_NE(err_.find("see --help"), std::string::npos);
  EXPECT_EQ(kinema("convert '" + in + "' '" + dir_ + "/out.bvh' --rotation-order XYX"), 2);
  EXPECT_EQ(lines(err_), 1) << err_;
  EXPECT_EQ(kinema("convert '" + in + "'"), 2);
  EXPECT_EQ(kinema("convert '" + in + "' '" + dir_ + "/out.bvh' --rate fast"), 2);
}

TEST_F(ConvertCli, BadInputExitsOneAndLeavesThePreviousFile) {
  const std::string out = dir_ + "/out.gltf";
  writeFile(out, "previous");
  EXPECT_EQ(kinema("convert '" + dir_ + "/missing.bvh' '" + out + "'"), 1);
  EXPECT_EQ(lines(err_), 1) << err_;
  EXPECT_NE(err_.find("missing.bvh"), std::string::npos) << err_;
  EXPECT_EQ(readFile(out), "previous");
  // A file that does not parse: the error names its line.
  writeFile(dir_ + "/broken.bvh", "HIERARCHY\nROOT a\n{\n  OFFSET 0 0\n");
  EXPECT_EQ(kinema("convert '" + dir_ + "/broken.bvh' '" + out + "'"), 1);
  EXPECT_EQ(lines(err_), 1) << err_;
  EXPECT_NE(err_.find("broken.bvh:"), std::string::npos) << err_;
  EXPECT_EQ(readFile(out), "previous");
  EXPECT_EQ(kinema("convert '" + std::string(KINEMA_SOURCE_DIR) + "/assets/default_character.kinema' '" + out +
                   "' --rate -3"),
            1);
  EXPECT_EQ(readFile(out), "previous");
}

TEST_F(ConvertCli, BvhWarnsAboutWhatItCannotHold) {
  const std::string in = dir_ + "/sample.kinema";
  ASSERT_EQ(saveKinemaFile(in, makeSampleScene()), "");
  EXPECT_EQ(kinema("convert '" + in + "' '" + dir_ + "/sample.bvh'"), 0) << err_;
  EXPECT_NE(err_.find("warning: 1 mesh(es)"), std::string::npos) << err_;
  EXPECT_NE(err_.find("only clip 0 ('dance') written; 1 more dropped"), std::string::npos) << err_;
  EXPECT_NE(err_.find("'temperature' dropped"), std::string::npos) << err_;
  // Every key of 'dance' lies on the 20 fps grid (its closest keys are 0.05 s apart): written
  // on that grid, nothing resampled.
  EXPECT_EQ(err_.find("key times are not on one frame grid"), std::string::npos) << err_;
  const Result<BvhData> bvh = loadBvh(dir_ + "/sample.bvh");
  ASSERT_TRUE(bvh.ok()) << bvh.error();
  EXPECT_NEAR(bvh->frameTime, 0.05, 1e-8);  // measured from float key times
  // And glTF reports what it resampled (the Squad and Euler channels).
  EXPECT_EQ(kinema("convert '" + in + "' '" + dir_ + "/sample.glb'"), 0) << err_;
  EXPECT_EQ(lines(err_), 3) << err_;
  // The clip has no rate of its own: resampled at the document's default 24 fps.
  EXPECT_NE(err_.find("joint 'B2' rotation resampled at 24 fps"), std::string::npos) << err_;
}

TEST_F(ConvertCli, LongClipsShowProgressAndOptionsApply) {
  KINEMA_REQUIRE_SHARED_DATA();
  const std::string in = sharedDataDir() + "/bvh/cmu_01_01_first720.bvh";
  const std::string out = dir_ + "/walk.bvh";
  // 720 frames: long enough for a progress line (stderr is not a terminal: the last one).
  EXPECT_EQ(kinema("convert '" + in + "' '" + out + "'"), 0) << err_;
  EXPECT_EQ(err_, "converting: frame 720/720\n");
  EXPECT_EQ(kinema("convert '" + in + "' '" + out + "' --rotation-order XYZ --rate 60"), 0) << err_;
  const Result<BvhData> bvh = loadBvh(out);
  ASSERT_TRUE(bvh.ok()) << bvh.error();
  EXPECT_NEAR(bvh->frameTime, 1.0 / 60.0, 1e-9);
  EXPECT_EQ(bvh->joints[0].channels.back(), BvhChannel::Zrotation);  // XYZ: X, Y, then Z
  // Short clips print nothing.
  EXPECT_EQ(kinema("convert '" + sharedDataDir() + "/bvh/games105_walk60.bvh' '" + dir_ + "/short.bvh'"), 0);
  EXPECT_EQ(err_, "");
}

}  // namespace
}  // namespace kinema::test
