// The BVH reader on the real files in ../shared/data/bvh, against values computed outside
// Kinema: three.js (../shared/data/reference, see its README) and the numpy script
// tests/tools/bvh_fk_reference.py. Skips when ../shared/data is absent.
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <regex>
#include <set>
#include <string>
#include <vector>

#include "anim/clip.h"
#include "core/forward_kinematics.h"
#include "io/bvh.h"
#include "test_support.h"

namespace kinema {
namespace KINEMA_UNITY_ID {

namespace fs = std::filesystem;
using test::sharedDataDir;

std::string bvhPath(const std::string& name) { return sharedDataDir() + "/bvh/" + name + ".bvh"; }

const BvhData& loaded(const std::string& name) {
  static std::map<std::string, BvhData> cache;
  auto it = cache.find(name);
  if (it == cache.end()) {
    Result<BvhData> r = loadBvh(bvhPath(name));
    EXPECT_TRUE(r.ok()) << r.error();
    it = cache.emplace(name, r.ok() ? std::move(r).value() : BvhData{}).first;
  }
  return it->second;
}

// World transforms of frame N the way the CLI computes them: the clip sampled at N x Frame Time.
std::vector<glm::mat4> worldAtFrame(const BvhData& d, int frame) {
  const Skeleton skel = d.skeleton();
  const Clip clip = d.clip();
  Pose pose = Pose::rest(skel);
  sampleClip(clip, ownFrameGrid(clip).frameToTime(frame), pose);
  return computeWorld(skel, pose);
}

int indexOf(const BvhData& d, const std::string& name) {
  for (size_t i = 0; i < d.joints.size(); ++i)
    if (d.joints[i].name == name) return static_cast<int>(i);
  return -1;
}

// Facts about each file. Joint and frame counts and frame times are from ../shared/data/SOURCES.md
// (geno's frame time, which SOURCES.md does not give, and the End Site counts are read off the
// files with grep: `grep -ci 'End Site' FILE`).
struct FileFacts {
  const char* name;
  int joints;    // ROOT + JOINT
  int endSites;
  int frames;
  double frameTime;
};
const FileFacts kFiles[] = {
    {"cmu_01_01_first720", 31, 7, 720, 0.0083333},
    {"mocapbank_test", 19, 5, 455, 0.033333},
    {"games105_walk60", 20, 5, 182, 0.016667},
    {"geno_bind", 75, 21, 2, 0.016667},
};

TEST(BvhReference, EveryFileLoadsWithItsDocumentedCounts) {
  KINEMA_REQUIRE_SHARED_DATA();
  std::set<std::string> known;
  for (const FileFacts& f : kFiles) {
    SCOPED_TRACE(f.name);
    known.insert(f.name);
    const BvhData& d = loaded(f.name);
    int joints = 0, ends = 0;
    for (size_t i = 0; i < d.joints.size(); ++i) {
      const BvhJoint& j = d.joints[i];
      (j.endSite ? ends : joints)++;
      EXPECT_LT(j.parent, static_cast<int>(i));
      if (j.endSite) {
        EXPECT_EQ(j.name, d.joints[j.parent].name + "_End");
      }
    }
    EXPECT_EQ(joints, f.joints);
    EXPECT_EQ(ends, f.endSites);
    EXPECT_EQ(d.frameCount, f.frames);
    EXPECT_DOUBLE_EQ(d.frameTime, f.frameTime);
    EXPECT_EQ(d.motion.size(), static_cast<size_t>(d.frameCount) * d.channelCount);
    EXPECT_EQ(d.skeleton().validate(), "");
    const Clip clip = d.clip();
    EXPECT_EQ(clip.validate(d.skeleton()), "");
    EXPECT_NEAR(clip.duration(), (f.frames - 1) * f.frameTime, 1e-4);
  }
  // Every .bvh in the folder is one of the files above.
  int files = 0;
  for (const auto& e : fs::directory_iterator(sharedDataDir() + "/bvh")) {
    if (e.path().extension() != ".bvh") continue;
    ++files;
    EXPECT_TRUE(known.count(e.path().stem().string())) << "no facts for " << e.path();
  }
  EXPECT_EQ(files, 4);
}

// Size of a posed skeleton: the diagonal of its joints' bounding box.
double extent(const nlohmann::json& joints) {
  glm::dvec3 lo(1e300), hi(-1e300);
  for (const auto& j : joints) {
    const glm::dvec3 p(j["world"][12].get<double>(), j["world"][13].get<double>(), j["world"][14].get<double>());
    lo = glm::min(lo, p);
    hi = glm::max(hi, p);
  }
  return glm::length(hi - lo);
}

TEST(BvhReference, WorldMatricesMatchThreeJs) {
  KINEMA_REQUIRE_SHARED_DATA();
  const std::regex pattern(R"((.+)\.frame(\d+)\.pose\.json)");
  std::vector<fs::path> references;
  for (const auto& e : fs::directory_iterator(sharedDataDir() + "/reference"))
    if (std::regex_match(e.path().filename().string(), pattern)) references.push_back(e.path());
  std::sort(references.begin(), references.end());
  ASSERT_EQ(references.size(), 11u);  // 3 cmu, 3 games105, 2 geno, 3 mocapbank
  for (const fs::path& file : references) {
    SCOPED_TRACE(file.filename().string());
    std::smatch m;
    const std::string filename = file.filename().string();
    ASSERT_TRUE(std::regex_match(filename, m, pattern));
    const std::string name = m[1];
    const int frame = std::stoi(m[2]);
    std::ifstream in(file);
    const nlohmann::json ref = nlohmann::json::parse(in);
    ASSERT_EQ(ref["frame"].get<int>(), frame);
    const BvhData& d = loaded(name);
    ASSERT_FALSE(d.joints.empty());
    ASSERT_LT(frame, d.frameCount);
    const Clip clip = d.clip();
    EXPECT_NEAR(ownFrameGrid(clip).frameToTime(frame), ref["time"].get<double>(), 1e-4);
    const std::vector<glm::mat4> world = worldAtFrame(d, frame);

    const nlohmann::json& joints = ref["joints"];
    const double positionTol = 1e-4 * extent(joints);
    // The reference lists every ROOT/JOINT (End Sites omitted) in file order.
    std::vector<std::string> expectedNames;
    for (const BvhJoint& j : d.joints)
      if (!j.endSite) expectedNames.push_back(j.name);
    std::vector<std::string> refNames;
    for (const auto& j : joints) refNames.push_back(j["name"].get<std::string>());
    EXPECT_EQ(refNames, expectedNames);

    for (const auto& j : joints) {
      const std::string joint = j["name"].get<std::string>();
      SCOPED_TRACE(joint);
      const int i = indexOf(d, joint);
      ASSERT_GE(i, 0);
      const float* k = glm::value_ptr(world[i]);  // column-major, as the JSON
      for (int c = 0; c < 3; ++c)
        for (int r = 0; r < 3; ++r)
          EXPECT_NEAR(k[c * 4 + r], j["world"][c * 4 + r].get<double>(), 1e-4) << "rotation [" << c << "][" << r << "]";
      for (int r = 0; r < 3; ++r) {
        EXPECT_NEAR(k[12 + r], j["world"][12 + r].get<double>(), positionTol) << "position " << r;
        EXPECT_NEAR(k[12 + r], j["world_position"][r].get<double>(), positionTol) << "position " << r;
      }
    }
  }
}

// The clip (sampled at N x Frame Time) and framePose(N) give the same pose on real files.
TEST(BvhReference, ClipAgreesWithFramePose) {
  KINEMA_REQUIRE_SHARED_DATA();
  for (const FileFacts& f : kFiles) {
    SCOPED_TRACE(f.name);
    const BvhData& d = loaded(f.name);
    const Skeleton skel = d.skeleton();
    for (int frame : {0, f.frames / 3, f.frames - 1}) {
      const std::vector<glm::mat4> a = worldAtFrame(d, frame);
      const std::vector<glm::mat4> b = computeWorld(skel, d.framePose(frame));
      ASSERT_EQ(a.size(), b.size());
      float scale = 1.0f;
      for (const glm::mat4& w : b) scale = std::max(scale, glm::length(glm::vec3(w[3])));
      for (size_t j = 0; j < a.size(); ++j)
        for (int c = 0; c < 4; ++c)
          for (int r = 0; r < 4; ++r)
            EXPECT_NEAR(a[j][c][r], b[j][c][r], 1e-6f * scale) << "frame " << frame << " joint " << j;
    }
  }
}

// Values printed by the independent numpy FK (its own parser and Euler composition):
//   /usr/bin/python3 tests/tools/bvh_fk_reference.py ../shared/data/bvh/games105_walk60.bvh 100 lWrist rToeJoint torso_head --matrix
//   /usr/bin/python3 tests/tools/bvh_fk_reference.py ../shared/data/bvh/mocapbank_test.bvh 300 RightWrist LeftAnkle Head --matrix
struct NumpyJoint {
  const char* file;
  int frame;
  const char* joint;
  double position[3];
  double rotationRows[9];
};
const NumpyJoint kNumpy[] = {
    {"games105_walk60", 100, "lWrist", {0.140385276, 0.720288167, 2.26988659},
     {0.074502289, 0.855511192, -0.51239634, -0.979218675, -0.0344299687, -0.199863364, -0.188627135, 0.516638344, 0.835167424}},
    {"games105_walk60", 100, "torso_head", {-0.0379607881, 1.35872122, 2.35609346},
     {0.999890849, 0.00607560157, -0.0134676211, -0.0079927717, 0.989071573, -0.147219354, 0.0124259951, 0.147310929, 0.989012176}},
    {"games105_walk60", 100, "rToeJoint", {-0.0449239313, 0.00410310533, 2.31860121},
     {0.998487565, 0.0220090868, -0.0503803811, -0.0220182288, 0.9997575, 0.000373597073, 0.0503763864, 0.000736254726, 0.998730032}},
    {"mocapbank_test", 300, "RightWrist", {-31.5910162, 22.5681348, 245.833179},
     {0.0138954982, -0.583860991, 0.811734722, -0.371221002, 0.750780677, 0.546372896, -0.928440565, -0.3089251, -0.206308991}},
    {"mocapbank_test", 300, "Head", {-22.5220695, 67.260662, 253.489207},
     {0.864006078, 0.318825253, 0.389671599, 0.313463362, 0.26502033, -0.91186893, -0.393997738, 0.910008067, 0.12903914}},
    {"mocapbank_test", 300, "LeftAnkle", {-15.2100206, 11.0514155, 233.726541},
     {0.992829325, -0.00168703547, 0.119528596, 0.0115204952, 0.996596479, -0.0816255872, -0.118984073, 0.0824173053, 0.989469645}},
};

TEST(BvhReference, MatchesIndependentNumpyComputation) {
  KINEMA_REQUIRE_SHARED_DATA();
  for (const NumpyJoint& n : kNumpy) {
    SCOPED_TRACE(std::string(n.file) + " frame " + std::to_string(n.frame) + " " + n.joint);
    const BvhData& d = loaded(n.file);
    const int i = indexOf(d, n.joint);
    ASSERT_GE(i, 0);
    // Skeleton heights: about 1.7 (games105, metres) and 170 (mocapbank, centimetres).
    const double tol = 1e-4 * (std::string(n.file) == "games105_walk60" ? 1.7 : 170.0);
    const glm::mat4 w = worldAtFrame(d, n.frame)[i];
    for (int r = 0; r < 3; ++r) {
      EXPECT_NEAR(w[3][r], n.position[r], tol) << "position " << r;
      for (int c = 0; c < 3; ++c) EXPECT_NEAR(w[c][r], n.rotationRows[r * 3 + c], 1e-4) << "row " << r << " col " << c;
    }
  }
}

// geno gives every joint position channels that repeat its OFFSET. Replacing the OFFSET
// leaves the bind pose in place; adding them (three.js's BVHLoader) would double every bone.
TEST(BvhReference, GenoPositionChannelsReplaceOffset) {
  KINEMA_REQUIRE_SHARED_DATA();
  const BvhData& d = loaded("geno_bind");
  std::ifstream in(sharedDataDir() + "/reference/geno_bind.frame0.pose.json");
  const nlohmann::json ref = nlohmann::json::parse(in);
  const std::vector<glm::mat4> world = worldAtFrame(d, 0);
  const Pose pose = d.framePose(0);

  // Every non-root joint has position channels, and the local translation is exactly their values.
  int checked = 0;
  for (size_t i = 0; i < d.joints.size(); ++i) {
    const BvhJoint& j = d.joints[i];
    if (j.endSite || j.parent < 0) continue;
    ASSERT_EQ(j.channels.size(), 6u) << j.name;
    ASSERT_EQ(j.channels[0], BvhChannel::Xposition);
    const float* row = d.motion.data();
    const glm::vec3 channels(row[j.firstChannel], row[j.firstChannel + 1], row[j.firstChannel + 2]);
    EXPECT_VEC3_NEAR(pose.local[i].translation, channels, 0.0f);
    ++checked;
  }
  EXPECT_EQ(checked, 74);

  // Far down the chain the two conventions part by far more than the tolerance; the reference
  // (which replaces) agrees with Kinema, and the additive reading does not.
  Pose added = pose;
  for (size_t i = 0; i < d.joints.size(); ++i)
    if (!d.joints[i].endSite) added.local[i].translation += d.joints[i].offset;  // root included, as three.js
  const std::vector<glm::mat4> addedWorld = computeWorld(d.skeleton(), added);
  int far = 0;
  for (const auto& rj : ref["joints"]) {
    const int i = indexOf(d, rj["name"].get<std::string>());
    ASSERT_GE(i, 0);
    const glm::vec3 p(rj["world_position"][0].get<float>(), rj["world_position"][1].get<float>(),
                      rj["world_position"][2].get<float>());
    EXPECT_LT(glm::distance(glm::vec3(world[i][3]), p), 0.02f) << rj["name"];
    if (glm::distance(glm::vec3(addedWorld[i][3]), p) > 10.0f) ++far;  // 10 cm
  }
  EXPECT_GT(far, 50);
  // The worst joint is about 1.7 m off under the additive reading (SOURCES.md); geno is in cm.
  float worst = 0.0f;
  for (size_t i = 0; i < d.joints.size(); ++i)
    worst = std::max(worst, glm::distance(glm::vec3(world[i][3]), glm::vec3(addedWorld[i][3])));
  EXPECT_GT(worst, 150.0f);
  EXPECT_LT(worst, 190.0f);
}

}  // namespace
}  // namespace kinema
