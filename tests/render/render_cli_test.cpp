// `kinema render`, plain `kinema` without a display, and `kinema edit` under Xvfb, through
// the built binary. Rendering is forced onto llvmpipe so a GPU host gives the same pixels.
#include <sys/stat.h>

#include <algorithm>
#include <set>

#include "io/image.h"
#include "render/image_compare.h"
#include "test_support.h"

namespace kinema::test {
namespace KINEMA_UNITY_ID {

// Under -DKINEMA_SANITIZE=ON, Mesa unloads its driver at exit and LeakSanitizer then reports
// the driver's own leftovers from an "<unknown module>" that no suppression can name, so
// leak checking is off for these GL subprocesses only (every other check stays on).
const std::string kSoftware =
    "LIBGL_ALWAYS_SOFTWARE=1 MESA_GL_VERSION_OVERRIDE=3.3 ASAN_OPTIONS=${ASAN_OPTIONS:+$ASAN_OPTIONS:}detect_leaks=0 ";

int kinema(const std::string& args, std::string* out = nullptr, std::string* err = nullptr) {
  return runCommand(kSoftware + KINEMA_BINARY + " " + args, out, err);
}

// Box around the lit bone faces: pixels much brighter than the background and the grid.
struct Box {
  int x0 = 1 << 30, y0 = 1 << 30, x1 = -1, y1 = -1;
  int width() const { return x1 - x0 + 1; }
  int height() const { return y1 - y0 + 1; }
};
Box brightBox(const Image& im) {
  Box b;
  for (int y = 0; y < im.height; ++y)
    for (int x = 0; x < im.width; ++x) {
      const std::uint8_t* p = im.pixel(x, y);
      if (p[0] > 140 && p[1] > 140 && p[2] > 140) {
        b.x0 = std::min(b.x0, x);
        b.y0 = std::min(b.y0, y);
        b.x1 = std::max(b.x1, x);
        b.y1 = std::max(b.y1, y);
      }
    }
  return b;
}

// Standard deviation of the bright pixels' x and y: a size measure that thin, tapering bone
// tips (which fade below the threshold when small) barely move.
glm::dvec2 brightSpread(const Image& im) {
  glm::dvec2 sum(0), sq(0);
  double n = 0;
  for (int y = 0; y < im.height; ++y)
    for (int x = 0; x < im.width; ++x) {
      const std::uint8_t* p = im.pixel(x, y);
      if (p[0] > 140 && p[1] > 140 && p[2] > 140) {
        sum += glm::dvec2(x, y);
        sq += glm::dvec2(x, y) * glm::dvec2(x, y);
        n += 1;
      }
    }
  if (n == 0) return glm::dvec2(0);
  const glm::dvec2 mean = sum / n;
  return glm::sqrt(sq / n - mean * mean);
}

// Centre of the selection-orange pixels.
glm::dvec2 orangeCentroid(const Image& im) {
  glm::dvec2 sum(0);
  double n = 0;
  for (int y = 0; y < im.height; ++y)
    for (int x = 0; x < im.width; ++x) {
      const std::uint8_t* p = im.pixel(x, y);
      if (p[0] > 90 && p[1] > 0.42 * p[0] && p[1] < 0.8 * p[0] && p[2] < 0.35 * p[0]) {  // not the red X axis
        sum += glm::dvec2(x, y);
        n += 1;
      }
    }
  EXPECT_GT(n, 3) << "no selection drawn";
  return n > 0 ? sum / n : glm::dvec2(0);
}

int distinctColors(const Image& im) {
  std::set<std::uint32_t> colors;
  for (size_t i = 0; i < im.rgba.size(); i += 4)
    colors.insert(im.rgba[i] | im.rgba[i + 1] << 8 | im.rgba[i + 2] << 16);
  return static_cast<int>(colors.size());
}

class RenderCli : public ::testing::Test {
 protected:
  void SetUp() override { dir_ = makeTempDir(); }
  void TearDown() override { std::system(("rm -rf '" + dir_ + "'").c_str()); }
  std::string dir_, out_, err_;
};

// The golden check: each backend matches the committed reference (a few pixels may differ
// by a little, e.g. another llvmpipe build rounding an edge differently), and they agree.
void expectGolden(const std::string& args, const std::string& golden, const std::string& dir) {
  const Image reference = loadImageOrFail(std::string(KINEMA_SOURCE_DIR) + "/tests/render/golden/" + golden);
  Image images[2];
  const char* backends[2] = {"egl", "osmesa"};
  for (int k = 0; k < 2; ++k) {
    const std::string path = dir + "/" + backends[k] + ".png";
    std::string err;
    ASSERT_EQ(kinema("render " + args + " --size 320x240 --backend " + backends[k] + " --out " + path, nullptr, &err), 0)
        << err;
    images[k] = loadImageOrFail(path);
    const int diff = differingPixels(images[k], reference, 8);
    EXPECT_GE(diff, 0) << "size differs from the reference";
    EXPECT_LE(diff, 320 * 240 / 1000) << backends[k] << " vs " << golden << ": " << diff << " pixels differ";
  }
  const int diff = differingPixels(images[0], images[1], 8);
  EXPECT_GE(diff, 0);
  EXPECT_LE(diff, 320 * 240 / 1000) << "EGL and OSMesa disagree on " << diff << " pixels";
}

TEST_F(RenderCli, DefaultCharacterMatchesGoldenWithEglAndOsMesa) {
  expectGolden("", "default_character.png", dir_);
}

TEST_F(RenderCli, MotionCaptureFrameMatchesGoldenWithEglAndOsMesa) {
  KINEMA_REQUIRE_SHARED_DATA();
  expectGolden("'" + sharedDataDir() + "/bvh/cmu_01_01_first720.bvh' --frame 240 --select LeftArm",
               "cmu_01_01_frame240.png", dir_);
}

// The skeleton alone (--mesh off): bone pixels and the orange selection measure the framing.
TEST_F(RenderCli, SizeScalesTheCharacterAndCameraTurnsIt) {
  ASSERT_EQ(kinema("render --mesh off --camera 0,0 --size 160x120 --out " + dir_ + "/small.png", &out_, &err_), 0) << err_;
  ASSERT_EQ(kinema("render --mesh off --camera 0,0 --size 320x240 --out " + dir_ + "/large.png", &out_, &err_), 0) << err_;
  const Image small = loadImageOrFail(dir_ + "/small.png"), large = loadImageOrFail(dir_ + "/large.png");
  ASSERT_EQ(small.width, 160);
  ASSERT_EQ(small.height, 120);
  ASSERT_EQ(large.width, 320);
  const Box s = brightBox(small), l = brightBox(large);
  ASSERT_GT(s.width(), 10);
  // Same framing at twice the pixels: the character's box doubles (to a couple of pixels).
  EXPECT_NEAR(l.width(), 2 * s.width(), 8);
  EXPECT_NEAR(l.height(), 2 * s.height(), 8);
  EXPECT_NEAR(brightSpread(large).x / brightSpread(small).x, 2.0, 0.1);
  EXPECT_NEAR(brightSpread(large).y / brightSpread(small).y, 2.0, 0.1);

  // The default character is in T-pose, arms along X: wide from the front (azimuth 0),
  // narrow from the side (azimuth 90). Its arm span is 1.5 units and its height 1.8.
  ASSERT_EQ(kinema("render --mesh off --camera 90,0 --size 320x240 --out " + dir_ + "/side.png", &out_, &err_), 0) << err_;
  const Box side = brightBox(loadImageOrFail(dir_ + "/side.png"));
  EXPECT_GT(double(l.width()) / l.height(), 0.6);
  EXPECT_LT(double(side.width()) / side.height(), 0.3);
  EXPECT_NEAR(side.height(), l.height(), l.height() * 0.1);

  // Twice the distance: half the hand-to-hand span on screen (both hands lie in the plane
  // z = 0 facing the camera, which looks at the skeleton's centre). The hands are found by
  // selecting each in turn: the selection is drawn orange.
  double span[2];
  for (int k = 0; k < 2; ++k) {
    const std::string camera = k == 0 ? "0,0,6" : "0,0,12";
    glm::dvec2 hand[2];
    for (int side = 0; side < 2; ++side) {
      const std::string path = dir_ + "/hand" + std::to_string(k) + std::to_string(side) + ".png";
      ASSERT_EQ(kinema(std::string("render --mesh off --select Hand.") + (side ? "R" : "L") + " --camera " + camera +
                           " --size 640x480 --out " + path, &out_, &err_), 0) << err_;
      hand[side] = orangeCentroid(loadImageOrFail(path));
    }
    span[k] = glm::length(hand[0] - hand[1]);
  }
  EXPECT_GT(span[0], 150.0);
  EXPECT_NEAR(span[1] / span[0], 0.5, 0.02);
}

TEST_F(RenderCli, SequenceWritesNumberedFramesWithProgress) {
  KINEMA_REQUIRE_SHARED_DATA();
  const std::string bvh = "'" + sharedDataDir() + "/bvh/cmu_01_01_first720.bvh'";
  ASSERT_EQ(kinema("render " + bvh + " --frames 100:129 --size 96x72 --out " + dir_ + "/seq/frame_%04d.png", &out_, &err_), 0)
      << err_;
  int progress = 0;
  for (size_t p = err_.find("frame "); p != std::string::npos; p = err_.find("frame ", p + 1)) ++progress;
  EXPECT_GE(progress, 30) << err_;
  EXPECT_NE(err_.find("(30/30)"), std::string::npos) << err_;
  for (int f = 100; f <= 129; ++f) {
    char name[64];
    std::snprintf(name, sizeof name, "/seq/frame_%04d.png", f);
    struct stat st {};
    EXPECT_EQ(::stat((dir_ + name).c_str(), &st), 0) << name;
  }
  struct stat st {};
  EXPECT_NE(::stat((dir_ + "/seq/frame_0099.png").c_str(), &st), 0);
  EXPECT_NE(::stat((dir_ + "/seq/frame_0130.png").c_str(), &st), 0);
  // The subject moves: the first and last frames differ, same camera.
  EXPECT_GT(differingPixels(loadImageOrFail(dir_ + "/seq/frame_0100.png"), loadImageOrFail(dir_ + "/seq/frame_0129.png"), 24), 20);
}

TEST_F(RenderCli, BadArgumentsAndInputsFailWithOneLine) {
  const std::string out = " --out " + dir_ + "/x.png";
  EXPECT_EQ(kinema("render --size 12" + out, &out_, &err_), 2) << err_;
  EXPECT_EQ(kinema("render --camera a,b" + out, &out_, &err_), 2) << err_;
  EXPECT_EQ(kinema("render --backend vulkan" + out, &out_, &err_), 2) << err_;
  EXPECT_EQ(kinema("render --frames 3" + out, &out_, &err_), 2) << err_;
  EXPECT_EQ(kinema("render", &out_, &err_), 2) << err_;  // --out is required
  EXPECT_EQ(kinema("render --size 0x10" + out, &out_, &err_), 1) << err_;
  EXPECT_EQ(kinema("render --camera nan,0" + out, &out_, &err_), 1) << err_;
  EXPECT_EQ(kinema("render --camera 0,0,-1" + out, &out_, &err_), 1) << err_;
  EXPECT_EQ(kinema("render --frames 5:1 --out " + dir_ + "/f_%04d.png", &out_, &err_), 1) << err_;
  EXPECT_EQ(kinema("render --frames 0:1" + out, &out_, &err_), 1) << err_;  // no frame number in the name
  EXPECT_NE(err_.find("%04d"), std::string::npos) << err_;
  EXPECT_EQ(kinema("render --select Nobody" + out, &out_, &err_), 1) << err_;
  EXPECT_NE(err_.find("Nobody"), std::string::npos);
  EXPECT_EQ(kinema("render " + dir_ + "/missing.bvh" + out, &out_, &err_), 1) << err_;
  EXPECT_NE(err_.find("missing.bvh"), std::string::npos);
  EXPECT_EQ(std::count(err_.begin(), err_.end(), '\n'), 1) << err_;
  struct stat st {};
  EXPECT_NE(::stat((dir_ + "/x.png").c_str(), &st), 0) << "no image after a failure";
}

TEST_F(RenderCli, EditorWindowOpensRendersAndExitsUnderXvfb) {
  if (runCommand("command -v xvfb-run") != 0) GTEST_SKIP() << "xvfb-run is not installed";
  KINEMA_REQUIRE_SHARED_DATA();
  const std::string shot = dir_ + "/editor.png";
  // Its own config and state folders: nothing remembered from the user's sessions.
  ASSERT_EQ(runCommand("sh '" KINEMA_SOURCE_DIR "/tests/tools/xvfb_run.sh' 1280x800x24 env XDG_CONFIG_HOME='" + dir_ + "' XDG_STATE_HOME='" +
                           dir_ + "' " + kSoftware + KINEMA_BINARY + " edit '" +
                           sharedDataDir() + "/bvh/cmu_01_01_first720.bvh' --frame-count 5 --screenshot " + shot,
                       &out_, &err_),
            0)
      << err_;
  const Image image = loadImageOrFail(shot);
  // No size remembered and no --size: nine tenths of the 1280x800 screen, centred.
  EXPECT_EQ(image.width, 1280 * 9 / 10);
  EXPECT_EQ(image.height, 800 * 9 / 10);
  EXPECT_GT(distinctColors(image), 50);
  EXPECT_GT(brightBox(image).height(), 150);
  // Without a display, `edit` fails with one line and exit 1, never a crash.
  EXPECT_EQ(runCommand("env -u DISPLAY -u WAYLAND_DISPLAY XDG_CONFIG_HOME='" + dir_ + "' XDG_STATE_HOME='" + dir_ + "' " +
                           std::string(KINEMA_BINARY) + " edit",
                       &out_, &err_),
            1);
  EXPECT_NE(err_.find("display"), std::string::npos) << err_;
}

}  // namespace
}  // namespace kinema::test
