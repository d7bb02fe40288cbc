// End-to-end tests of the timeline, keying and auto-key (issue 9): the real `kinema edit`
// runs under xvfb-run (e2e_harness.h) on --script replay, panel widgets clicked by name. Checked in --dump-state, in the saved
// .kinema file (read back with our reader and sampled here with glm::slerp, independently
// of the editor's sampling), in files exported from the saved document, and in the pixels
// of the keyframe diamonds (their place computed from the dumped ruler, timeline.h).
#include <cmath>
#include <set>

#include "anim/clip.h"
#include "core/forward_kinematics.h"
#include "editor/model/document_files.h"
#include "editor/e2e_harness.h"
#include "io/image.h"
#include "io/scene_files.h"

namespace kinema::test {
namespace KINEMA_UNITY_ID {

using namespace e2e;

const json* channelIn(const json& d, const std::string& joint, const std::string& target) {
  for (const json& c : d["timeline"]["channels"])
    if (c["joint"] == joint && c["target"] == target) return &c;
  return nullptr;
}

const Channel* channelOf(const Scene& s, int joint, ChannelTarget target) {
  if (s.clips.empty()) return nullptr;
  for (const Channel& c : s.clips[0].channels)
    if (c.joint == joint && c.target == target) return &c;
  return nullptr;
}

glm::quat quatOf(const glm::vec4& v) { return glm::quat(v.w, v.x, v.y, v.z); }

class KeyingE2e : public FrontViewSuite<KeyingE2e> {
 public:
  static constexpr const char* kShotFolder = "keying_e2e";

