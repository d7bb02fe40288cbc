// BVH reader tests on small files written inline. Expected numbers are derived by hand
// (in the comments) or printed by the independent numpy script named next to them.
#include "io/bvh.h"
#include "io/text_file.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <string>
#include <vector>

#include "anim/clip.h"
#include "core/forward_kinematics.h"
#include "test_support.h"

namespace kinema {
namespace KINEMA_UNITY_ID {

using test::makeTempDir;
using test::runCommand;
using test::writeFile;

std::string joinLines(const std::vector<std::string>& lines, const std::string& eol = "\n") {
  std::string s;
  for (const std::string& l : lines) s += l + eol;
  return s;
}

BvhData parseOk(const std::string& text, const std::string& source = "test.bvh") {
  Result<BvhData> r = parseBvh(text, source);
  EXPECT_TRUE(r.ok()) << r.error();
  if (!r.ok()) return BvhData{};
  return std::move(r).value();
}

// World transforms of frame N, computed both ways the reader offers: straight from the
// motion numbers (framePose) and through the clip sampled at frameToTime(N).
std::vector<glm::mat4> worldFromFrame(const BvhData& d, int frame) {
  return computeWorld(d.skeleton(), d.framePose(frame));
}

std::vector<glm::mat4> worldFromClip(const BvhData& d, int frame) {
  const Skeleton skel = d.skeleton();
  const Clip clip = d.clip();
  Pose pose = Pose::rest(skel);
  sampleClip(clip, ownFrameGrid(clip).frameToTime(frame), pose);
  return computeWorld(skel, pose);
}

void expectSameWorlds(const std::vector<glm::mat4>& a, const std::vector<glm::mat4>& b, float tol,
                      const std::string& what) {
  ASSERT_EQ(a.size(), b.size()) << what;
  for (size_t j = 0; j < a.size(); ++j)
    for (int c = 0; c < 4; ++c)
      for (int r = 0; r < 4; ++r) EXPECT_NEAR(a[j][c][r], b[j][c][r], tol) << what << " joint " << j << " [" << c << "][" << r << "]";
}

void expectClipAgreesWithFrames(const BvhData& d) {
  for (int f = 0; f < d.frameCount; ++f)
    expectSameWorlds(worldFromFrame(d, f), worldFromClip(d, f), 1e-5f, "frame " + std::to_string(f));
}

glm::vec3 position(const glm::mat4& m) { return glm::vec3(m[3]); }

// Row r, column c of the rotation part (glm is column-major: m[c][r]).
void expectRotationRows(const glm::mat4& m, const double (&rows)[9], float tol, const std::string& what) {
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(m[c][r], rows[r * 3 + c], tol) << what << " row " << r << " col " << c;
}

// ---------------------------------------------------------------------------------------
// Rotation orders

// The same 3-joint file for every order: Hips (6 channels) -> Arm (3) -> End Site.
// Frame 1 uses X=30 Y=-50 Z=70 on Hips and X=-20 Y=35 Z=110 on Arm, listed in channel order.
// Mirrored by six_order_bvh() in tests/tools/bvh_six_orders.py.
std::string sixOrderBvh(const std::string& order) {
  const std::map<char, int> root{{'X', 30}, {'Y', -50}, {'Z', 70}};
  const std::map<char, int> arm{{'X', -20}, {'Y', 35}, {'Z', 110}};
  std::string ch, rootValues, armValues;
  for (char a : order) {
    ch += std::string(" ") + a + "rotation";
    rootValues += " " + std::to_string(root.at(a));
    armValues += " " + std::to_string(arm.at(a));
  }
  return "HIERARCHY\n"
         "ROOT Hips\n"
         "{\n"
         "  OFFSET 1 2 3\n"
         "  CHANNELS 6 Xposition Yposition Zposition" + ch + "\n"
         "  JOINT Arm\n"
         "  {\n"
         "    OFFSET 1 2 0.5\n"
         "    CHANNELS 3" + ch + "\n"
         "    End Site\n"
         "    {\n"
         "      OFFSET 0.5 1 -1\n"
         "    }\n"
         "  }\n"
         "}\n"
         "MOTION\n"
         "Frames: 2\n"
         "Frame Time: 0.1\n"
         "0 0 0 0 0 0 0 0 0\n"
         "0.5 -1 2" + rootValues + armValues + "\n";
}

struct OrderCase {
  const char* order;
  double hipsRotation[9];  // world rotation rows
  double armRotation[9];
  double arm[3];           // world positions
  double armEnd[3];
};

// Printed by `/usr/bin/python3 tests/tools/bvh_six_orders.py` (numpy, independent of Kinema).
const OrderCase kOrderCases[] = {
    {"XYZ",
     {0.21984631, -0.604022774, -0.766044443, 0.682796366, 0.656121288, -0.321393805, 0.696747244, -0.45239512, 0.556670399},
     {-0.530500124, -0.564042623, -0.63279186, 0.476142911, -0.815880332, 0.328065866, -0.701325564, -0.127260375, 0.701389514},
     {-0.871221458, 0.83434204, 2.0702922},
     {-1.06772228, -0.0715327029, 0.890979533}},
    {"XZY",
     {0.21984631, -0.939692621, -0.26200263, 0.140076845, 0.296198133, -0.944798996, 0.965425335, 0.171010072, 0.196747244},
     {-0.346763846, 0.0647749456, -0.935713119, 0.874868021, -0.33734591, -0.347568241, -0.338172708, -0.939149585, 0.0603098368},
     {-1.29054025, -0.739926388, 3.4058191},
     {-0.463434105, -0.292270046, 2.23727332}},
    {"YXZ",
     {-0.140076845, -0.735024089, -0.663413948, 0.813797681, 0.296198133, -0.5, 0.564014017, -0.609923155, 0.556670399},
     {-0.539463229, -0.0864826239, -0.837556076, -0.0829201151, -0.984419673, 0.155055349, -0.837916272, 0.153096905, 0.523887067},
     {-1.441832, 0.156193947, 1.62250291},
     {-0.960490159, -1.02474113, 0.832754609}},
    {"YZX",
     {0.21984631, -0.906121288, -0.361402561, 0.939692621, 0.296198133, -0.171010072, 0.26200263, -0.302011387, 0.916593554},
     {-0.983967096, 0.00728162714, -0.178201379, -0.0184830413, -0.997949526, 0.0612790327, -0.17738977, 0.0635902553, 0.982084084},
     {-1.27309755, 0.44658385, 2.11627663},
     {-1.57959809, -0.621886229, 1.10908792}},
    {"ZXY",
     {0.579769466, -0.813797681, 0.0400087565, 0.473021458, 0.296198133, -0.829769466, 0.663413948, 0.5, 0.556670399},
     {-0.75814316, -0.264083589, -0.596220435, 0.649780076, -0.229086832, -0.724779329, 0.0548160756, -0.93689865, 0.345276869},
     {-0.527821519, -0.349467009, 3.94174915},
     {-0.574756253, 0.471115526, 2.68698167}},
    {"ZYX",
     {0.21984631, -0.944798996, 0.242945377, 0.604022774, -0.0637250225, -0.794415263, 0.766044443, 0.321393805, 0.556670399},
     {-0.928201411, 0.230376897, -0.292179099, 0.237378521, -0.238041511, -0.941800232, -0.286519769, -0.943537347, 0.166263939},
     {-1.04827899, -0.920634903, 3.68716725},
     {-0.989823704, -0.0981869218, 2.43410608}},
};

TEST(BvhSixOrders, WorldTransformsMatchIndependentComputation) {
  for (const OrderCase& c : kOrderCases) {
    SCOPED_TRACE(c.order);
    const BvhData d = parseOk(sixOrderBvh(c.order));
    ASSERT_EQ(d.joints.size(), 3u);
    ASSERT_EQ(d.frameCount, 2);
    for (const std::vector<glm::mat4>& world : {worldFromFrame(d, 1), worldFromClip(d, 1)}) {
      expectRotationRows(world[0], c.hipsRotation, 1e-5f, "Hips");
      expectRotationRows(world[1], c.armRotation, 1e-5f, "Arm");
      EXPECT_VEC3_NEAR(position(world[0]), glm::vec3(0.5f, -1.0f, 2.0f), 1e-6f);  // position channels
      EXPECT_VEC3_NEAR(position(world[1]), glm::vec3(c.arm[0], c.arm[1], c.arm[2]), 1e-5f);
      EXPECT_VEC3_NEAR(position(world[2]), glm::vec3(c.armEnd[0], c.armEnd[1], c.armEnd[2]), 1e-5f);
    }
    // Frame 0 is all zeros: no rotation, and the root's position channels (0,0,0) replace
    // its OFFSET (1,2,3). Arm sits at its OFFSET, the End Site one OFFSET further.
    const std::vector<glm::mat4> w0 = worldFromFrame(d, 0);
    EXPECT_VEC3_NEAR(position(w0[0]), glm::vec3(0.0f), 1e-6f);
    EXPECT_VEC3_NEAR(position(w0[1]), glm::vec3(1.0f, 2.0f, 0.5f), 1e-6f);
    EXPECT_VEC3_NEAR(position(w0[2]), glm::vec3(1.5f, 3.0f, -0.5f), 1e-6f);
    expectClipAgreesWithFrames(d);
  }
}

TEST(BvhSixOrders, NinetyDegreeTurnsDerivedByHand) {
  // One root, rotations Z=90 and X=90 (Y=0), and an End Site at (0,1,0).
  auto file = [](const std::string& channels, const std::string& values) {
    return joinLines({"HIERARCHY", "ROOT R", "{", "OFFSET 0 0 0", "CHANNELS 3 " + channels, "End Site", "{",
                      "OFFSET 0 1 0", "}", "}", "MOTION", "Frames: 1", "Frame Time: 1", values});
  };
  // "Zrotation Xrotation Yrotation" -> R = Rz(90) Rx(90). Rx(90) maps x->x, y->z, z->-y;
  // Rz(90) maps x->y, y->-x, z->z. Columns R e_x = Rz e_x = e_y; R e_y = Rz e_z = e_z;
  // R e_z = Rz(-e_y) = e_x. The End Site is at R (0,1,0) = (0,0,1).
  {
    const BvhData d = parseOk(file("Zrotation Xrotation Yrotation", "90 90 0"));
    for (const auto& w : {worldFromFrame(d, 0), worldFromClip(d, 0)}) {
      EXPECT_VEC3_NEAR(glm::vec3(w[0][0]), glm::vec3(0, 1, 0), 1e-6f);
      EXPECT_VEC3_NEAR(glm::vec3(w[0][1]), glm::vec3(0, 0, 1), 1e-6f);
      EXPECT_VEC3_NEAR(glm::vec3(w[0][2]), glm::vec3(1, 0, 0), 1e-6f);
      EXPECT_VEC3_NEAR(position(w[1]), glm::vec3(0, 0, 1), 1e-6f);
    }
  }
  // "Xrotation Zrotation Yrotation" with the same angles -> R = Rx(90) Rz(90):
  // R e_x = Rx e_y = e_z; R e_y = Rx(-e_x) = -e_x; R e_z = Rx e_z = -e_y. End Site at (-1,0,0).
  {
    const BvhData d = parseOk(file("Xrotation Zrotation Yrotation", "90 90 0"));
    for (const auto& w : {worldFromFrame(d, 0), worldFromClip(d, 0)}) {
      EXPECT_VEC3_NEAR(glm::vec3(w[0][0]), glm::vec3(0, 0, 1), 1e-6f);
      EXPECT_VEC3_NEAR(glm::vec3(w[0][1]), glm::vec3(-1, 0, 0), 1e-6f);
      EXPECT_VEC3_NEAR(glm::vec3(w[0][2]), glm::vec3(0, -1, 0), 1e-6f);
      EXPECT_VEC3_NEAR(position(w[1]), glm::vec3(-1, 0, 0), 1e-6f);
    }
  }
  // Degrees, right-handed: Yrotation 90 maps +x to -z; Yrotation -90 maps +x to +z.
  {
    auto f = [](const std::string& v) {
      return joinLines({"HIERARCHY", "ROOT R", "{", "OFFSET 0 0 0", "CHANNELS 1 Yrotation", "End Site", "{",
                        "OFFSET 2 0 0", "}", "}", "MOTION", "Frames: 2", "Frame Time: 1", v, "-90"});
    };
    const BvhData d = parseOk(f("90"));
    EXPECT_VEC3_NEAR(position(worldFromFrame(d, 0)[1]), glm::vec3(0, 0, -2), 1e-6f);
    EXPECT_VEC3_NEAR(position(worldFromFrame(d, 1)[1]), glm::vec3(0, 0, 2), 1e-6f);
    EXPECT_VEC3_NEAR(position(worldFromClip(d, 1)[1]), glm::vec3(0, 0, 2), 1e-6f);
  }
}

// ---------------------------------------------------------------------------------------
// Position channels, End Sites, order, forests, timing

TEST(BvhPositionChannels, ReplaceTheOffsetOnChildJoints) {
  const std::string text = joinLines({
      "HIERARCHY",
      "ROOT Hips",
      "{",
      "  OFFSET 10 20 30",
      "  CHANNELS 6 Xposition Yposition Zposition Yrotation Xrotation Zrotation",
      "  JOINT Chest",
      "  {",
      "    OFFSET 100 200 300",
      "    CHANNELS 6 Xposition Yposition Zposition Zrotation Yrotation Xrotation",
      "    JOINT Neck",
      "    {",
      "      OFFSET 7 8 9",
      "      CHANNELS 4 Yposition Xrotation Yrotation Zrotation",
      "      End Site",
      "      { OFFSET 0 1 0 }",
      "    }",
      "  }",
      "}",
      "MOTION",
      "Frames: 1",
      "Frame Time: 0.5",
      "1 2 3 90 0 0  4 5 6 0 0 0  -3 0 0 0",
  });
  const BvhData d = parseOk(text);
  ASSERT_EQ(d.joints.size(), 4u);
  // Local translations: position channels replace the OFFSET component by component.
  const Pose pose = d.framePose(0);
  EXPECT_VEC3_NEAR(pose.local[0].translation, glm::vec3(1, 2, 3), 0.0f);
  EXPECT_VEC3_NEAR(pose.local[1].translation, glm::vec3(4, 5, 6), 0.0f);   // not (104,205,306)
  EXPECT_VEC3_NEAR(pose.local[2].translation, glm::vec3(7, -3, 9), 0.0f);  // only Y replaced
  EXPECT_VEC3_NEAR(pose.local[3].translation, glm::vec3(0, 1, 0), 0.0f);
  // World: Hips at (1,2,3) turned Ry(90) (x' = z, z' = -x). Chest = (1,2,3) + Ry(4,5,6)
  // = (1,2,3) + (6,5,-4) = (7,7,-1). Neck = (7,7,-1) + Ry(7,-3,9) = (7,7,-1) + (9,-3,-7)
  // = (16,4,-8). Neck_End = (16,4,-8) + Ry(0,1,0) = (16,5,-8).
  for (const auto& w : {worldFromFrame(d, 0), worldFromClip(d, 0)}) {
    EXPECT_VEC3_NEAR(position(w[0]), glm::vec3(1, 2, 3), 1e-5f);
    EXPECT_VEC3_NEAR(position(w[1]), glm::vec3(7, 7, -1), 1e-5f);
    EXPECT_VEC3_NEAR(position(w[2]), glm::vec3(16, 4, -8), 1e-5f);
    EXPECT_VEC3_NEAR(position(w[3]), glm::vec3(16, 5, -8), 1e-5f);
  }
  // The skeleton's rest pose keeps the OFFSETs.
  const Skeleton skel = d.skeleton();
  EXPECT_VEC3_NEAR(skel.rest[1].translation, glm::vec3(100, 200, 300), 0.0f);
  EXPECT_VEC3_NEAR(skel.rest[2].translation, glm::vec3(7, 8, 9), 0.0f);
}

TEST(BvhStructure, EndSitesFileOrderAndSeveralRoots) {
  const std::string text = joinLines({
      "HIERARCHY",          // 1
      "ROOT A",             // 2
      "{",                  // 3
      "  OFFSET 1 0 0",     // 4
      "  CHANNELS 3 Xposition Yposition Zposition",
      "  JOINT B",          // 6
      "  {",
      "    OFFSET 0 1 0",
      "    CHANNELS 0",
      "    End Site",       // 10
      "    {",
      "      OFFSET 0 0 2",
      "    }",
      "  }",
      "  JOINT C",          // 15
      "  {",
      "    OFFSET 0 -1 0",
      "    CHANNELS 1 Zrotation",
      "    End Site",       // 19
      "    {",
      "      OFFSET 3 0 0",
      "    }",
      "  }",
      "}",
      "ROOT D",             // 25
      "{",
      "  OFFSET 5 5 5",
      "  CHANNELS 0",
      "  End Site",         // 29
      "  {",
      "    OFFSET 1 1 1",
      "  }",
      "}",
      "MOTION",
      "Frames: 1",
      "Frame Time: 1",
      "0.25 0 0 90",
  });
  const BvhData d = parseOk(text);
  const std::vector<std::string> names{"A", "B", "B_End", "C", "C_End", "D", "D_End"};
  const std::vector<int> parents{-1, 0, 1, 0, 3, -1, 5};
  const std::vector<bool> ends{false, false, true, false, true, false, true};
  const std::vector<int> lines{2, 6, 10, 15, 19, 25, 29};
  const std::vector<glm::vec3> offsets{{1, 0, 0}, {0, 1, 0}, {0, 0, 2}, {0, -1, 0}, {3, 0, 0}, {5, 5, 5}, {1, 1, 1}};
  ASSERT_EQ(d.joints.size(), names.size());
  for (size_t i = 0; i < names.size(); ++i) {
    SCOPED_TRACE(names[i]);
    EXPECT_EQ(d.joints[i].name, names[i]);
    EXPECT_EQ(d.joints[i].parent, parents[i]);
    EXPECT_LT(d.joints[i].parent, static_cast<int>(i));
    EXPECT_EQ(d.joints[i].endSite, ends[i]);
    EXPECT_EQ(d.joints[i].line, lines[i]);
    EXPECT_VEC3_NEAR(d.joints[i].offset, offsets[i], 0.0f);
    if (ends[i]) {
      EXPECT_TRUE(d.joints[i].channels.empty());
    }
  }
  EXPECT_EQ(d.channelCount, 4);
  EXPECT_EQ(d.joints[0].firstChannel, 0);
  EXPECT_EQ(d.joints[3].firstChannel, 3);
  ASSERT_EQ(d.joints[3].channels.size(), 1u);
  EXPECT_EQ(d.joints[3].channels[0], BvhChannel::Zrotation);

  const Skeleton skel = d.skeleton();
  EXPECT_EQ(skel.validate(), "");
  EXPECT_EQ(skel.names, names);
  EXPECT_EQ(skel.parents, parents);
  // A at (0.25,0,0) (channels replace its OFFSET); B (0.25,1,0), B_End (0.25,1,2);
  // C (0.25,-1,0) turned Rz(90): its End Site (3,0,0) -> (0,3,0), so (0.25,2,0).
  // D is its own root at (5,5,5), D_End at (6,6,6).
  const std::vector<glm::vec3> expected{{0.25f, 0, 0}, {0.25f, 1, 0}, {0.25f, 1, 2}, {0.25f, -1, 0},
                                        {0.25f, 2, 0}, {5, 5, 5},     {6, 6, 6}};
  for (const auto& w : {worldFromFrame(d, 0), worldFromClip(d, 0)})
    for (size_t i = 0; i < expected.size(); ++i) {
      SCOPED_TRACE(names[i]);
      EXPECT_VEC3_NEAR(position(w[i]), expected[i], 1e-6f);
    }
}

TEST(BvhStructure, EndSiteNamesNeverTakeARealJointName) {
  // A real joint literally called "A_End" comes after A's End Site: the End Site yields.
  const char* text =
      "HIERARCHY\nROOT A\n{\n OFFSET 0 0 0\n CHANNELS 3 Zrotation Xrotation Yrotation\n"
      " End Site\n {\n  OFFSET 0 1 0\n }\n"
      " JOINT A_End\n {\n  OFFSET 1 0 0\n  CHANNELS 3 Zrotation Xrotation Yrotation\n"
      "  End Site\n  {\n   OFFSET 0 0 1\n  }\n }\n}\n"
      "MOTION\nFrames: 1\nFrame Time: 0.1\n0 0 0 0 0 0\n";
  Result<BvhData> r = parseBvh(text, "names.bvh");
  ASSERT_TRUE(r.ok()) << r.error();
  ASSERT_EQ(r->joints.size(), 4u);
  EXPECT_EQ(r->joints[0].name, "A");
  EXPECT_EQ(r->joints[1].name, "A_End.2");
  EXPECT_TRUE(r->joints[1].endSite);
  EXPECT_EQ(r->joints[2].name, "A_End");
  EXPECT_FALSE(r->joints[2].endSite);
  EXPECT_EQ(r->joints[3].name, "A_End_End");
  EXPECT_TRUE(r->skeleton().validate().empty());
}

TEST(BvhStructure, Latin1NamesBecomeUtf8) {
  // "\xC9paule" is "Épaule" in Latin-1 (an older exporter); UTF-8 names pass unchanged.
  const std::string text =
      "HIERARCHY\nROOT \xC9paule\n{\n OFFSET 0 0 0\n CHANNELS 3 Zrotation Xrotation Yrotation\n"
      " JOINT Gen\xC3\xBBt\n {\n  OFFSET 0 1 0\n  CHANNELS 0\n }\n}\n"
      "MOTION\nFrames: 1\nFrame Time: 0.1\n0 0 0\n";
  Result<BvhData> r = parseBvh(text, "latin1.bvh");
  ASSERT_TRUE(r.ok()) << r.error();
  EXPECT_EQ(r->joints[0].name, "\xC3\x89paule");
  EXPECT_EQ(r->joints[1].name, "Gen\xC3\xBBt");
  EXPECT_TRUE(isValidUtf8(r->joints[0].name));
}

TEST(BvhStructure, FrameNIsAtNTimesFrameTime) {
  const std::string text = joinLines({"HIERARCHY", "ROOT R", "{", "OFFSET 0 0 0", "CHANNELS 2 Xposition Zrotation",
                                      "}", "MOTION", "Frames: 3", "Frame Time: 0.25", "0 0", "2 10", "6 30"});
  const BvhData d = parseOk(text);
  EXPECT_EQ(d.frameCount, 3);
  EXPECT_DOUBLE_EQ(d.frameTime, 0.25);
  const Clip clip = d.clip();
  EXPECT_DOUBLE_EQ(clip.frameTime, 0.25);
  EXPECT_FLOAT_EQ(ownFrameGrid(clip).frameToTime(2), 0.5f);
  EXPECT_FLOAT_EQ(clip.duration(), 0.5f);
  for (const Channel& ch : clip.channels) {
    ASSERT_EQ(ch.times.size(), 3u);
    EXPECT_FLOAT_EQ(ch.times[0], 0.0f);
    EXPECT_FLOAT_EQ(ch.times[1], 0.25f);
    EXPECT_FLOAT_EQ(ch.times[2], 0.5f);
  }
  const Skeleton skel = d.skeleton();
  auto sample = [&](float t) {
    Pose p = Pose::rest(skel);
    sampleClip(clip, t, p);
    return p.local[0];
  };
  EXPECT_FLOAT_EQ(sample(0.25f).translation.x, 2.0f);   // frame 1
  EXPECT_FLOAT_EQ(sample(0.5f).translation.x, 6.0f);    // frame 2
  EXPECT_NEAR(sample(0.375f).translation.x, 4.0f, 1e-6f);  // halfway between frames 1 and 2
  // Halfway between 10 and 30 degrees about Z is 20 degrees.
  EXPECT_SAME_ROTATION(sample(0.375f).rotation, glm::angleAxis(glm::radians(20.0f), glm::vec3(0, 0, 1)), 1e-6f);
  EXPECT_FLOAT_EQ(sample(9.0f).translation.x, 6.0f);   // clamped after the end
  EXPECT_FLOAT_EQ(sample(-1.0f).translation.x, 0.0f);  // and before the start
  expectClipAgreesWithFrames(d);
}

TEST(BvhFormat, CrlfTabsLeadingDotNamesOnBraceLinesAndBlankMotionLines) {
  const std::vector<std::string> lines{
      "HIERARCHY",
      "ROOT Hips {",
      "\tOFFSET\t1\t2\t3",
      "\tCHANNELS\t6\tXposition\tYposition\tZposition\tZrotation\tYrotation\tXrotation",
      "\tJOINT Chest {",
      "\t\tOFFSET\t0\t2\t0",
      "\t\tCHANNELS\t3\tZrotation\tYrotation\tXrotation",
      "\t\tEnd Site {",
      "\t\t\tOFFSET\t0\t1\t0",
      "\t\t}",
      "\t}",
      "}",
      "MOTION",
      "",
      "Frames:\t2",
      "Frame Time: .0083333",
      "",
      "0\t0\t0\t0\t0\t0\t0\t0\t0",
      "",
      " \t ",
      "1\t2\t3\t0\t0\t90\t0\t0\t0",
      "",
  };
  for (const std::string& eol : std::vector<std::string>{"\r\n", "\n", "\r"}) {
    SCOPED_TRACE(eol == "\r\n" ? "CRLF" : eol == "\n" ? "LF" : "CR");
    const BvhData d = parseOk(joinLines(lines, eol));
    ASSERT_EQ(d.joints.size(), 3u);
    EXPECT_EQ(d.joints[0].name, "Hips");
    EXPECT_EQ(d.joints[1].name, "Chest");
    EXPECT_EQ(d.joints[2].name, "Chest_End");
    EXPECT_EQ(d.joints[1].line, 5);
    EXPECT_EQ(d.frameCount, 2);
    EXPECT_DOUBLE_EQ(d.frameTime, 0.0083333);
    EXPECT_FLOAT_EQ(ownFrameGrid(d.clip()).frameToTime(1), 0.0083333f);
    // Frame 1: Hips at (1,2,3) turned Rx(90) (y -> z). Chest = (1,2,3) + (0,0,2) = (1,2,5);
    // its End Site (0,1,0) -> (0,0,1): (1,2,6).
    for (const auto& w : {worldFromFrame(d, 1), worldFromClip(d, 1)}) {
      EXPECT_VEC3_NEAR(position(w[1]), glm::vec3(1, 2, 5), 1e-6f);
      EXPECT_VEC3_NEAR(position(w[2]), glm::vec3(1, 2, 6), 1e-6f);
    }
  }
  // Line numbers still count right with CRLF: a bad value on line 21.
  std::vector<std::string> bad = lines;
  bad[20] = "1\t2\t3\t0\t0\tninety\t0\t0\t0";
  Result<BvhData> r = parseBvh(joinLines(bad, "\r\n"), "crlf.bvh");
  ASSERT_FALSE(r.ok());
  EXPECT_EQ(r.error().rfind("crlf.bvh:21: ", 0), 0u) << r.error();
}

TEST(BvhFormat, NumbersAsWritersPrintThem) {
  const std::string text = joinLines({"HIERARCHY", "ROOT R", "{", "OFFSET -.5 +2 1e-1", "CHANNELS 3 Xposition Yposition Zposition",
                                      "}", "MOTION", "Frames: 1", "Frame Time: 1E-2", "1. -2.5E+1 +.25"});
  const BvhData d = parseOk(text);
  EXPECT_VEC3_NEAR(d.joints[0].offset, glm::vec3(-0.5f, 2.0f, 0.1f), 0.0f);
  EXPECT_DOUBLE_EQ(d.frameTime, 0.01);
  EXPECT_VEC3_NEAR(d.framePose(0).local[0].translation, glm::vec3(1.0f, -25.0f, 0.25f), 0.0f);
}

// ---------------------------------------------------------------------------------------
// Malformed files: one failed Result, one line, naming the source and the line.

// A valid file with 20 lines; the cases below damage it.
const std::vector<std::string> kGood{
    "HIERARCHY",                                                               // 1
    "ROOT Hips",                                                               // 2
    "{",                                                                       // 3
    "  OFFSET 0 0 0",                                                          // 4
    "  CHANNELS 6 Xposition Yposition Zposition Zrotation Xrotation Yrotation",  // 5
    "  JOINT Chest",                                                           // 6
    "  {",                                                                     // 7
    "    OFFSET 0 5 0",                                                        // 8
    "    CHANNELS 3 Zrotation Xrotation Yrotation",                            // 9
    "    End Site",                                                            // 10
    "    {",                                                                   // 11
    "      OFFSET 0 3 0",                                                      // 12
    "    }",                                                                   // 13
    "  }",                                                                     // 14
    "}",                                                                       // 15
    "MOTION",                                                                  // 16
    "Frames: 2",                                                               // 17
    "Frame Time: 0.04",                                                        // 18
    "0 0 0 0 0 0 0 0 0",                                                       // 19
    "1 2 3 4 5 6 7 8 9",                                                       // 20
};

std::vector<std::string> replaced(int line, const std::string& text) {
  std::vector<std::string> v = kGood;
  v[line - 1] = text;
  return v;
}
std::vector<std::string> without(int line) {
  std::vector<std::string> v = kGood;
  v.erase(v.begin() + (line - 1));
  return v;
}
std::vector<std::string> inserted(int line, const std::string& text) {
  std::vector<std::string> v = kGood;
  v.insert(v.begin() + (line - 1), text);
  return v;
}
std::string withoutFinalNewline(const std::string& s) { return s.substr(0, s.size() - 1); }
std::vector<std::string> firstLines(int n) { return std::vector<std::string>(kGood.begin(), kGood.begin() + n); }

struct BadCase {
  const char* what;
  std::string text;
  int line;
  const char* mentions;  // a word the message must contain
};

std::vector<BadCase> badCases() {
  return {
      {"empty file", "", 1, "empty"},
      {"missing HIERARCHY", joinLines(without(1)), 1, "HIERARCHY"},
      {"misspelt HIERARCHY", joinLines(replaced(1, "HIERACHY")), 1, "HIERARCHY"},
      {"HIERARCHY after blank lines is missing", "\n\n" + joinLines(without(1)), 3, "HIERARCHY"},
      // Truncated: the end of the text is on line N+1 when the file ends with a newline
      // (the line an editor puts the cursor on), on line N when it does not.
      {"truncated in an OFFSET", joinLines(firstLines(7)) + "    OFFSET 0 5\n", 9, "OFFSET"},
      {"truncated in an OFFSET, no final newline", joinLines(firstLines(7)) + "    OFFSET 0 5", 8, "OFFSET"},
      {"truncated after End Site", joinLines(firstLines(10)), 11, "{"},
      {"truncated after CHANNELS", joinLines(firstLines(9)), 10, "Chest"},
      {"truncated after CHANNELS, no final newline", withoutFinalNewline(joinLines(firstLines(9))), 9, "Chest"},
      // A missing '}' shows where the hierarchy ends: the MOTION line (now line 15).
      {"missing '}' of the End Site", joinLines(without(13)), 15, "}"},
      {"missing '}' before a second ROOT", joinLines(inserted(15, "ROOT Other")), 15, "ROOT"},
      {"End Site given a child", joinLines(replaced(13, "    JOINT Finger")), 13, "End Site"},
      {"extra '}'", joinLines(inserted(16, "}")), 16, "}"},
      {"missing '{' of a JOINT", joinLines(without(7)), 7, "{"},
      {"missing '{' of the ROOT", joinLines(without(3)), 3, "{"},
      {"missing '{' of an End Site", joinLines(without(11)), 11, "{"},
      {"CHANNELS 3 listing 2 names", joinLines(replaced(9, "    CHANNELS 3 Zrotation Xrotation")), 9, "lists 2"},
      {"CHANNELS 2 listing 3 names", joinLines(replaced(9, "    CHANNELS 2 Zrotation Xrotation Yrotation")), 9, "Yrotation"},
      {"unknown channel", joinLines(replaced(9, "    CHANNELS 3 Zrotation Xrotation Wrotation")), 9, "Wrotation"},
      {"CHANNELS without a count", joinLines(replaced(9, "    CHANNELS Zrotation Xrotation Yrotation")), 9, "count"},
      {"word in an OFFSET", joinLines(replaced(8, "    OFFSET 0 five 0")), 8, "five"},
      {"OFFSET with two numbers", joinLines(replaced(8, "    OFFSET 0 5")), 8, "CHANNELS"},
      {"nan in an OFFSET", joinLines(replaced(12, "      OFFSET 0 nan 0")), 12, "nan"},
      {"inf in an OFFSET", joinLines(replaced(4, "  OFFSET inf 0 0")), 4, "inf"},
      {"duplicate joint name", joinLines(replaced(6, "  JOINT Hips")), 6, "Hips"},
      {"missing MOTION", joinLines(firstLines(15)), 16, "MOTION"},
      {"missing MOTION keyword before the motion data", joinLines(without(16)), 16, "Frames:"},
      {"missing Frames", joinLines(without(17)), 17, "Frames:"},
      {"Frames not a number", joinLines(replaced(17, "Frames: two")), 17, "two"},
      {"negative Frames", joinLines(replaced(17, "Frames: -1")), 17, "Frames"},
      {"fractional Frames", joinLines(replaced(17, "Frames: 1.5")), 17, "Frames"},
      {"Frame Time nan", joinLines(replaced(18, "Frame Time: nan")), 18, "nan"},
      {"Frame Time zero", joinLines(replaced(18, "Frame Time: 0")), 18, "Frame Time"},
      // Found by fuzz_bvh (10-minute run): the key time of frame 1 overflowed float.
      {"Frame Time beyond float range of key times", joinLines(replaced(18, "Frame Time: 8e127")), 18, "float range"},
      {"word in the motion", joinLines(replaced(20, "1 2 3 4 x 6 7 8 9")), 20, "'x'"},
      {"nan in the motion", joinLines(replaced(19, "0 0 0 nan 0 0 0 0 0")), 19, "nan"},
      {"NaN in the motion", joinLines(replaced(20, "1 2 3 4 5 6 7 8 NaN")), 20, "NaN"},
      {"inf in the motion", joinLines(replaced(20, "1 2 3 4 inf 6 7 8 9")), 20, "inf"},
      {"-infinity in the motion", joinLines(replaced(19, "-infinity 0 0 0 0 0 0 0 0")), 19, "infinity"},
      {"overflowing number in the motion", joinLines(replaced(20, "1 2 3 4 5 6 7 8 1e999")), 20, "1e999"},
      // Found by fuzz_bvh: finite as double, infinite as float (the stored type).
      {"number beyond float range in the motion", joinLines(replaced(20, "1 2 3 4 5 6 7 8 1e39")), 20, "1e39"},
      {"number beyond float range in an OFFSET", joinLines(replaced(12, "      OFFSET 0 -4e38 0")), 12, "-4e38"},
      {"two signs in the motion", joinLines(replaced(20, "1 2 +-3 4 5 6 7 8 9")), 20, "+-3"},
      {"too few values", joinLines(replaced(19, "0 0 0 0 0 0 0 0")), 19, "8 values"},
      {"too many values", joinLines(replaced(20, "1 2 3 4 5 6 7 8 9 10")), 20, "10 values"},
      {"too few motion lines", joinLines(replaced(17, "Frames: 3")), 21, "Frames says 3"},
      {"too few motion lines, no final newline", withoutFinalNewline(joinLines(replaced(17, "Frames: 3"))), 20, "Frames says 3"},
      {"too few motion lines after blank lines", joinLines(replaced(17, "Frames: 3")) + "\n\n", 23, "Frames says 3"},
  };
}

TEST(BvhErrors, OneLineNamingSourceAndLine) {
  for (const BadCase& c : badCases()) {
    SCOPED_TRACE(c.what);
    Result<BvhData> r = parseBvh(c.text, "bad.bvh");
    EXPECT_FALSE(r.ok());
    if (r.ok()) continue;
    const std::string& e = r.error();
    EXPECT_EQ(e.find('\n'), std::string::npos) << e;
    EXPECT_EQ(e.find('\r'), std::string::npos) << e;
    const std::string prefix = "bad.bvh:" + std::to_string(c.line) + ": ";
    EXPECT_EQ(e.rfind(prefix, 0), 0u) << "expected '" << prefix << "...', got: " << e;
    EXPECT_GT(e.size(), prefix.size() + 5) << e;  // says what is wrong, not just where
    EXPECT_NE(e.find(c.mentions), std::string::npos) << "message should mention '" << c.mentions << "': " << e;
  }
}

TEST(BvhErrors, TheUndamagedFileParses) {
  // Guards the cases above: their base file is valid, so each failure comes from its damage.
  const BvhData d = parseOk(joinLines(kGood));
  EXPECT_EQ(d.joints.size(), 3u);
  EXPECT_EQ(d.frameCount, 2);
  EXPECT_EQ(d.channelCount, 9);
  const BvhData noFinalNewline = parseOk(withoutFinalNewline(joinLines(kGood)));
  EXPECT_EQ(noFinalNewline.frameCount, 2);
}

TEST(BvhErrors, LoadBvhNamesTheFile) {
  const std::string dir = makeTempDir();
  ASSERT_FALSE(dir.empty());
  {
    const std::string missing = dir + "/no_such_file.bvh";
    Result<BvhData> r = loadBvh(missing);
    ASSERT_FALSE(r.ok());
    EXPECT_NE(r.error().find(missing), std::string::npos) << r.error();
    EXPECT_EQ(r.error().find('\n'), std::string::npos);
  }
  {
    Result<BvhData> r = loadBvh(dir);
    ASSERT_FALSE(r.ok());
    EXPECT_NE(r.error().find(dir), std::string::npos) << r.error();
    EXPECT_EQ(r.error().find('\n'), std::string::npos);
  }
  {
    const std::string bad = dir + "/bad.bvh";
    writeFile(bad, joinLines(replaced(20, "1 2 3 4 x 6 7 8 9")));
    Result<BvhData> r = loadBvh(bad);
    ASSERT_FALSE(r.ok());
    EXPECT_EQ(r.error().rfind(bad + ":20: ", 0), 0u) << r.error();
  }
  {
    const std::string good = dir + "/good.bvh";
    writeFile(good, joinLines(kGood));
    Result<BvhData> r = loadBvh(good);
    ASSERT_TRUE(r.ok()) << r.error();
    EXPECT_EQ(r->joints.size(), 3u);
  }
  runCommand("rm -rf '" + dir + "'");
}

// ---------------------------------------------------------------------------------------
// The command line on malformed files: exit 1, one line on stderr, no crash.

TEST(BvhCli, MalformedFileGivesExitOneAndOneLine) {
  const std::string dir = makeTempDir();
  ASSERT_FALSE(dir.empty());
  struct CliCase {
    std::string text;
    int line;
  };
  const std::vector<CliCase> cases{
      {joinLines(replaced(20, "1 2 3 4 x 6 7 8 9")), 20},
      {joinLines(replaced(9, "    CHANNELS 3 Zrotation Xrotation")), 9},
      {joinLines(without(13)), 15},
      {joinLines(replaced(17, "Frames: 3")), 21},
      {"", 1},
  };
  for (size_t i = 0; i < cases.size(); ++i) {
    SCOPED_TRACE("case " + std::to_string(i));
    const std::string path = dir + "/bad" + std::to_string(i) + ".bvh";
    writeFile(path, cases[i].text);
    std::string out, err;
    const int status = runCommand(std::string("'") + KINEMA_BINARY + "' pose '" + path + "' --frame 0 --json", &out, &err);
    EXPECT_EQ(status, 1) << err;
    EXPECT_EQ(out, "");
    ASSERT_FALSE(err.empty());
    EXPECT_EQ(std::count(err.begin(), err.end(), '\n'), 1) << err;
    EXPECT_EQ(err.back(), '\n');
    EXPECT_NE(err.find(path + ":" + std::to_string(cases[i].line) + ": "), std::string::npos) << err;
  }
  {  // The same command on the undamaged file succeeds, so the failures above are the damage.
    const std::string path = dir + "/good.bvh";
    writeFile(path, joinLines(kGood));
    std::string out, err;
    EXPECT_EQ(runCommand(std::string("'") + KINEMA_BINARY + "' pose '" + path + "' --frame 1 --json", &out, &err), 0)
        << err;
    EXPECT_NE(out.find("\"Chest_End\""), std::string::npos) << out;
  }
  {  // A missing file: exit 1, one line naming it.
    const std::string path = dir + "/missing.bvh";
    std::string out, err;
    EXPECT_EQ(runCommand(std::string("'") + KINEMA_BINARY + "' pose '" + path + "' --frame 0 --json", &out, &err), 1);
    EXPECT_EQ(std::count(err.begin(), err.end(), '\n'), 1) << err;
    EXPECT_NE(err.find(path), std::string::npos) << err;
  }
  runCommand("rm -rf '" + dir + "'");
}

}  // namespace
}  // namespace kinema

namespace kinema {
namespace KINEMA_UNITY_ID {

TEST(TextEncoding, Utf8ValidationMatchesTheStandard) {
  EXPECT_TRUE(isValidUtf8(""));
  EXPECT_TRUE(isValidUtf8("plain ascii"));
  EXPECT_TRUE(isValidUtf8("\xC3\x89paule \xE2\x82\xAC \xF0\x9F\x98\x80"));  // É, €, 😀
  EXPECT_FALSE(isValidUtf8("\xC9paule"));                                 // Latin-1 byte
  EXPECT_FALSE(isValidUtf8("\xC0\xAF"));                                  // overlong '/'
  EXPECT_FALSE(isValidUtf8("\xED\xA0\x80"));                              // surrogate U+D800
  EXPECT_FALSE(isValidUtf8("\xF4\x90\x80\x80"));                          // past U+10FFFF
  EXPECT_FALSE(isValidUtf8("\xE2\x82"));                                  // truncated
  EXPECT_EQ(toUtf8("abc"), "abc");
  EXPECT_EQ(toUtf8("\xFF"), "\xC3\xBF");  // U+00FF
}

}  // namespace
}  // namespace kinema
