// End-to-end tests of the curve editor: the real `kinema edit` under xvfb-run on a small
// keyed file written here, driven by --script (select the joint in the outliner, Shift+F6
// opens the curve editor), checked in --dump-state and in the saved file. Key pixels come
// from the dumped plot rectangle and view (the test's own mapping); widgets are clicked by
// name (e2e_harness.h).
// Expected values are derived by hand in the comments (Kochanek-Bartels with tension 1 has
// zero tangents, so the segment is a cubic Hermite with zero tangents).
#include <cmath>
#include <set>
#include <tuple>

#include "anim/sampling.h"
#include "editor/e2e_harness.h"
#include "io/kinema_file.h"

namespace kinema::test {
namespace KINEMA_UNITY_ID {

using namespace e2e;

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

// The curve editor's toolbar, then the key properties strip (interpolation combo, then the
// TCB sliders or handle types).
const std::string kInterpolationCombo = "Curve Editor/Interpolation";
std::string interpolationItem(const char* name) { return kInterpolationCombo + "/" + name; }
// The T slider's right end: tension 1 (range -1..1; the slider clamps past its last pixel).
const glm::dvec2 kSliderMax{0.99, 0.5};

class CurveEditorE2e : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    if (runCommand("command -v xvfb-run") != 0) return;
    const std::string dir = makeTempDir();
    const std::string file = dir + "/anim.kinema";
    std::ofstream(file) << kFile;
    const json d = runEditor(dir, shotDir(), open(Script()), "curve_open", file);
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
    return s.select("Hips").keyDown("LEFT_SHIFT").key("F6").keyUp("LEFT_SHIFT").wait(3);
  }
  json run(Script& s, const std::string& name) { return runEditor(dir_, shotDir(), s, name, file_); }
  static Script& save(Script& s) { return s.keyDown("LEFT_CONTROL").key("S").keyUp("LEFT_CONTROL").wait(3); }

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

// The Hips translation channel of a saved file.
Channel savedChannel(const std::string& path) {
  const Result<Scene> scene = loadKinemaFile(path);
  EXPECT_TRUE(scene.ok()) << scene.error();
  if (!scene.ok() || scene.value().clips.empty() || scene.value().clips[0].channels.empty()) return Channel();
  return scene.value().clips[0].channels[0];
}

// Keys 1 and 2 of the y curve (frames 10 and 20, values 2 and 4, both interior) set to TCB
// with tension 1 through the panel: both tangents of the segment between them are
// (1 - T)(...) = 0, so it is the Hermite cubic with zero tangents,
//   y(u) = 2 + (4 - 2)(3u^2 - 2u^3),  at u = 1/4 (frame 12.5): 2 + 2 * 5/32 = 2.3125.
TEST_F(CurveEditorE2e, TcbWithTensionOneThroughThePanelGivesTheZeroTangentHermite) {
  Script s;
  open(s).click(yKeyPixel(1)).wait(1).keyDown("LEFT_SHIFT").click(yKeyPixel(2)).keyUp("LEFT_SHIFT").wait(1);
  s.clickItem(kInterpolationCombo).wait(2).clickItem(interpolationItem("TCB")).wait(2);
  s.clickItem("Curve Editor/T", kSliderMax).wait(2);
  save(s);
  const json d = run(s, "curve_tcb");
  ASSERT_TRUE(d.is_object());
  EXPECT_EQ(d["curve_editor"]["selected_keys"].size(), 2u);
  EXPECT_EQ(yKey(d, 1)["interpolation"], "tcb");
  EXPECT_EQ(yKey(d, 2)["interpolation"], "tcb");
  EXPECT_EQ(yKey(d, 0)["interpolation"], "linear");
  EXPECT_EQ(d["undo_depth"], 2);  // the interpolation, then the tension slider
  EXPECT_EQ(d["dirty"], false);  // saved
  const Channel ch = savedChannel(file_);
  ASSERT_EQ(ch.keys.size(), 4u);
  EXPECT_EQ(ch.keys[1].interpolation, Interpolation::TCB);
  EXPECT_EQ(ch.keys[1].tension, 1.0f);
  EXPECT_EQ(ch.keys[2].tension, 1.0f);
  EXPECT_NEAR(sampleChannel(ch, 12.5f / 30.0f).y, 2.3125, 1e-5);
  // The key values are untouched.
  EXPECT_FLOAT_EQ(ch.values[1].y, 2.0f);
  EXPECT_FLOAT_EQ(ch.values[2].y, 4.0f);
}

// Dragging the last y key 2 frames right and 1 unit up: time snapped to frame 32, value
// free (to the pixel); the x and z components of that key move in time only.
TEST_F(CurveEditorE2e, DraggingAKeyMovesItsTimeSnappedAndItsValueFree) {
  const glm::dvec2 sc = scale(opened_), from = yKeyPixel(3);
  const glm::dvec2 to = from + glm::dvec2(2.2 / 30.0 * sc.x, -1.0 * sc.y);
  Script s;
  open(s).move(from).down().path(from, to, 8).up().wait(2);
  const json d = run(s, "curve_drag_key");
  ASSERT_TRUE(d.is_object());
  EXPECT_NEAR(double(yKey(d, 3)["time"]), 32.0 / 30.0, 1e-5);
  EXPECT_NEAR(double(yKey(d, 3)["value"]), 4.0, 1.0 / sc.y);
  EXPECT_NEAR(double(d["curve_editor"]["curves"][0]["keys"][3]["time"]), 32.0 / 30.0, 1e-5);
  EXPECT_NEAR(double(d["curve_editor"]["curves"][0]["keys"][3]["value"]), 0.0, 1e-6);
  EXPECT_EQ(d["undo_depth"], 1);  // the whole drag is one step
}

// Key 1 set to Bezier shows its right handle where the auto-clamped rule puts it: a third of
// the interval (1/9 s) along the neighbours' chord, slope (4 - 1) / (2/3 s) = 4.5 per second,
// so at (+1/9 s, +0.5). Dragging it by (dx, dy) pixels makes both handles aligned: the right
// one at (1/9 + dx/sx, 0.5 + dy/sy), the left one turned to stay collinear with its length
// (in frames x value) kept: |(-10/3 frames, -0.5)|.
TEST_F(CurveEditorE2e, DraggingABezierHandleAlignsTheOtherOne) {
  const glm::dvec2 sc = scale(opened_);
  const double t1 = 1.0 / 3, handleT = 1.0 / 9, handleV = 0.5;
  const glm::dvec2 handle = pixel(opened_, t1 + handleT, 2.0 + handleV);
  const glm::dvec2 delta{30, -24};
  Script s;
  open(s).click(yKeyPixel(1)).wait(1).clickItem(kInterpolationCombo).wait(2).clickItem(interpolationItem("Bezier")).wait(2);
  s.move(handle).down().path(handle, handle + delta, 6).up().wait(2);
  save(s);
  const json d = run(s, "curve_drag_handle");
  ASSERT_TRUE(d.is_object());
  EXPECT_EQ(d["undo_depth"], 2);
  const Channel ch = savedChannel(file_);
  ASSERT_EQ(ch.keys.size(), 4u);
  const KeySettings& k = ch.keys[1];
  EXPECT_EQ(k.interpolation, Interpolation::Bezier);
  EXPECT_EQ(k.leftHandleType, HandleType::Aligned);
  EXPECT_EQ(k.rightHandleType, HandleType::Aligned);
  EXPECT_NEAR(k.rightHandleTime, handleT + delta.x / sc.x, 1e-4);
  EXPECT_NEAR(k.rightHandleValue.y, handleV - delta.y / sc.y, 1e-3);
  const double fps = 30, lt = k.leftHandleTime * fps, lv = k.leftHandleValue.y;
  const double rt = k.rightHandleTime * fps, rv = k.rightHandleValue.y;
  EXPECT_NEAR(lt * rv - lv * rt, 0.0, 1e-4);  // collinear
  EXPECT_LT(lt, 0.0);
  EXPECT_NEAR(std::hypot(lt, lv), std::hypot(10.0 / 3, 0.5), 1e-4);
  EXPECT_FLOAT_EQ(ch.values[1].y, 2.0f);  // the key stays
}

// Wheel zooms both axes about the mouse (1.15 per notch), Ctrl+wheel the time axis only,
// a middle drag pans, and Home over the plot fits all curves again.
TEST_F(CurveEditorE2e, WheelZoomsCtrlWheelZoomsTimeAndHomeFits) {
  const json& v0 = opened_["curve_editor"]["view"];
  const double fitT = double(v0["t1"]) - double(v0["t0"]), fitV = double(v0["v1"]) - double(v0["v0"]);
  const glm::dvec2 centre = pixel(opened_, 0.5, 2.0);
  Script zoom;
  open(zoom).move(centre).scroll(2).wait(1).keyDown("LEFT_CONTROL").scroll(1).keyUp("LEFT_CONTROL").wait(2);
  const json z = run(zoom, "curve_zoom");
  ASSERT_TRUE(z.is_object());
  const json& v = z["curve_editor"]["view"];
  EXPECT_NEAR(double(v["t1"]) - double(v["t0"]), fitT / std::pow(1.15, 3), 1e-4);
  EXPECT_NEAR(double(v["v1"]) - double(v["v0"]), fitV / std::pow(1.15, 2), 1e-4);
  Script home;
  open(home).move(centre).scroll(3).wait(1).down("middle").path(centre, centre + glm::dvec2(40, 10), 4).up("middle");
  home.wait(1).key("HOME").wait(2);
  const json h = run(home, "curve_home");
  ASSERT_TRUE(h.is_object());
  for (const char* k : {"t0", "t1", "v0", "v1"})
    EXPECT_NEAR(double(h["curve_editor"]["view"][k]), double(v0[k]), 1e-5) << k;
}

// Normalize maps each curve onto [-1, 1]: the y keys 1, 2, 4, 3 show as -1, -1/3, 1, 1/3,
// the flat x and z curves at 0; the fit then spans -1.2 .. 1.2.
TEST_F(CurveEditorE2e, NormalizeTogglesTheNormalizedView) {
  Script s;
  open(s).clickItem("Curve Editor/Normalize").wait(2);
  const json d = run(s, "curve_normalized");
  ASSERT_TRUE(d.is_object());
  const json& ce = d["curve_editor"];
  EXPECT_EQ(ce["normalized"], true);
  const double expected[4] = {-1.0, -1.0 / 3, 1.0, 1.0 / 3};
  for (int k = 0; k < 4; ++k) EXPECT_NEAR(double(yKey(d, k)["display"]), expected[k], 1e-5) << k;
  EXPECT_NEAR(double(ce["curves"][0]["keys"][2]["display"]), 0.0, 1e-6);
  EXPECT_NEAR(double(ce["view"]["v0"]), -1.2, 1e-5);
  EXPECT_NEAR(double(ce["view"]["v1"]), 1.2, 1e-5);
}

// Step then Linear on key 1 through the combo: the file saved in between holds Step (the
// value holds at 2 until frame 20), the final state Linear; two undo steps.
TEST_F(CurveEditorE2e, InterpolationChangesToStepAndLinear) {
  Script s;
  open(s).click(yKeyPixel(1)).wait(1).clickItem(kInterpolationCombo).wait(2).clickItem(interpolationItem("Step")).wait(2);
  save(s);
  s.clickItem(kInterpolationCombo).wait(2).clickItem(interpolationItem("Linear")).wait(2);
  const json d = run(s, "curve_step_linear");
  ASSERT_TRUE(d.is_object());
  EXPECT_EQ(yKey(d, 1)["interpolation"], "linear");
  EXPECT_EQ(d["undo_depth"], 2);
  const Channel ch = savedChannel(file_);
  ASSERT_EQ(ch.keys.size(), 4u);
  EXPECT_EQ(ch.keys[1].interpolation, Interpolation::Step);
  EXPECT_FLOAT_EQ(sampleChannel(ch, 19.0f / 30.0f).y, 2.0f);
}

// The View menu's item opens it too; with Hips and Spine selected, the quaternion view shows
// Spine's rotation as x, y, z, w (3 + 4 curves), the Euler view as three angles (3 + 3).
// The last frame is the README's screenshot (docs/images/curve_editor.png).
TEST_F(CurveEditorE2e, ViewMenuOpensItAndTheRotationViewSwitches) {
  Script s;
  s.select("Hips").keyDown("LEFT_SHIFT").clickItem("Outliner/Spine").keyUp("LEFT_SHIFT").wait(1);
  s.menu("View", "Curve Editor").wait(2);
  const json euler = run(s, "curve_euler_view");
  ASSERT_TRUE(euler.is_object());
  ASSERT_EQ(euler["curve_editor"]["open"], true);
  ASSERT_EQ(euler["curve_editor"]["curves"].size(), 6u);
  EXPECT_EQ(euler["curve_editor"]["curves"][5]["label"], "Spine Rotation Z (XYZ)");
  // Spine turns 60 degrees about Z: its Euler Z key goes 0 -> 60 (degrees, as the properties panel shows).
  EXPECT_EQ(euler["curve_editor"]["curves"][5]["unit"], "deg");
  EXPECT_NEAR(double(euler["curve_editor"]["curves"][5]["keys"][1]["value"]), 60.0, 1e-3);
  s.clickItem("Curve Editor/Rotation view").wait(2);
  // A key of the y curve selected, Bezier, so that the screenshot shows handles.
  const json q = run(s, "curve_quaternion_view");
  ASSERT_TRUE(q.is_object());
  EXPECT_EQ(q["curve_editor"]["rotation_view"], "quaternion");
  ASSERT_EQ(q["curve_editor"]["curves"].size(), 7u);
  EXPECT_NEAR(double(q["curve_editor"]["curves"][6]["keys"][1]["value"]), std::cos(M_PI / 6), 1e-5);  // w
  EXPECT_EQ(q["curve_editor"]["curves"][6]["unit"], "");  // quaternion components: unitless
}

// The README's picture (docs/images/curve_editor.png): Hips and Spine in the normalized
// Euler view (fit: -1.2 .. 1.2), the y curve's key 1 (normalized -1/3) set to Bezier with
// its handle showing.
TEST_F(CurveEditorE2e, ReadmeScreenshotNormalizedWithABezierKey) {
  json normalizedView = opened_;
  normalizedView["curve_editor"]["view"] = {{"t0", -0.1}, {"t1", 1.1}, {"v0", -1.2}, {"v1", 1.2}};
  Script s;
  s.select("Hips").keyDown("LEFT_SHIFT").clickItem("Outliner/Spine").keyUp("LEFT_SHIFT").wait(1);
  s.keyDown("LEFT_SHIFT").key("F6").keyUp("LEFT_SHIFT").wait(2).clickItem("Curve Editor/Normalize").wait(2);
  s.click(pixel(normalizedView, 1.0 / 3, -1.0 / 3)).wait(1).clickItem(kInterpolationCombo).wait(2);
  // The mouse then rests in the 3D view, off the plot.
  s.clickItem(interpolationItem("Bezier")).wait(2).move(viewportRect(opened_).at(0.6, 0.6)).wait(2);
  const json d = run(s, "curve_editor_readme");
  ASSERT_TRUE(d.is_object());
  EXPECT_EQ(d["curve_editor"]["normalized"], true);
  EXPECT_EQ(d["curve_editor"]["curves"].size(), 6u);
  EXPECT_EQ(yKey(d, 1)["interpolation"], "bezier");
}

// Head (no channels in the file) keyed with I at frame 0 (its rest, 0 degrees about Z) and
// at frame 10 at 90 degrees (typed into the properties panel), then the playhead back at
// frame 2 (u = 0.2). The new keys ease: Bezier with auto-clamped handles, flat at both end
// keys and a third of the interval long, so the quaternion moves by s = 3u^2 - 2u^3 and
// is normalised: the angle is 2 atan2(s sin 45, (1 - s) + s cos 45) = 8.68 degrees, not
// the 18 of a straight line. The curve editor shows it in degrees.
Script& keyHeadTwice(Script& s) {
  s.select("Head").key("I").wait(2);
  for (int i = 0; i < 10; ++i) s.key("RIGHT").wait(1);
  s.euler(2, 90.0).select("Head").key("I").wait(2);
  s.keyDown("LEFT_SHIFT").key("F6").keyUp("LEFT_SHIFT").wait(2);
  for (int i = 0; i < 8; ++i) s.key("LEFT").wait(1);
  return s.wait(2);
}
double easedDegrees(double u) {
  const double sm = 3 * u * u - 2 * u * u * u, h = M_PI / 4;
  return 2 * std::atan2(sm * std::sin(h), (1 - sm) + sm * std::cos(h)) * 180 / M_PI;
}
const json* curveLabelled(const json& d, const std::string& label) {
  for (const json& c : d["curve_editor"]["curves"])
    if (c["label"] == label) return &c;
  ADD_FAILURE() << "no curve " << label;
  return nullptr;
}

// One run keys and dumps (degrees, the eased default, playback); a second replays that and
// then selects: A (all 12 keys of Head's 6 curves) and Linear from the interpolation combo
// for all of them; the combo opened again and closed with Esc, so a click where its Step
// entry was picks nothing; A then Alt+A (none); a Shift+drag from empty plot space boxes the
// 90-degree key (added to the empty selection); B then a Shift+drag starting on the
// frame-0 keys boxes them without moving them. The boxed keys are computed here from the
// first run's plot, view and key values.
TEST_F(CurveEditorE2e, NewRotationKeysEaseInDegreesAndKeysSelectWithABoxAndEsc) {
  Script first;
  keyHeadTwice(first);
  const json d = run(first, "curve_degrees_ease");
  ASSERT_TRUE(d.is_object());
  ASSERT_EQ(d["curve_editor"]["curves"].size(), 6u);  // Head location x y z, rotation X Y Z
  const json* z = curveLabelled(d, "Head Rotation Z (XYZ)");
  ASSERT_NE(z, nullptr);
  EXPECT_EQ((*z)["unit"], "deg");
  ASSERT_EQ((*z)["keys"].size(), 2u);
  EXPECT_NEAR(double((*z)["keys"][0]["value"]), 0.0, 1e-3);
  EXPECT_NEAR(double((*z)["keys"][1]["value"]), 90.0, 1e-3);
  EXPECT_EQ((*z)["keys"][0]["interpolation"], "bezier");
  // The playhead's place between the keys (frame 2 of 0..10).
  const double k0 = (*z)["keys"][0]["time"], k1 = (*z)["keys"][1]["time"];
  const double u = (double(d["playback"]["time"]) - k0) / (k1 - k0);
  EXPECT_NEAR(u, 0.2, 1e-4);
  const double eased = easedDegrees(u);
  EXPECT_NEAR(double((*z)["value_now"]), eased, 1e-2);
  EXPECT_LT(double((*z)["value_now"]), u * 90 - 5) << "an ease lags the straight line here";
  // Playback follows the curve: Head's pose at frame 2 is that rotation about Z.
  expectRotation(rotationIn(d, "Head"), glm::angleAxis(glm::radians(eased), glm::dvec3(0, 0, 1)), 1e-4, "frame 2");

  const glm::dvec2 z1 = pixel(d, (*z)["keys"][1]["time"], (*z)["keys"][1]["display"]);
  const glm::dvec2 z0 = pixel(d, (*z)["keys"][0]["time"], (*z)["keys"][0]["display"]);
  const glm::dvec2 centre = pixel(d, 5.0 / 30, 45.0 + 20.0);  // empty plot space above the curves
  const glm::dvec2 box{14, 14};
  Script s;
  keyHeadTwice(s);
  s.move(centre).wait(1).key("A").wait(2);
  s.clickItem(kInterpolationCombo).wait(2).clickItem(interpolationItem("Linear")).wait(2);
  s.clickItem(kInterpolationCombo).wait(2).key("ESCAPE").wait(2).clickItem(interpolationItem("Step")).wait(2);
  s.move(centre).wait(1).key("A").wait(1).keyDown("LEFT_ALT").key("A").keyUp("LEFT_ALT").wait(2);
  s.keyDown("LEFT_SHIFT").move(z1 - box).down().path(z1 - box, z1 + box, 6).up().keyUp("LEFT_SHIFT").wait(2);
  s.move(centre).wait(1).key("B").wait(1);
  const glm::dvec2 b0 = z0 - glm::dvec2(4, 4), b1 = z0 + box;  // pressed on the keys (within their pick radius)
  s.keyDown("LEFT_SHIFT").move(b0).down().path(b0, b1, 4).up().keyUp("LEFT_SHIFT").wait(2);
  const json e = run(s, "curve_select_box_esc");
  ASSERT_TRUE(e.is_object());
  EXPECT_EQ(e["popup_open"], false);
  EXPECT_EQ(e["curve_editor"]["box_armed"], false);
  // A then Linear: every key of the six curves is linear; the click after Esc picked no Step.
  for (const json& c : e["curve_editor"]["curves"])
    for (const json& k : c["keys"]) EXPECT_EQ(k["interpolation"], "linear") << c["label"];
  // The selection: the 90-degree key, then the keys inside the B box (corners b0, b1), none
  // of them moved.
  std::set<std::tuple<int, int, int>> expected{{int((*z)["channel"]), int((*z)["component"]), 1}};
  for (const json& c : d["curve_editor"]["curves"])
    for (size_t k = 0; k < c["keys"].size(); ++k) {
      const glm::dvec2 p = pixel(d, c["keys"][k]["time"], c["keys"][k]["display"]);
      if (p.x >= b0.x && p.x <= b1.x && p.y >= b0.y && p.y <= b1.y)
        expected.insert({int(c["channel"]), int(c["component"]), int(k)});
    }
  EXPECT_GE(expected.size(), 3u) << "the Z key at frame 0 and others at 0 degrees";
  std::set<std::tuple<int, int, int>> got;
  for (const json& k : e["curve_editor"]["selected_keys"]) got.insert({int(k["channel"]), int(k["component"]), int(k["key"])});
  EXPECT_EQ(got, expected);
  const json* ez = curveLabelled(e, "Head Rotation Z (XYZ)");
  ASSERT_NE(ez, nullptr);
  EXPECT_NEAR(double((*ez)["keys"][0]["value"]), 0.0, 1e-3);
  EXPECT_EQ(double((*ez)["keys"][0]["time"]), double((*z)["keys"][0]["time"]));
}

}  // namespace
}  // namespace kinema::test
