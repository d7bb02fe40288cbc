// BVH export: round trips on the shared captures (joint world positions at every frame),
// every rotation order, and a hand-built skeleton whose text is checked line by line.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <dirent.h>

#include "core/forward_kinematics.h"
#include "core/rotation.h"
#include "io/bvh.h"
#include "io/bvh_writer.h"
#include "test_support.h"

namespace kinema {
namespace KINEMA_UNITY_ID {

std::vector<std::string> sharedBvhFiles() {
  std::vector<std::string> files;
  const std::string dir = test::sharedDataDir() + "/bvh";
  if (DIR* d = opendir(dir.c_str())) {
    while (dirent* e = readdir(d)) {
      const std::string name = e->d_name;
      if (name.size() > 4 && name.substr(name.size() - 4) == ".bvh") files.push_back(dir + "/" + name);
    }
    closedir(d);
  }
  std::sort(files.begin(), files.end());
  return files;
}

// Largest distance between the two files' joint world positions over all frames.
double maxWorldDistance(const BvhData& a, const BvhData& b) {
  const Skeleton sa = a.skeleton(), sb = b.skeleton();
  double worst = 0.0;
  for (int f = 0; f < a.frameCount; ++f) {
    const std::vector<glm::mat4> wa = computeWorld(sa, a.framePose(f)), wb = computeWorld(sb, b.framePose(f));
    for (size_t j = 0; j < wa.size(); ++j)
      worst = std::max(worst, double(glm::length(glm::vec3(wa[j][3]) - glm::vec3(wb[j][3]))));
  }
  return worst;
}

void expectRoundTrip(const std::string& path, EulerOrder order) {
  const Result<BvhData> original = loadBvh(path);
  ASSERT_TRUE(original.ok()) << original.error();
  const Clip clip = original->clip();
  BvhWriteOptions options;
  options.order = order;
  std::vector<std::string> report;
  const Result<std::string> text = bvhText(original->skeleton(), &clip, options, &report);
  ASSERT_TRUE(text.ok()) << text.error();
  EXPECT_TRUE(report.empty()) << path << ": " << report.front();
  const Result<BvhData> back = parseBvh(text.value(), "written.bvh");
  ASSERT_TRUE(back.ok()) << back.error();
  ASSERT_EQ(back->joints.size(), original->joints.size()) << path;
  for (size_t j = 0; j < back->joints.size(); ++j) {
    EXPECT_EQ(back->joints[j].name, original->joints[j].name);
    EXPECT_EQ(back->joints[j].endSite, original->joints[j].endSite) << back->joints[j].name;
    EXPECT_EQ(back->joints[j].parent, original->joints[j].parent);
  }
  EXPECT_EQ(back->frameCount, original->frameCount);
  EXPECT_EQ(back->frameTime, original->frameTime);
  EXPECT_LT(maxWorldDistance(original.value(), back.value()), 1e-4) << path << " in " << toString(order);
}

TEST(BvhWriter, RoundTripKeepsJointWorldPositionsAtEveryFrame) {
  KINEMA_REQUIRE_SHARED_DATA();
  const std::vector<std::string> files = sharedBvhFiles();
  ASSERT_FALSE(files.empty());
  for (const std::string& f : files) expectRoundTrip(f, EulerOrder::ZXY);
}

TEST(BvhWriter, EveryRotationOrderRoundTrips) {
  KINEMA_REQUIRE_SHARED_DATA();
  for (EulerOrder order : {EulerOrder::XYZ, EulerOrder::XZY, EulerOrder::YXZ, EulerOrder::YZX, EulerOrder::ZXY,
                           EulerOrder::ZYX})
    expectRoundTrip(test::sharedDataDir() + "/bvh/games105_walk60.bvh", order);
}

// The rest rotation goes into the rotation channels (BVH has none), End Sites come back
// as End Sites, a leaf that is not one gets an End Site continuing its bone (Tail's offset,
// its rest rotation being none); numbers by hand.
TEST(BvhWriter, HandBuiltSkeletonText) {
  Skeleton s;
  Transform root = Transform::fromTranslation({1, 2, 3});
  root.rotation = axisAngle({0, 1, 0}, 3.14159265f / 2);  // 90 degrees about Y
  s.addJoint("Hips", -1, root);
  s.addJoint("Spine", 0, Transform::fromTranslation({0, 1, 0}));
  s.addJoint("Spine_End", 1, Transform::fromTranslation({0, 0.5f, 0}));
  s.addJoint("Tail", 0, Transform::fromTranslation({0, 0, -1}));
  std::vector<std::string> report;
  const Result<std::string> text = bvhText(s, nullptr, {}, &report);
  ASSERT_TRUE(text.ok()) << text.error();
  const std::string expected =
      "HIERARCHY\n"
      "ROOT Hips\n"
      "{\n"
      "  OFFSET 1.000000 2.000000 3.000000\n"
      "  CHANNELS 6 Xposition Yposition Zposition Zrotation Xrotation Yrotation\n"
      "  JOINT Spine\n"
      "  {\n"
      "    OFFSET 0.000000 1.000000 0.000000\n"
      "    CHANNELS 3 Zrotation Xrotation Yrotation\n"
      "    End Site\n"
      "    {\n"
      "      OFFSET 0.000000 0.500000 0.000000\n"
      "    }\n"
      "  }\n"
      "  JOINT Tail\n"
      "  {\n"
      "    OFFSET 0.000000 0.000000 -1.000000\n"
      "    CHANNELS 3 Zrotation Xrotation Yrotation\n"
      "    End Site\n"
      "    {\n"
      "      OFFSET 0.000000 0.000000 -1.000000\n"
      "    }\n"
      "  }\n"
      "}\n"
      "MOTION\n"
      "Frames: 1\n"
      "Frame Time: 0.0416666667\n"  // no clip: one frame at the default 24 fps
      "1.000000 2.000000 3.000000 0.000000 0.000000 90.000000 0.000000 0.000000 0.000000 0.000000 0.000000 0.000000\n";
  EXPECT_EQ(text.value(), expected);
  ASSERT_EQ(report.size(), 1u);
  EXPECT_EQ(report[0],
            "leaves given an End Site as long as their bone (read back, each adds a '<name>_End' joint): 1 joint: 'Tail'");
}

TEST(BvhWriter, FrameRateComesFromTheKeysWhenTheClipHasNone) {
  Skeleton s;
  s.addJoint("a", -1, Transform::identity());
  Clip clip;
  clip.channels.push_back(Channel(0, ChannelTarget::Translation, Interpolation::Linear, {0.0f, 0.05f, 0.2f},
                                  {{0, 0, 0, 0}, {1, 0, 0, 0}, {4, 0, 0, 0}}));
  bool uniform = false;
  EXPECT_NEAR(bvhFrameTime(&clip, BvhWriteOptions{}, &uniform), 0.05, 1e-7);
  EXPECT_TRUE(uniform);
  const Result<std::string> text = bvhText(s, &clip, {});
  ASSERT_TRUE(text.ok());
  const Result<BvhData> back = parseBvh(text.value(), "x.bvh");
  ASSERT_TRUE(back.ok()) << back.error();
  EXPECT_EQ(back->frameCount, 5);  // 0, 0.05, 0.1, 0.15, 0.2; linear: x = 20 t
  EXPECT_NEAR(back->framePose(2).local[0].translation.x, 2.0f, 1e-5);

  // Keys on no grid (not even 100 or 120 fps's) are sampled at the document's rate.
  clip.channels[0].times = {0.0f, 0.05f, 0.1234f};
  std::vector<std::string> report;
  EXPECT_NEAR(bvhFrameTime(&clip, BvhWriteOptions{}, &uniform), 1.0 / 24.0, 1e-9);
  EXPECT_FALSE(uniform);
  ASSERT_TRUE(bvhText(s, &clip, {}, &report).ok());
  EXPECT_TRUE(std::any_of(report.begin(), report.end(),
                          [](const std::string& l) { return l.find("sampled at the document's 24 fps") != std::string::npos; }));
  BvhWriteOptions at60;
  at60.frameRate = 60.0;
  EXPECT_NE(bvhText(s, &clip, at60)->find("Frame Time: 0.0166666667\n"), std::string::npos);
}

TEST(BvhWriter, ProgressReachesTheLastFrameAndBadRatesFail) {
  Skeleton s;
  s.addJoint("a", -1, Transform::identity());
  Clip clip;
  clip.frameTime = 0.01;
  clip.channels.push_back(Channel(0, ChannelTarget::Translation, Interpolation::Linear, {0.0f, 9.99f},
                                  {{0, 0, 0, 0}, {1, 0, 0, 0}}));
  long long last = 0, total = 0;
  BvhWriteOptions options;
  options.progress = [&](long long f, long long n) {
    last = f;
    total = n;
  };
  ASSERT_TRUE(bvhText(s, &clip, options).ok());
  EXPECT_EQ(total, 1000);
  EXPECT_EQ(last, 1000);
  // A key a year away would be billions of frames: refused, not attempted.
  Clip far = clip;
  far.channels[0].times[1] = 3.0e7f;
  const Result<std::string> huge = bvhText(s, &far, {});
  ASSERT_FALSE(huge.ok());
  // 3e7 s at the clip's 100 fps: 3e9 frames, said in double.
  EXPECT_NE(huge.error().find("needs 3e+09 frames, more than 10000000"), std::string::npos) << huge.error();
  options.frameRate = -5.0;
  const Result<std::string> bad = bvhText(s, &clip, options);
  ASSERT_FALSE(bad.ok());
  EXPECT_NE(bad.error().find("frame rate"), std::string::npos);
}

}  // namespace
}  // namespace kinema
