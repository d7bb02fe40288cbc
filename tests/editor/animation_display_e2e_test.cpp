// Onion skin, motion path and motion control driven end to end: `kinema edit` under xvfb-run
// on a small BVH written here, whose motion is known in closed form (so the expected ghost
// and path positions come from that formula, not from the editor).
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>

#include "anim/sampling.h"
#include "core/forward_kinematics.h"
#include "editor/e2e_harness.h"
#include "editor/model/document_files.h"
#include "io/image.h"
#include "io/kinema_file.h"
#include "io/scene_files.h"

namespace kinema::test {
namespace KINEMA_UNITY_ID {

using e2e::DumpCamera;
using e2e::json;
using e2e::runEditor;
using e2e::Script;

constexpr int kFrames = 21;         // frames 0..20, 0.1 s apart
constexpr double kFrameTime = 0.1;
// Hips moves along X with constant acceleration: x(f) = 0.015 f^2 (0 .. 6 m); Chest is 1 m
// above it and Head 1 m above Chest (End Site); no rotation.
double hipsX(double frame) { return 0.015 * frame * frame; }
glm::dvec3 chestAt(double frame) { return {hipsX(frame), 1.0, 0.0}; }

std::string bvhText() {
  std::string s =
      "HIERARCHY\nROOT Hips\n{\n  OFFSET 0 0 0\n  CHANNELS 6 Xposition Yposition Zposition Zrotation Xrotation Yrotation\n"
      "  JOINT Chest\n  {\n    OFFSET 0 1 0\n    CHANNELS 3 Zrotation Xrotation Yrotation\n"
      "    End Site\n    {\n      OFFSET 0 1 0\n    }\n  }\n}\nMOTION\nFrames: " +
      std::to_string(kFrames) + "\nFrame Time: 0.1\n";
  for (int f = 0; f < kFrames; ++f) s += std::to_string(hipsX(f)) + " 0 0 0 0 0 0 0 0\n";
  return s;
}

glm::ivec3 pixelAt(const Image& img, glm::dvec2 p) {
  const int x = int(std::lround(p.x)), y = int(std::lround(p.y));
  if (x < 0 || y < 0 || x >= img.width || y >= img.height) return glm::ivec3(-1);
  const std::uint8_t* c = img.pixel(x, y);
  return {c[0], c[1], c[2]};
}
// Any pixel within `r` of p whose colour passes `test`.
template <class F>
bool anyNear(const Image& img, glm::dvec2 p, int r, F test) {
  for (int dy = -r; dy <= r; ++dy)
    for (int dx = -r; dx <= r; ++dx) {
      const glm::ivec3 c = pixelAt(img, p + glm::dvec2(dx, dy));
      if (c.r >= 0 && test(c)) return true;
    }
  return false;
}
// The ghost tints (OnionSkinSettings' defaults): green before, blue after, blended over grey.
bool greenTint(glm::ivec3 c) { return c.g > c.r + 12 && c.g > c.b + 12; }
bool blueTint(glm::ivec3 c) { return c.b > c.r + 12 && c.b > c.g + 12; }
// The motion path's yellow (MotionPathSettings' default colour).
bool yellow(glm::ivec3 c) { return c.r > 150 && c.g > 120 && c.b < 110; }

class AnimationDisplayE2e : public ::testing::Test {
 protected:
  void SetUp() override {
    if (runCommand("command -v xvfb-run") != 0) GTEST_SKIP() << "SKIPPED: xvfb-run is not installed";
    dir_ = makeTempDir();
    bvh_ = dir_ + "/accelerating.bvh";
    std::ofstream(bvh_) << bvhText();
  }
  void TearDown() override {
    if (!dir_.empty()) runCommand("rm -rf '" + dir_ + "'");
  }
  static std::string shotDir() {
    const std::string dir = std::string(KINEMA_BUILD_DIR) + "/animation_display_e2e";
    runCommand("mkdir -p '" + dir + "'");
    return dir;
  }
  json run(const Script& s, const std::string& name) { return runEditor(dir_, shotDir(), s, name, bvh_); }
  static Image shot(const std::string& name) {
    auto png = loadPng(shotDir() + "/" + name + ".png");
    EXPECT_TRUE(png.ok()) << name;
    return png.ok() ? png.value() : Image();
  }
  // Plays ~1 s (60 replay frames of 1/60 s), pauses, frames the pose (Home) and zooms out
  // so the ghosts up to 1 s away on either side (x 0 .. 6 m) are in the view.
  static Script playToAboutFrame10() {
    Script s;
    s.key("SPACE").wait(59).key("SPACE").wait(2).key("HOME").wait(2).scroll(-3).wait(2).scroll(-3).wait(2).scroll(-3).wait(2);
    return s;
  }
  std::string dir_, bvh_;
};

// Alt+O: ghosts 2 before in green, 2 after in blue, every `step` frames (the dumped
// default), at the clip's poses of those frames (those inside the clip); Alt+O again: gone.
// The BVH has no mesh: the ghosts are bones.
TEST_F(AnimationDisplayE2e, OnionSkinDrawsOneGhostPerGhostFrameAndGoesAway) {
  Script on = playToAboutFrame10();
  on.keyDown("LEFT_ALT").key("O").keyUp("LEFT_ALT").wait(3);
  const json d = run(on, "onion_on");
  ASSERT_TRUE(d.is_object());
  const long long current = std::llround(double(d["playback"]["time"]) / kFrameTime);
  ASSERT_GE(current, 4);
  ASSERT_LE(current, 16);
  EXPECT_EQ(d["onion_skin"]["enabled"], true);
  EXPECT_EQ(d["onion_skin"]["drawn_as"], "bones");
  const long long step = d["onion_skin"]["step"];
  ASSERT_GE(step, 1);
  std::vector<long long> expected;
  for (long long f : {current - 2 * step, current - step, current + step, current + 2 * step})
    if (f >= 0 && f < kFrames) expected.push_back(f);
  const json& ghosts = d["onion_skin"]["ghosts"];
  ASSERT_EQ(ghosts.size(), expected.size());
  ASSERT_GE(expected.size(), 2u);
  const Image img = shot("onion_on");
  const DumpCamera cam(d);
  for (size_t i = 0; i < expected.size(); ++i) {
    EXPECT_EQ(ghosts[i]["frame"], expected[i]);
    const bool before = expected[i] < current;
    // The ghost's Chest joint and the middle of its Hips -> Chest bone, where the clip puts them.
    const glm::dvec3 chest = chestAt(double(expected[i])), bone = chest - glm::dvec3(0, 0.5, 0);
    for (glm::dvec3 p : {chest, bone}) {
      const glm::dvec2 px = cam.pixel(p);
      ASSERT_TRUE(px.x > cam.x0 && px.x < cam.x0 + cam.w && px.y > cam.y0 && px.y < cam.y0 + cam.h)
          << "ghost " << i << " is outside the view";
      const bool tinted = before ? anyNear(img, px, 2, greenTint) : anyNear(img, px, 2, blueTint);
      EXPECT_TRUE(tinted) << "ghost of frame " << expected[i] << " at pixel (" << px.x << ", " << px.y << "): "
                          << pixelAt(img, px).r << "," << pixelAt(img, px).g << "," << pixelAt(img, px).b;
    }
  }
  Script off = playToAboutFrame10();
  off.keyDown("LEFT_ALT").key("O").keyUp("LEFT_ALT").wait(3).keyDown("LEFT_ALT").key("O").keyUp("LEFT_ALT").wait(3);
  const json d2 = run(off, "onion_off");
  ASSERT_TRUE(d2.is_object());
  EXPECT_EQ(d2["onion_skin"]["enabled"], false);
  EXPECT_TRUE(d2["onion_skin"]["ghosts"].empty());
  const Image img2 = shot("onion_off");
  const DumpCamera cam2(d2);
  for (size_t i = 0; i < expected.size(); ++i) {
    const glm::dvec2 px = cam2.pixel(chestAt(double(expected[i])));
    EXPECT_FALSE(anyNear(img2, px, 3, greenTint) || anyNear(img2, px, 3, blueTint)) << "ghost " << i << " still drawn";
  }
}

// Select Chest, Alt+P: a yellow polyline through Chest's positions at every frame of the clip.
TEST_F(AnimationDisplayE2e, MotionPathFollowsTheActiveJointOverTheClip) {
  // Frame all at frame 0 puts the skeleton at x = 0; zoom out so the whole path (0 .. 6 m) shows.
  Script probe;
  const json d0 = run(probe, "path_probe");
  ASSERT_TRUE(d0.is_object());
  const DumpCamera cam0(d0);
  Script s;
  s.click(cam0.pixel(chestAt(0))).wait(2);
  s.keyDown("LEFT_ALT").key("P").keyUp("LEFT_ALT").wait(2);
  s.move(cam0.pixel(glm::dvec3(3, 1, 0))).scroll(-3).wait(3).scroll(-3).wait(3);
  const json d = run(s, "motion_path");
  ASSERT_TRUE(d.is_object());
  EXPECT_EQ(d["active"], "Chest");
  EXPECT_EQ(d["motion_path"]["enabled"], true);
  const Image img = shot("motion_path");
  const DumpCamera cam(d);
  int inside = 0, found = 0;
  // Between frames (the polyline) and at frames (the dots), away from the skeleton at x = 0.
  for (double f = 6.5; f <= 20.0; f += 1.0) {
    const glm::dvec2 px = cam.pixel(chestAt(f));
    if (!(px.x > cam.x0 + 5 && px.x < cam.x0 + cam.w - 5)) continue;
    ++inside;
    if (anyNear(img, px, 2, yellow)) ++found;
    else ADD_FAILURE() << "no path at frame " << f << " pixel (" << px.x << ", " << px.y << ")";
  }
  EXPECT_GE(inside, 8) << "zoomed out too little: most of the path is outside the view";
  EXPECT_EQ(found, inside);
  // Nothing yellow 0.4 m above the path (it is a line, not a band).
  const glm::dvec2 above = cam.pixel(chestAt(14) + glm::dvec3(0, 0.4, 0));
  EXPECT_FALSE(anyNear(img, above, 2, yellow));
}

// Select Hips, Alt+M opens Motion Control; choose a profile, Apply, save: the saved Hips
// translation has a key per frame spaced by the profile's distance-time curve.
TEST_F(AnimationDisplayE2e, MotionControlRetimesTheRootsTranslation) {
  Script probe;
  const json d0 = run(probe, "mc_probe");
  ASSERT_TRUE(d0.is_object());
  const DumpCamera cam0(d0);
  const glm::dvec2 hips = cam0.pixel(glm::dvec3(0, 0, 0));
  Script open;
  open.click(hips).wait(2).keyDown("LEFT_ALT").key("M").keyUp("LEFT_ALT").wait(4);
  const json d1 = run(open, "mc_window");
  ASSERT_TRUE(d1.is_object());
  EXPECT_EQ(d1["active"], "Hips");
  ASSERT_EQ(d1["motion_control"]["window_open"], true);
  auto centre = [](const json& r) { return glm::dvec2(double(r[0]) + 10.0, double(r[1]) + double(r[3]) / 2); };
  const glm::dvec2 apply = centre(d1["motion_control"]["apply_rect"]);
  ASSERT_GT(double(d1["motion_control"]["apply_rect"][2]), 0.0);

  for (int profile = 0; profile < 2; ++profile) {
    const std::string saved = dir_ + (profile == 0 ? "/constant.kinema" : "/sine.kinema");
    Script s = open;
    s.click(centre(d1["motion_control"]["profile_rects"][profile])).wait(2).click(apply).wait(3);
    s.keyDown("LEFT_CONTROL").keyDown("LEFT_SHIFT").key("S").keyUp("LEFT_SHIFT").keyUp("LEFT_CONTROL").wait(2);
    s.type(saved).key("ENTER").wait(3);
    const json d = run(s, profile == 0 ? "mc_constant" : "mc_sine");
    ASSERT_TRUE(d.is_object());
    EXPECT_EQ(d["motion_control"]["profile"], profile == 0 ? "constant-speed" : "sine-ease");
    EXPECT_EQ(d["undo_depth"], 1) << "one undo step";
    auto scene = loadKinemaFile(saved);
    ASSERT_TRUE(scene.ok()) << scene.error();
    const Clip& clip = scene.value().clips.at(0);
    const Channel* hipsT = nullptr;
    for (const Channel& c : clip.channels)
      if (c.joint == 0 && c.target == ChannelTarget::Translation) hipsT = &c;
    ASSERT_NE(hipsT, nullptr);
    ASSERT_EQ(hipsT->keyCount(), kFrames);
    // Distance along the straight path = x; total 6 m over 2 s.
    for (int f = 0; f < kFrames; ++f) {
      const double u = f / 20.0;
      const double x = profile == 0 ? 6.0 * u : 3.0 * (1.0 - std::cos(M_PI * u));
      EXPECT_NEAR(hipsT->times[f], f * kFrameTime, 1e-5);
      EXPECT_NEAR(hipsT->values[f].x, x, 5e-3) << "frame " << f;
      EXPECT_NEAR(hipsT->values[f].y, 0.0, 1e-5);
    }
  }
}

// The default character (a skinned body): UpperArm.L keyed at rest on frame 1 and turned 80
// degrees about Z on frame 20, the playhead on frame 20. With the onion skin on, the body's
// ghosts at frames 10 and 15 (every 5th frame, the default step) show where the arm was: at
// points of those ghost arms away from the current arm, the pixels are tinted green (the
// past's tint), where the same run without the onion skin has no tint. The ghost poses are
// the saved clip sampled here, not the editor's ghosts.
TEST_F(AnimationDisplayE2e, OnionSkinShowsTheBodysGhostsOnTheDefaultCharacter) {
  // Two copies of the character: the run with the onion skin saves its keys into its own.
  Document doc = newDocument();
  const std::string file = dir_ + "/character.kinema", plain = dir_ + "/plain.kinema";
  ASSERT_EQ(saveDocumentAs(doc, file), "");
  ASSERT_EQ(saveDocumentAs(doc, plain), "");
  Script s;
  s.select("UpperArm.L");
  s.key("I");
  for (int i = 0; i < 19; ++i) s.key("RIGHT");
  s.wait(21);
  s.key("R").key("Z").key("8").key("0").key("ENTER").key("I").wait(2);
  Script on = s;
  on.keyDown("LEFT_CONTROL").key("S").keyUp("LEFT_CONTROL").wait(2);
  on.keyDown("LEFT_ALT").key("O").keyUp("LEFT_ALT").wait(3);
  const json off = runEditor(dir_, shotDir(), s, "body_onion_off", plain);
  const json d = runEditor(dir_, shotDir(), on, "body_onion_on", file);
  ASSERT_TRUE(d.is_object() && off.is_object());
  EXPECT_EQ(d["timeline"]["frame"], 20);
  EXPECT_EQ(d["onion_skin"]["enabled"], true);
  EXPECT_EQ(d["onion_skin"]["drawn_as"], "bodies");
  ASSERT_EQ(d["onion_skin"]["ghosts"].size(), 2u) << "frames 10 and 15 (none after the clip's end)";
  EXPECT_EQ(d["onion_skin"]["ghosts"][0]["frame"], 10);
  EXPECT_EQ(d["onion_skin"]["ghosts"][1]["frame"], 15);

  Result<Scene> saved = loadScene(file);
  ASSERT_TRUE(saved.ok()) << saved.error();
  const Scene& sc = saved.value();
  ASSERT_EQ(sc.clips.size(), 1u);
  const Image imgOn = shot("body_onion_on"), imgOff = shot("body_onion_off");
  ASSERT_EQ(imgOn.width, imgOff.width);
  const DumpCamera cam(d);
  const char* arm[3] = {"UpperArm.L", "LowerArm.L", "Hand.L"};
  std::vector<glm::dvec2> current;  // the arm at frame 20, on screen
  for (const char* name : arm) current.push_back(cam.pixel(e2e::jointIn(d, name)));
  auto distanceToCurrentArm = [&](glm::dvec2 p) {
    double best = 1e9;
    for (int k = 0; k + 1 < 3; ++k) {
      const glm::dvec2 a = current[k], b = current[k + 1];
      const double t = std::clamp(glm::dot(p - a, b - a) / std::max(glm::dot(b - a, b - a), 1e-9), 0.0, 1.0);
      best = std::min(best, glm::length(p - (a + t * (b - a))));
    }
    return best;
  };
  int checked = 0;
  for (long long frame : {10LL, 15LL}) {
    Pose pose = Pose::rest(sc.skeleton);
    sampleClip(sc.clips[0], sc.frameGrid(0).frameToTime(frame), pose);
    const std::vector<glm::mat4> world = computeWorld(sc.skeleton, pose);
    // Along the ghost's forearm (lower arm to hand), where the arm's axis is.
    const glm::dvec3 elbow = glm::dvec3(world[sc.skeleton.find("LowerArm.L")][3]);
    const glm::dvec3 hand = glm::dvec3(world[sc.skeleton.find("Hand.L")][3]);
    for (double t : {0.2, 0.3, 0.4, 0.5, 0.6, 0.7, 0.8}) {
      const glm::dvec2 px = cam.pixel(elbow + t * (hand - elbow));
      if (distanceToCurrentArm(px) < 25.0) continue;  // too near the arm as it is now
      ++checked;
      EXPECT_TRUE(anyNear(imgOn, px, 1, greenTint))
          << "frame " << frame << " ghost at (" << px.x << ", " << px.y << "): " << pixelAt(imgOn, px).r << ","
          << pixelAt(imgOn, px).g << "," << pixelAt(imgOn, px).b;
      EXPECT_FALSE(anyNear(imgOff, px, 3, greenTint)) << "frame " << frame << ": tinted without the onion skin";
    }
  }
  EXPECT_GE(checked, 4) << "the ghost arms lie away from the current one";
}

}  // namespace
}  // namespace kinema::test
