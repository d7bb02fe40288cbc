// `kinema render` on skinned glTF files: the shaded, textured mesh matches a golden image on
// EGL and OSMesa, bones can be hidden or drawn x-ray, weights show as heat colours, and the
// new options fail like the others. llvmpipe is forced so a GPU host gives the same pixels.
#include <algorithm>
#include <cstdlib>

#include "io/image.h"
#include "render/image_compare.h"
#include "test_support.h"

namespace kinema::test {
namespace KINEMA_UNITY_ID {

const std::string kSoftware =
    "LIBGL_ALWAYS_SOFTWARE=1 MESA_GL_VERSION_OVERRIDE=3.3 ASAN_OPTIONS=${ASAN_OPTIONS:+$ASAN_OPTIONS:}detect_leaks=0 ";

int kinema(const std::string& args, std::string* err = nullptr) {
  std::string out;
  return runCommand(kSoftware + KINEMA_BINARY + " " + args, &out, err);
}

// Pixels of a colour class, counted.
template <class Pred>
int countPixels(const Image& im, Pred pred) {
  int n = 0;
  for (int y = 0; y < im.height; ++y)
    for (int x = 0; x < im.width; ++x)
      if (pred(im.pixel(x, y))) ++n;
  return n;
}
bool isBackgroundGrey(const std::uint8_t* p) { return std::abs(p[0] - p[1]) < 6 && std::abs(p[1] - p[2]) < 6 && p[0] < 110; }
bool isHeatBlue(const std::uint8_t* p) { return p[2] > 60 && p[0] < 0.3 * p[2] && p[1] < 0.3 * p[2]; }
bool isHeatWarm(const std::uint8_t* p) { return p[0] > 60 && p[2] < 0.35 * p[0]; }  // yellow to red
bool isXRayBlue(const std::uint8_t* p) { return p[2] > 120 && p[2] > p[0] + 50; }

class MeshRenderCli : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = makeTempDir();
    if (!sharedDataDir().empty()) cesium_ = "'" + sharedDataDir() + "/gltf/CesiumMan.glb'";
  }
  void TearDown() override { std::system(("rm -rf '" + dir_ + "'").c_str()); }
  std::string dir_, err_, cesium_;
};

// Same rule as the skeleton goldens (render_cli_test.cpp): at most 0.1% of the pixels off by
// more than 8 levels, against the committed image and between the two backends.
TEST_F(MeshRenderCli, CesiumManMidAnimationMatchesGoldenWithEglAndOsMesa) {
  KINEMA_REQUIRE_SHARED_DATA();
  const Image reference = loadImageOrFail(std::string(KINEMA_SOURCE_DIR) + "/tests/render/golden/cesium_man_t1.png");
  Image images[2];
  const char* backends[2] = {"egl", "osmesa"};
  for (int k = 0; k < 2; ++k) {
    const std::string path = dir_ + "/" + backends[k] + ".png";
    ASSERT_EQ(kinema("render " + cesium_ + " --time 1 --size 320x240 --backend " + backends[k] + " --out " + path, &err_), 0)
        << err_;
    images[k] = loadImageOrFail(path);
    const int diff = differingPixels(images[k], reference, 8);
    EXPECT_GE(diff, 0) << "size differs from the reference";
    EXPECT_LE(diff, 320 * 240 / 1000) << backends[k] << ": " << diff << " pixels differ from the golden image";
  }
  const int diff = differingPixels(images[0], images[1], 8);
  EXPECT_GE(diff, 0);
  EXPECT_LE(diff, 320 * 240 / 1000) << "EGL and OSMesa disagree on " << diff << " pixels";
}

TEST_F(MeshRenderCli, MeshCoversTheBonesUnlessXRayAndWeightsShowAsHeat) {
  KINEMA_REQUIRE_SHARED_DATA();
  const std::string common = cesium_ + " --time 1 --camera 0,0 --size 320x240 --out " + dir_;
  ASSERT_EQ(kinema("render " + common + "/none.png --bones none", &err_), 0) << err_;
  ASSERT_EQ(kinema("render " + common + "/xray.png --bones xray", &err_), 0) << err_;
  const Image none = loadImageOrFail(dir_ + "/none.png"), xray = loadImageOrFail(dir_ + "/xray.png");
  // The body fills a good part of the frame (the camera frames the mesh, not just the joints).
  const int body = 320 * 240 - countPixels(none, isBackgroundGrey);
  EXPECT_GT(body, 320 * 240 / 20);
  // X-ray draws the (blue) bones over the body; without bones the image has hardly any of that blue
  // (CesiumMan's texture has light-blue stripes, far less saturated).
  EXPECT_GT(countPixels(xray, isXRayBlue), countPixels(none, isXRayBlue) + 200);

  // The selection stays opaque orange in x-ray; drawn solid it hides inside the thigh.
  ASSERT_EQ(kinema("render " + common + "/xray_sel.png --bones xray --select leg_joint_L_1", &err_), 0) << err_;
  ASSERT_EQ(kinema("render " + common + "/on_sel.png --bones on --select leg_joint_L_1", &err_), 0) << err_;
  auto orange = [](const std::uint8_t* p) { return p[0] > 150 && p[1] > 0.45 * p[0] && p[1] < 0.8 * p[0] && p[2] < 0.3 * p[0]; };
  EXPECT_GT(countPixels(loadImageOrFail(dir_ + "/xray_sel.png"), orange), countPixels(loadImageOrFail(dir_ + "/on_sel.png"), orange) + 60);
  // --mesh off: the skeleton alone, far fewer non-background pixels than the body.
  ASSERT_EQ(kinema("render " + common + "/bare.png --mesh off", &err_), 0) << err_;
  EXPECT_LT(320 * 240 - countPixels(loadImageOrFail(dir_ + "/bare.png"), isBackgroundGrey), body / 2);

  // Heat colours: the left forearm's weights are warm on the arm, blue elsewhere.
  ASSERT_EQ(kinema("render " + common + "/weights.png --bones none --weights Skeleton_arm_joint_L__3_", &err_), 0) << err_;
  const Image weights = loadImageOrFail(dir_ + "/weights.png");
  const int blue = countPixels(weights, isHeatBlue), warm = countPixels(weights, isHeatWarm);
  EXPECT_GT(blue, body / 2);
  EXPECT_GT(warm, 20);
  EXPECT_LT(warm, body / 5);
}

TEST_F(MeshRenderCli, BadBonesOrWeightsFailWithOneLine) {
  KINEMA_REQUIRE_SHARED_DATA();
  const std::string out = " --out " + dir_ + "/x.png";
  EXPECT_EQ(kinema("render " + cesium_ + " --bones sometimes" + out, &err_), 2) << err_;
  EXPECT_EQ(kinema("render " + cesium_ + " --mesh sometimes" + out, &err_), 2) << err_;
  EXPECT_EQ(kinema("render " + cesium_ + " --weights Nobody" + out, &err_), 1) << err_;
  EXPECT_NE(err_.find("Nobody"), std::string::npos) << err_;
  EXPECT_EQ(std::count(err_.begin(), err_.end(), '\n'), 1) << err_;
}

}  // namespace
}  // namespace kinema::test