 protected:
  // The default character saved as .kinema, so that Ctrl+S saves in place.
  std::string characterFile() {
    Document doc = newDocument();
    const std::string path = dir_ + "/character.kinema";
    EXPECT_EQ(saveDocumentAs(doc, path), "");
    return path;
  }
  glm::dvec2 pixelOf(const std::string& name) const { return DumpCamera(front_).pixel(jointIn(front_, name)); }
  // The ruler's x of a frame and its middle row, from a dump (timeline.h TimelineRuler).
  static double rulerX(const json& d, long long frame) {
    const json& r = d["timeline"]["ruler"];
    const double x = r["x"], w = r["width"], m = r["margin"];
    const double first = r["first"], last = r["last"];
    return x + m + (frame - first) / (last - first) * (w - 2 * m);
  }
  static double rulerMiddle(const json& d) {
    const json& r = d["timeline"]["ruler"];
    return double(r["y"]) + double(r["height"]) / 2;
  }
  // n presses of a key, one a frame. The editor handles a key's release a frame after its
  // press, so n presses take 2n frames: wait for them before clicking (else a click lands
  // in the same frame as its mouse move, judged by the previous frame's ImGui hover).
  static Script steps(Script s, const char* key, int n) {
    for (int i = 0; i < n; ++i) s.key(key);
    return s.wait(n + 2);
  }

};

TEST_F(KeyingE2e, TheTimelineIsThereWithoutMotionAtFrameOne) {
  const json& t = front_["timeline"];
  EXPECT_TRUE(bool(t["shown"]));
  EXPECT_EQ(t["frame"], 1);
  EXPECT_EQ(t["start"], 1);
  EXPECT_EQ(t["end"], 250);
  EXPECT_EQ(t["fps"], 24.0);
  EXPECT_FALSE(bool(t["auto_key"]));
  EXPECT_TRUE(t["channels"].empty());
  // The 3D view ends where the timeline begins (the timeline's window, above the status bar).
  EXPECT_EQ(viewportRect(front_).bottom(), itemRect(front_, "Timeline").y);
  EXPECT_LT(itemRect(front_, "Timeline").bottom(), double(front_["window"]["height"]));
}

// Pose -> I at frame 1 -> pose -> I at frame 24 -> Ctrl+S: the file has both keys; frame 12
// (stepped back to with Left) is the eased blend of the two saved keys: the default keys are
// Bezier with auto-clamped handles, which on two end keys are flat and a third of the
// interval long, so each quaternion component moves by the smoothstep s = 3u^2 - 2u^3 of
// u = 11/23, then the blend is normalised (computed here with glm).
TEST_F(KeyingE2e, KeyTwoPosesSaveAndFrameTwelveIsBetween) {
  const std::string file = characterFile();
  Script s;
  s.select("UpperArm.L");
  s.key("R").key("Z").key("3").key("0").key("ENTER").key("I");
  s = steps(s, "RIGHT", 23);
  s.key("R").key("X").key("5").key("0").key("ENTER").key("I");
  s.keyDown("LEFT_CONTROL").key("S").keyUp("LEFT_CONTROL").wait(2);
  s = steps(s, "LEFT", 12);
  const json d = run(s, "key_two_poses", file);
  ASSERT_TRUE(d.is_object());
  EXPECT_EQ(d["timeline"]["frame"], 12);
  EXPECT_EQ(d["timeline"]["clip_name"], "Action");
  EXPECT_FALSE(bool(d["dirty"]));  // frame changes are not edits
  const json* rot = channelIn(d, "UpperArm.L", "rotation");
  ASSERT_NE(rot, nullptr);
  EXPECT_EQ((*rot)["times"].size(), 2u);
  EXPECT_EQ((*rot)["interpolations"][0], "bezier");  // eased rotations, as Blender's default

  Result<Scene> saved = loadScene(file);
  ASSERT_TRUE(saved.ok()) << saved.error();
  const Scene& sc = saved.value();
  const int arm = sc.skeleton.find("UpperArm.L");
  ASSERT_EQ(sc.clips.size(), 1u);
  const Channel* ch = channelOf(sc, arm, ChannelTarget::Rotation);
  ASSERT_NE(ch, nullptr);
  ASSERT_EQ(ch->keyCount(), 2);
  EXPECT_FLOAT_EQ(ch->times[0], 1.0f / 24);
  EXPECT_FLOAT_EQ(ch->times[1], 24.0f / 24);
  // Frame 1: 30 degrees about Z (rest rotations are the identity).
  const glm::quat k1 = quatOf(ch->values[0]), k24 = quatOf(ch->values[1]);
  EXPECT_NEAR(2 * std::acos(std::min(1.0f, std::abs(k1.w))), glm::radians(30.0f), 1e-4f);
  EXPECT_NEAR(std::abs(k1.z), std::sin(glm::radians(15.0f)), 1e-4f);
  // Frame 24: then 50 degrees about world X on top: q = rx(50) * rz(30).
  const glm::quat rx = glm::angleAxis(glm::radians(50.0f), glm::vec3(1, 0, 0));
  const glm::quat rz = glm::angleAxis(glm::radians(30.0f), glm::vec3(0, 0, 1));
  const float match = std::max(std::abs(glm::dot(k24, rx * rz)), std::max(std::abs(glm::dot(k24, glm::inverse(rx) * rz)),
                                std::max(std::abs(glm::dot(k24, rx * glm::inverse(rz))),
                                         std::abs(glm::dot(k24, glm::inverse(rx) * glm::inverse(rz))))));
  EXPECT_NEAR(match, 1.0f, 1e-4f);
  const float u = 11.0f / 23.0f, sm = 3 * u * u - 2 * u * u * u;
  EXPECT_GT(glm::dot(k1, k24), 0.0f) << "keyed in one hemisphere";
  const glm::quat expected = glm::normalize(k1 * (1 - sm) + k24 * sm);
  expectRotation(rotationIn(d, "UpperArm.L"), glm::dquat(expected.w, expected.x, expected.y, expected.z), 1e-5,
                 "frame 12");

  // The authored clip exported to glTF and BVH, read back by our readers: the same pose at frame 12.
  Result<Document> doc = openDocument(file);
  ASSERT_TRUE(doc.ok());
  Pose base = Pose::rest(sc.skeleton);
  sampleClip(sc.clips[0], 0.5f, base);
  const std::vector<glm::mat4> want = computeWorld(sc.skeleton, base);
  for (const char* ext : {".gltf", ".bvh"}) {
    const std::string out = dir_ + "/exported" + ext;
    std::vector<std::string> report;
    ASSERT_EQ(exportDocument(doc.value(), out, &report), "") << ext;
    Result<Scene> back = loadScene(out);
    ASSERT_TRUE(back.ok()) << back.error();
    ASSERT_FALSE(back.value().clips.empty()) << ext;
    Pose p = Pose::rest(back.value().skeleton);
    sampleClip(back.value().clips[0], 0.5f, p);
    const std::vector<glm::mat4> got = computeWorld(back.value().skeleton, p);
    for (const char* name : {"UpperArm.L", "LowerArm.L", "Hand.L"}) {
      const int j = sc.skeleton.find(name), k = back.value().skeleton.find(name);
      ASSERT_GE(k, 0) << ext << " " << name;
      EXPECT_LT(glm::distance(glm::vec3(want[j][3]), glm::vec3(got[k][3])), 2e-3f) << ext << " " << name;
    }
  }
}

TEST_F(KeyingE2e, SpacePlaysArrowsStepAndShiftArrowsJump) {
  json d = run(steps(Script(), "RIGHT", 3), "step_right");
  EXPECT_EQ(d["timeline"]["frame"], 4);
  d = run(steps(Script(), "RIGHT", 3).key("LEFT"), "step_left");
  EXPECT_EQ(d["timeline"]["frame"], 3);
  d = run(Script().keyDown("LEFT_SHIFT").key("RIGHT").keyUp("LEFT_SHIFT"), "jump_end");
  EXPECT_EQ(d["timeline"]["frame"], 250);
  d = run(steps(Script(), "RIGHT", 5).keyDown("LEFT_SHIFT").key("LEFT").keyUp("LEFT_SHIFT"), "jump_start");
  EXPECT_EQ(d["timeline"]["frame"], 1);
  // Space plays (1/60 s per replayed frame): still playing at the end, past frame 1.
  d = run(Script().key("SPACE").wait(30), "play");
  EXPECT_TRUE(bool(d["timeline"]["playing"]));
  EXPECT_GT(d["timeline"]["frame"].get<long long>(), 1);
  // Space again pauses on a whole frame.
  d = run(Script().key("SPACE").wait(30).key("SPACE"), "pause");
  EXPECT_FALSE(bool(d["timeline"]["playing"]));
  EXPECT_GT(d["timeline"]["frame"].get<long long>(), 1);
  EXPECT_NEAR(double(d["playback"]["time"]) * 24, double(d["timeline"]["frame"]), 1e-6);
}

TEST_F(KeyingE2e, DraggingInTheRulerScrubs) {
  const double y = rulerMiddle(front_);
  const glm::dvec2 a(rulerX(front_, 100), y), b(rulerX(front_, 60), y);
  json d = run(Script().move(a).down().wait(2), "scrub_press");
  EXPECT_EQ(d["timeline"]["frame"], 100);
  d = run(Script().move(a).down().path(a, b, 5).up(), "scrub_drag");
  EXPECT_EQ(d["timeline"]["frame"], 60);
  EXPECT_EQ(d["undo_depth"], 0);  // scrubbing is not an edit
}

// Auto-IK on (Ctrl+I), frame 10, auto-key on (Pose > Auto-key), then drag the hand: keys at
// frame 10 for exactly the joints the drag moved (the chain of 2 above the hand), one undo step.
TEST_F(KeyingE2e, AutoKeyRecordsAnIkDrag) {
  const glm::dvec2 h = pixelOf("Hand.L");
  Script s;
  s.keyDown("LEFT_CONTROL").key("I").keyUp("LEFT_CONTROL");
  s = steps(s, "RIGHT", 9);
  s.menu("Pose", "Auto-key");
  s.move(h).down().path(h, h + glm::dvec2(-50, 70), 8).up().wait(2);
  json d = run(s, "auto_key_ik");
  ASSERT_TRUE(d.is_object());
  EXPECT_TRUE(bool(d["timeline"]["auto_key"]));
  EXPECT_EQ(d["undo_depth"], 1);
  std::set<std::string> keyed;
  for (const json& c : d["timeline"]["channels"]) {
    keyed.insert(c["joint"].get<std::string>());
    ASSERT_EQ(c["times"].size(), 1u);
    EXPECT_NEAR(double(c["times"][0]), 10.0 / 24, 1e-6);
  }
  EXPECT_EQ(keyed, (std::set<std::string>{"UpperArm.L", "LowerArm.L"}));
  // Ctrl+Z takes back the pose and the keys.
  s.keyDown("LEFT_CONTROL").key("Z").keyUp("LEFT_CONTROL");
  d = run(s, "auto_key_ik_undone");
  EXPECT_TRUE(d["timeline"]["channels"].empty());
  expectNear(jointIn(d, "Hand.L"), jointIn(front_, "Hand.L"), 1e-5, "hand after undo");
}

TEST_F(KeyingE2e, AltIDeletesAndUndoRemovesAKey) {
  Script s;
  s.select("UpperArm.L").key("I");
  s = steps(s, "RIGHT", 4);
  s.key("I");
  json d = run(s, "two_keys");
  ASSERT_NE(channelIn(d, "UpperArm.L", "rotation"), nullptr);
  EXPECT_EQ((*channelIn(d, "UpperArm.L", "rotation"))["times"].size(), 2u);
  EXPECT_EQ(d["timeline"]["selected_key_frames"], json::array({1, 5}));
  Script del = s;
  del.keyDown("LEFT_ALT").key("I").keyUp("LEFT_ALT");
  d = run(del, "alt_i");
  EXPECT_EQ(d["timeline"]["selected_key_frames"], json::array({1}));
  EXPECT_EQ(d["undo_depth"], 3);
  s.keyDown("LEFT_CONTROL").key("Z").keyUp("LEFT_CONTROL");
  d = run(s, "undo_key");
  EXPECT_EQ(d["timeline"]["selected_key_frames"], json::array({1}));
  EXPECT_EQ(d["undo_depth"], 1);
}

// Keys on frames 1, 24 and 60 of the selected joint: a diamond at each, in the ruler's
// middle row (the fill colour), none at frame 40.
TEST_F(KeyingE2e, KeyframeDiamondsAreDrawnOnTheKeyedFrames) {
  Script s;
  s.select("UpperArm.L");
  s.key("R").key("Z").key("3").key("0").key("ENTER").key("I");
  s = steps(s, "RIGHT", 23);
  s.key("R").key("X").key("5").key("0").key("ENTER").key("I");
  s = steps(s, "RIGHT", 36);
  s.key("R").key("Y").key("4").key("0").key("ENTER").key("I");
  s = steps(s, "LEFT", 30);  // the playhead at frame 30, away from the diamonds
  const json d = run(s, "diamonds");
  ASSERT_TRUE(d.is_object());
  EXPECT_EQ(d["timeline"]["selected_key_frames"], json::array({1, 24, 60}));
  Result<Image> shot = loadPng(shotDir() + "/diamonds.png");
  ASSERT_TRUE(shot.ok()) << shot.error();
  const int y = static_cast<int>(std::lround(rulerMiddle(d) + 2));
  auto isDiamond = [&](double x) {
    const std::uint8_t* p = shot.value().pixel(static_cast<int>(std::lround(x)), y);
    return p[0] > 200 && p[1] > 140 && p[1] < 220 && p[2] < 100;
  };
  for (long long f : {1LL, 24LL, 60LL}) EXPECT_TRUE(isDiamond(rulerX(d, f))) << "frame " << f;
  EXPECT_FALSE(isDiamond(rulerX(d, 40)));
  EXPECT_FALSE(isDiamond(rulerX(d, 30)));
}

}  // namespace
}  // namespace kinema::test
