// Hostile-input limits (issue 11): each limit refuses a file one step over it with a
// message naming the limit, and accepts a file exactly at it. Small limits keep the files
// small; the defaults are checked against what they must still allow.
#include "io/input_limits.h"

#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <string>

#include "io/bvh.h"
#include "io/kinema_file.h"
#include "io/scene_files.h"
#include "io/text_file.h"
#include "test_support.h"

namespace kinema {
namespace KINEMA_UNITY_ID {

// A BVH chain of `joints` joints (each one channel), then `frames` frames of zeros.
std::string bvhChain(int joints, int frames) {
  std::string s = "HIERARCHY\n";
  for (int i = 0; i < joints; ++i) {
    s += (i == 0 ? "ROOT j" : "JOINT j") + std::to_string(i) + "\n{\nOFFSET 0 1 0\nCHANNELS 1 Zrotation\n";
  }
  for (int i = 0; i < joints; ++i) s += "}\n";
  s += "MOTION\nFrames: " + std::to_string(frames) + "\nFrame Time: 0.1\n";
  for (int f = 0; f < frames; ++f) {
    for (int i = 0; i < joints; ++i) s += i ? " 0" : "0";
    s += "\n";
  }
  return s;
}

std::string kinemaWithJoints(int joints) {
  std::string s = R"({"format": "kinema", "version": 1, "skeleton": {"joints": [)";
  for (int i = 0; i < joints; ++i)
    s += (i ? "," : "") + std::string(R"({"name": "j)") + std::to_string(i) + R"(", "parent": )" +
         std::to_string(i - 1) + "}";
  return s + "]}}";
}

std::string kinemaWithKeys(int keys) {
  std::string times, values;
  for (int k = 0; k < keys; ++k) {
    times += (k ? "," : "") + std::to_string(k);
    values += std::string(k ? "," : "") + "[0, 0, 0]";
  }
  return R"({"format": "kinema", "version": 1, "skeleton": {"joints": [{"name": "a", "parent": -1}]},)"
         R"( "clips": [{"name": "c", "channels": [{"joint": "a", "target": "translation", "times": [)" +
         times + "], \"values\": [" + values + "]}]}]}";
}

TEST(InputLimits, BvhJointCountAboveTheLimitIsRefusedNamingTheLimitAndLine) {
  InputLimits limits;
  limits.maxJoints = 3;
  ASSERT_TRUE(parseBvh(bvhChain(3, 1), "ok.bvh", limits)) << "exactly at the limit must load";
  const Result<BvhData> r = parseBvh(bvhChain(4, 1), "big.bvh", limits);
  ASSERT_FALSE(r);
  // The fourth joint is declared on line 14 (4 lines per joint after HIERARCHY).
  EXPECT_EQ(r.error().rfind("big.bvh:14: ", 0), 0u) << r.error();
  EXPECT_NE(r.error().find("InputLimits::maxJoints"), std::string::npos) << r.error();
  EXPECT_NE(r.error().find("limit of 3"), std::string::npos) << r.error();
}

TEST(InputLimits, BvhFramesTimesChannelsAboveTheLimitIsRefusedBeforeReadingFrames) {
  InputLimits limits;
  limits.maxKeys = 12;  // 3 channels x 4 frames
  ASSERT_TRUE(parseBvh(bvhChain(3, 4), "ok.bvh", limits));
  const Result<BvhData> r = parseBvh(bvhChain(3, 5), "long.bvh", limits);
  ASSERT_FALSE(r);
  EXPECT_NE(r.error().find("InputLimits::maxKeys"), std::string::npos) << r.error();
  EXPECT_NE(r.error().find("15 keys"), std::string::npos) << r.error();
  // Reported on the Frames line: HIERARCHY (1), 3 joints x 4 lines (2-13), 3 x "}" (14-16),
  // MOTION (17), Frames (18).
  EXPECT_EQ(r.error().rfind("long.bvh:18: ", 0), 0u) << r.error();
}

// A header claiming a billion frames of 300 channels is refused from its header alone:
// under a 256 MiB address-space cap the parser must answer, not run out of memory.
TEST(InputLimits, BvhHugeFrameClaimIsRefusedWithoutAllocating) {
  std::string text = "HIERARCHY\nROOT a\n{\nOFFSET 0 0 0\nCHANNELS 6 Xposition Yposition Zposition "
                     "Zrotation Xrotation Yrotation\n";
  for (int i = 0; i < 49; ++i)
    text += "JOINT b" + std::to_string(i) + "\n{\nOFFSET 0 1 0\nCHANNELS 6 Xposition Yposition Zposition "
            "Zrotation Xrotation Yrotation\n}\n";
  text += "}\nMOTION\nFrames: 999999999\nFrame Time: 0.01\n0 0 0\n";
  const pid_t child = ::fork();
  ASSERT_GE(child, 0);
  if (child == 0) {
#if !defined(KINEMA_UNDER_SANITIZER)  // ASan reserves terabytes of shadow address space
    struct rlimit cap {};
    cap.rlim_cur = cap.rlim_max = rlim_t(256) << 20;
    if (::setrlimit(RLIMIT_AS, &cap) != 0) ::_exit(4);
#endif
    const Result<BvhData> r = parseBvh(text, "claim.bvh");
    ::_exit(!r && r.error().find("InputLimits::maxKeys") != std::string::npos ? 0 : 3);
  }
  int status = 0;
  ASSERT_EQ(::waitpid(child, &status, 0), child);
  ASSERT_TRUE(WIFEXITED(status)) << "the parser crashed or was killed";
  EXPECT_EQ(WEXITSTATUS(status), 0);
}

TEST(InputLimits, DefaultsStillLoadAHundredThousandJointChain) {
  const InputLimits defaults;
  EXPECT_GE(defaults.maxJoints, 100000);
  const Result<BvhData> r = parseBvh(bvhChain(100000, 1), "deep.bvh");
  ASSERT_TRUE(r) << r.error();
  EXPECT_EQ(r->joints.size(), 100000u);
  EXPECT_EQ(r->joints.back().parent, 99998);
}

TEST(InputLimits, KinemaJointCountAboveTheLimitIsRefused) {
  InputLimits limits;
  limits.maxJoints = 5;
  ASSERT_TRUE(parseKinemaJson(kinemaWithJoints(5), "ok.kinema", limits));
  const Result<Scene> r = parseKinemaJson(kinemaWithJoints(6), "big.kinema", limits);
  ASSERT_FALSE(r);
  EXPECT_EQ(r.error(), "big.kinema: skeleton.joints: 6 joints, more than the limit of 5 (InputLimits::maxJoints)");
}

TEST(InputLimits, KinemaKeysAboveTheLimitAreRefused) {
  InputLimits limits;
  limits.maxKeys = 10;
  ASSERT_TRUE(parseKinemaJson(kinemaWithKeys(10), "ok.kinema", limits));
  const Result<Scene> r = parseKinemaJson(kinemaWithKeys(11), "long.kinema", limits);
  ASSERT_FALSE(r);
  EXPECT_EQ(r.error(), "long.kinema: clips[0].channels: 11 keys, more than the limit of 10 (InputLimits::maxKeys)");
}

TEST(InputLimits, KinemaNestingDeeperThanTheLimitIsRefusedBeforeParsing) {
  // Brackets inside strings do not count: a joint may be called "[[[[".
  const std::string brackets = kinemaWithJoints(1).replace(kinemaWithJoints(1).find("j0"), 2, "[[[[[[[[");
  InputLimits limits;
  limits.maxJsonDepth = 4;  // {"skeleton": {"joints": [{ ... }]}} is 4 deep
  ASSERT_TRUE(parseKinemaJson(brackets, "ok.kinema", limits)) << parseKinemaJson(brackets, "ok.kinema", limits).error();
  const std::string deep = "{\"a\": " + std::string(1000000, '[') + std::string(1000000, ']') + "}";
  const Result<Scene> r = parseKinemaJson(deep, "deep.kinema");
  ASSERT_FALSE(r);
  EXPECT_EQ(r.error(),
            "deep.kinema: JSON nested 1000001 levels deep, more than the limit of 64 (InputLimits::maxJsonDepth)");
}

TEST(InputLimits, FileLargerThanTheLimitIsRefusedBeforeReading) {
  const std::string dir = test::makeTempDir();
  const std::string path = dir + "/eleven.bvh";
  test::writeFile(path, "HIERARCHY\n\n");
  std::string text;
  EXPECT_EQ(readTextFile(path, text, 11), "");
  const std::string error = readTextFile(path, text, 10);
  EXPECT_EQ(error, path + ": the file is 11 bytes, more than the limit of 10 (InputLimits::maxFileBytes)");
  // The limit travels through loadScene to each reader.
  InputLimits limits;
  limits.maxFileBytes = 10;
  const Result<Scene> scene = loadScene(path, limits);
  ASSERT_FALSE(scene);
  EXPECT_NE(scene.error().find("InputLimits::maxFileBytes"), std::string::npos) << scene.error();
  test::runCommand("rm -rf '" + dir + "'");
}

// Devices and pipes have no size to check up front: they are refused before a byte is read
// (issue 19) instead of filling memory with /dev/zero up to the limit.
TEST(InputLimits, EndlessStreamIsRefusedBeforeReading) {
  std::string text = "left over";
  const std::string error = readTextFile("/dev/zero", text, 1 << 20);
  EXPECT_EQ(error, "/dev/zero: is a character device, not a regular file");
  EXPECT_TRUE(text.empty());
}

}  // namespace
}  // namespace kinema
