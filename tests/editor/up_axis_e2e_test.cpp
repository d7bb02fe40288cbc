// Issue 19 (h19cli): File > Open offers the BVH up axis for .bvh names; Z reads a Z-up file
// (what Blender's BVH exporter writes) standing up. One editor launch: open the Z-up file
// with "Z", save it as .kinema, and compare with the same character written Y-up. The
// screenshot (build/up_axis_e2e/open_z_up.png) shows it standing, the walking hips hung from
// the root by a dashed relationship line.
#include <gtest/gtest.h>

#include "core/forward_kinematics.h"
#include "editor/e2e_harness.h"
#include "io/kinema_file.h"
#include "io/scene_files.h"
#include "test_support.h"

namespace kinema::test {
namespace KINEMA_UNITY_ID {

using namespace e2e;

class UpAxisE2e : public TempDirSuite<UpAxisE2e> {
 public:
  static constexpr const char* kShotFolder = "up_axis_e2e";
};

// Root on the ground, Hips 0.9 above it with their own (walking) position channels, a leg
// down to the ground and a head. zUp writes every vector (x, y, z) as (x, -z, y).
std::string walker(bool zUp) {
  const auto v = [zUp](double x, double y, double z) {
    char b[96];
    std::snprintf(b, sizeof b, "%g %g %g", x, zUp ? -z : y, zUp ? y : z);
    return std::string(b);
  };
  std::string s = "HIERARCHY\nROOT Root\n{\n  OFFSET 0 0 0\n  CHANNELS 3 Zrotation Xrotation Yrotation\n";
  s += "  JOINT Hips\n  {\n    OFFSET " + v(0, 0.9, 0) +
       "\n    CHANNELS 6 Xposition Yposition Zposition Zrotation Xrotation Yrotation\n";
  s += "    JOINT Leg\n    {\n      OFFSET " + v(0.12, -0.45, 0) + "\n      CHANNELS 3 Zrotation Xrotation Yrotation\n";
  s += "      End Site\n      {\n        OFFSET " + v(0, -0.45, 0) + "\n      }\n    }\n";
  s += "    JOINT Head\n    {\n      OFFSET " + v(0, 0.7, 0) + "\n      CHANNELS 3 Zrotation Xrotation Yrotation\n";
  s += "      End Site\n      {\n        OFFSET " + v(0, 0.2, 0) + "\n      }\n    }\n  }\n}\n";
  s += "MOTION\nFrames: 2\nFrame Time: 0.0333333\n";
  s += "0 0 0 " + v(0.5, 0.9, 0) + " 0 0 0 0 0 0 0 0 0\n";
  s += "0 0 0 " + v(0.6, 0.9, 0.1) + " 0 0 0 0 0 0 0 0 0\n";
  return s;
}

TEST_F(UpAxisE2e, OpenDialogReadsAZUpBvhStandingUp) {
  const std::string zup = dir_ + "/walker_zup.bvh", yup = dir_ + "/walker_yup.bvh", saved = dir_ + "/opened.kinema";
  writeFile(zup, walker(true));
  writeFile(yup, walker(false));
  Script s;
  s.chord("O", {"ctrl"}).wait(2).type(zup).wait(2);
  s.clickItem("Open/Up Z").wait(2).clickItem("Open/Accept").wait(6);
  s.saveAs(saved);
  const json d = runEditor(dir_, shotDir(), s, "open_z_up");
  ASSERT_TRUE(d.is_object());
  EXPECT_EQ(d["errors"].size(), 0u) << d["errors"];
  ASSERT_TRUE(d["items"].contains("Open/Up Z")) << "the up-axis choice was not shown for a .bvh name";
  const Result<Scene> opened = loadKinemaFile(saved), want = loadScene(yup);
  ASSERT_TRUE(opened.ok()) << opened.error();
  ASSERT_TRUE(want.ok()) << want.error();
  ASSERT_EQ(opened->skeleton.names, want->skeleton.names);
  const std::vector<glm::mat4> a = computeWorld(opened->skeleton, Pose::rest(opened->skeleton));
  const std::vector<glm::mat4> b = computeWorld(want->skeleton, Pose::rest(want->skeleton));
  for (size_t j = 0; j < a.size(); ++j) EXPECT_VEC3_NEAR(glm::vec3(a[j][3]), glm::vec3(b[j][3]), 1e-5f);
  // Standing: the leg's end on the ground, the head's end 1.8 up along +Y.
  const int foot = opened->skeleton.find("Leg_End"), head = opened->skeleton.find("Head_End");
  ASSERT_GE(foot, 0);
  ASSERT_GE(head, 0);
  EXPECT_NEAR(a[foot][3].y, 0.0f, 1e-5f);
  EXPECT_NEAR(a[head][3].y, 1.8f, 1e-5f);
}

}  // namespace
}  // namespace kinema::test
