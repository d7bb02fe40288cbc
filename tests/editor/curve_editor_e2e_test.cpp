// End-to-end tests of the curve editor: the real `kinema edit` under xvfb-run on a small
// keyed file written here, driven by --script (select the joint in the outliner, Shift+F6
// opens the curve editor), checked in --dump-state and in the saved file. Key pixels come
// from the dumped plot rectangle and view (the test's own mapping); widget pixels from the
// fixed layout at 1280x800 with ImGui 1.86's default font, read off a screenshot once.
// Expected values are derived by hand in the comments (Kochanek-Bartels with tension 1 has
// zero tangents, so the segment is a cubic Hermite with zero tangents).
#include <cmath>

#include "anim/sampling.h"
#include "editor/e2e_harness.h"
#include "io/kinema_file.h"

namespace kinema::test {
namespace {

using namespace e2e;

const std::string kSize = "1280x800";
// Hips's translation y: 1, 2, 4, 3 at frames 0, 10, 20, 30 (30 fps); x = z = 0.
const char* kFile = R"({"format": "kinema", "version": 1,
 "skeleton": {"joints": [
   {"name": "Hips", "parent": -1, "translation": [0, 1, 0]},
   {"name": "Spine", "parent": 0, "translation": [0, 0.3, 0]},
   {"name": "Head", "parent": 1, "translation": [0, 0.3, 0]}]},
 "clips": [{"name": "bounce", "frame_time": 0.0333333333333,
   "channels": [
     {"joint": "Hips", "target": "translation", "interpolation": "linear",
      "times": [0, 0.333333333333, 0.666666666667, 1.0],
      "values": [[0, 1, 0], [0, 2, 0], [0, 4, 0], [0, 3, 0]]},
     {"joint": "Spine", "target": "rotation", "interpolation": "linear",
      "times": [0, 1.0], "values": [[0, 0, 0, 1], [0, 0, 0.5, 0.8660254]]}]}]})";

const glm::dvec2 kHipsRow{150, 76};  // the outliner's first row
// The curve editor at 1280x800 (animation editor area from y = 476): toolbar, key strip.
const glm::dvec2 kFit{490, 493}, kNormalize{580, 493}, kRotationView{700, 493};
const glm::dvec2 kInterpolationCombo{500, 517};
// The combo's list opens below it, one item per 17 px: Step, Linear, Hermite, Catmull-Rom, TCB, Bezier ...
glm::dvec2 interpolationItem(int i) { return {500, 540 + 17.0 * i}; }
const glm::dvec2 kTensionMax{630, 517};  // the T slider's right end: tension 1

class CurveEditorE2e : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    if (runCommand("command -v xvfb-run") != 0) return;
    const std::string dir = makeTempDir();
    const std::string file = dir + "/anim.kinema";
    std::ofstream(file) << kFile;
    const json d = runEditor(dir, shotDir(), open(Script()), "curve_open", kSize, file);
    if (d.is_object()) opened_ = d;
    runCommand("rm -rf '" + dir + "'");
  }
  void SetUp() override {
    if (runCommand("command -v xvfb-run") != 0) GTEST_SKIP() << "SKIPPED: xvfb-run is not installed";
    ASSERT_TRUE(opened_.is_object()) << "the opening run failed";
    dir_ = makeTempDir();
    file_ = dir_ + "/anim.kinema";
    std::ofstream(file_) << kFile;
  }
  void TearDown() override {
    if (!dir_.empty()) runCommand("rm -rf '" + dir_ + "'");
  }
  static std::string shotDir() {
    const std::string dir = std::string(KINEMA_BUILD_DIR) + "/curve_editor_e2e";
    runCommand("mkdir -p '" + dir + "'");
    return dir;
  }
  // Selects Hips in the outliner and opens the curve editor with Shift+F6.
  static Script& open(Script&& s) { return open(s); }
  static Script& open(Script& s) {
    return s.click(kHipsRow).wait(1).keyDown("LEFT_SHIFT").key("F6").keyUp("LEFT_SHIFT").wait(3);
  }
  json run(Script& s, const std::string& name) { return runEditor(dir_, shotDir(), s, name, kSize, file_); }
  static Script save(Script& s) { return s.keyDown("LEFT_CONTROL").key("S").keyUp("LEFT_CONTROL").wait(3); }

  // The pixel of a (time, display value) point in a dump's curve editor plot.
  static glm::dvec2 pixel(const json& d, double t, double v) {
    const json& ce = d["curve_editor"];
    const json &p = ce["plot"], &w = ce["view"];
    const double x0 = p["x"], y0 = p["y"], pw = p["width"], ph = p["height"];
    const double t0 = w["t0"], t1 = w["t1"], v0 = w["v0"], v1 = w["v1"];
    return {x0 + (t - t0) / (t1 - t0) * pw, y0 + ph - (v - v0) / (v1 - v0) * ph};
  }
  // Pixels per second and per display unit in a dump's plot.
  static glm::dvec2 scale(const json& d) {
    const json& ce = d["curve_editor"];
    return {double(ce["plot"]["width"]) / (double(ce["view"]["t1"]) - double(ce["view"]["t0"])),
            double(ce["plot"]["height"]) / (double(ce["view"]["v1"]) - double(ce["view"]["v0"]))};
  }
  // The y curve's key k (Hips location Y: curve 1).
  static const json& yKey(const json& d, int k) { return d["curve_editor"]["curves"][1]["keys"][k]; }
  glm::dvec2 yKeyPixel(int k) const { return pixel(opened_, yKey(opened_, k)["time"], yKey(opened_, k)["display"]); }

  static inline json opened_;
  std::string dir_, file_;
};

TEST_F(CurveEditorE2e, OpensOnTheSelectedJointsChannelsFittedToTheirKeys) {
  const json& ce = opened_["curve_editor"];
  ASSERT_EQ(ce["open"], true);
  ASSERT_EQ(ce["curves"].size(), 3u);  // Hips location x, y, z
  EXPECT_EQ(ce["curves"][1]["label"], "Hips Location Y");
  // Fit: times 0..1 s and values 0..4 (x = z = 0, y 1..4) with 10 % margins.
  EXPECT_NEAR(double(ce["view"]["t0"]), -0.1, 1e-5);
  EXPECT_NEAR(double(ce["view"]["t1"]), 1.1, 1e-5);
  EXPECT_NEAR(double(ce["view"]["v0"]), -0.4, 1e-5);
  EXPECT_NEAR(double(ce["view"]["v1"]), 4.4, 1e-5);
}

}  // namespace
}  // namespace kinema::test
