// End-to-end tests of the dope sheet: the real `kinema edit` under xvfb-run on --script
// replay (and once by xdotool through the X server) with a .kinema file written here (the
// default character with a clip keyed on five joints). Outcomes are read from --dump-state
// (its dope_sheet rows, selection and view) or from the saved file.
//
// Pixels come from the dump of a run that only opens the dope sheet (the suite's first run),
// not from constants of the window size: its key area (dope_sheet.view: x, y, the frame at
// the left edge, pixels per frame, row height), with the summary row first, so frame f is at
// x = view.x + (f - first) * ppf and row r's centre at y = view.y + rowHeight (r + 1/2);
// the joint names lie left of the key area and the frame ruler above it, inside the dope
// sheet's window (named "Dope Sheet"). Menus and widgets are clicked by name.
#include <cmath>
#include <fstream>

#include "editor/e2e_harness.h"

namespace kinema::test {
namespace KINEMA_UNITY_ID {

using namespace e2e;

// Rows of the clip below (skeleton order under the summary).
enum Row { kSummary = 0, kHips = 1, kSpine = 2, kHead = 3, kUpperArmL = 4, kLowerArmL = 5 };

// The clip: rotation keys (frame time 1/24 s) on Hips 0, 10, 20; Spine 5, 10; Head 10, 15;
// UpperArm.L 0, 8, 16, 24; LowerArm.L 4, 12, 20.
json clipJson() {
  const auto channel = [](const char* joint, std::vector<int> frames) {
    json times = json::array(), values = json::array();
    for (size_t i = 0; i < frames.size(); ++i) {
      times.push_back(frames[i] / 24.0);
      const double a = 0.3 * ((i % 2) ? 1 : -1);  // +-0.3 rad about Z, alternating
      values.push_back({0.0, 0.0, std::sin(a / 2), std::cos(a / 2)});
    }
    return json{{"joint", joint}, {"target", "rotation"}, {"times", times}, {"values", values}};
  };
  return json::array({json{{"name", "wave"},
                           {"frame_time", 1.0 / 24.0},
                           {"channels", json::array({channel("Hips", {0, 10, 20}), channel("Spine", {5, 10}),
                                                     channel("Head", {10, 15}), channel("UpperArm.L", {0, 8, 16, 24}),
                                                     channel("LowerArm.L", {4, 12, 20})})}}});
}

std::vector<double> framesOfRow(const json& d, const std::string& joint) {
  for (const json& r : d["dope_sheet"]["rows"])
    if (r["joint"] == joint) {
      std::vector<double> out;
      for (const json& f : r["frames"]) out.push_back(std::round(double(f) * 1000) / 1000);
      return out;
    }
  return {};
}

std::vector<std::string> selectedKeys(const json& d) {
  std::vector<std::string> out;
  for (const json& s : d["dope_sheet"]["selected"])
    out.push_back(std::string(s["joint"]) + "@" + std::to_string(std::lround(double(s["frame"]))));
  return out;
}

using Frames = std::vector<double>;

// The default character with the clip, written to `path`; false when the asset is unreadable.
bool writeWaveFile(const std::string& path) {
  std::ifstream in(std::string(KINEMA_SOURCE_DIR) + "/assets/default_character.kinema");
  json file = json::parse(in, nullptr, false);
  if (file.is_discarded()) return false;
  file["clips"] = clipJson();
  std::ofstream(path) << file.dump(1);
  return true;
}

class DopeSheetE2e : public ::testing::Test {
 protected:
  // The dope sheet opened from the View menu once for the suite: its dump (opened_) gives
  // the key area and the widgets' rectangles the other tests' pixels come from.
  static void SetUpTestSuite() {
    if (runCommand("command -v xvfb-run") != 0) return;
    const std::string dir = makeTempDir(), file = dir + "/wave.kinema";
    if (writeWaveFile(file)) {
      const json d = runEditor(dir, shotDir(), opened(), "open", file);
      if (d.is_object()) opened_ = d;
    }
    runCommand("rm -rf '" + dir + "'");
  }
  void SetUp() override {
    if (runCommand("command -v xvfb-run") != 0) GTEST_SKIP() << "SKIPPED: xvfb-run is not installed";
    ASSERT_TRUE(opened_.is_object()) << "the run opening the dope sheet failed";
    dir_ = makeTempDir();
    file_ = dir_ + "/wave.kinema";
    ASSERT_TRUE(writeWaveFile(file_));
  }
  void TearDown() override {
    if (!dir_.empty()) runCommand("rm -rf '" + dir_ + "'");
  }
  static std::string shotDir() {
    const std::string dir = std::string(KINEMA_BUILD_DIR) + "/dope_sheet_e2e";
    runCommand("mkdir -p '" + dir + "'");
    return dir;
  }
  json run(const Script& script, const std::string& name) { return runEditor(dir_, shotDir(), script, name, file_); }
  // A script that opens the dope sheet from the View menu.
  static Script opened() {
    Script s;
    s.menu("View", "Dope Sheet");
    return s;
  }
  // The key area of the opened dope sheet: frame f's x, row r's centre y, row r's top.
  static const json& view() { return opened_["dope_sheet"]["view"]; }
  static double frameX(double frame) {
    return double(view()["x"]) + (frame - double(view()["first_frame"])) * double(view()["pixels_per_frame"]);
  }
  static double rowHeight() { return view()["row_height"]; }
  static double rowTop(int row) { return double(view()["y"]) + rowHeight() * (row - int(view()["first_row"])); }
  static double rowY(int row) { return rowTop(row) + rowHeight() / 2; }
  static glm::dvec2 key(double frame, int row) { return {frameX(frame), rowY(row)}; }
  // The middle of the frame ruler (between the window's top and the key area's) and of the
  // names column (between the window's left and the key area's).
  static double rulerY() { return (itemRect(opened_, "Dope Sheet").y + double(view()["y"])) / 2; }
  static double namesX() { return (itemRect(opened_, "Dope Sheet").x + double(view()["x"])) / 2; }

  static inline json opened_;
  std::string dir_, file_;
};

TEST_F(DopeSheetE2e, TheViewMenuOpensItOverTheTimelineWithTheClipsRows) {
  json d = opened_;  // the suite's run of opened()
  const json& ds = d["dope_sheet"];
  EXPECT_TRUE(ds["shown"].get<bool>());
  // Over the timeline: the 3D view ends where the dope sheet begins, the dope sheet where
  // the timeline does, as wide as the view; its key area right of the names and under the
  // ruler, to its window's right and bottom edges.
  const e2e::Rect sheet = itemRect(d, "Dope Sheet"), timeline = itemRect(d, "Timeline"), view = viewportRect(d);
  EXPECT_EQ(view.bottom(), sheet.y);
  EXPECT_EQ(sheet.bottom(), timeline.y);
  EXPECT_EQ(sheet.x, view.x);
  EXPECT_EQ(sheet.width, view.width);
  EXPECT_GT(double(ds["view"]["x"]), sheet.x);
  EXPECT_GT(double(ds["view"]["y"]), sheet.y);
  EXPECT_EQ(double(ds["view"]["x"]) + double(ds["view"]["width"]), sheet.right());
  EXPECT_EQ(double(ds["view"]["y"]) + double(ds["view"]["height"]), sheet.bottom());
  // The view opens at frame -2 on the left edge with 12 px per frame.
  EXPECT_EQ(double(ds["view"]["first_frame"]), -2.0);
  EXPECT_EQ(double(ds["view"]["pixels_per_frame"]), 12.0);
  ASSERT_EQ(ds["rows"].size(), 6u);
  EXPECT_EQ(ds["rows"][0]["joint"], "Summary");
  EXPECT_EQ(ds["rows"][kSpine]["joint"], "Spine");
  EXPECT_EQ(ds["rows"][kLowerArmL]["joint"], "LowerArm.L");
  EXPECT_EQ(framesOfRow(d, "Summary"), (Frames{0, 4, 5, 8, 10, 12, 15, 16, 20, 24}));
  EXPECT_EQ(int(d["undo_depth"]), 0);
  // The menu item again closes it: the 3D view gets its room back, down to the timeline.
  d = run(opened().menu("View", "Dope Sheet"), "close");
  EXPECT_FALSE(d["dope_sheet"]["shown"].get<bool>());
  EXPECT_EQ(viewportRect(d).height, view.height + sheet.height);
  EXPECT_EQ(viewportRect(d).bottom(), itemRect(d, "Timeline").y);
}

TEST_F(DopeSheetE2e, DraggingAKeyMovesItToTheFrameUnderTheMouse) {
  // Spine's key at 5, dragged 8.4 frames to the right: snapped to frame 13,
  // past Spine's key at 10, which stays. One undo step.
  Script s = opened();
  s.move(key(5, kSpine)).down().path(key(5, kSpine), key(13.4, kSpine), 8).up().wait(2);
  json d = run(s, "drag_key");
  ASSERT_TRUE(d.is_object());
  EXPECT_EQ(framesOfRow(d, "Spine"), (Frames{10, 13}));
  EXPECT_EQ(framesOfRow(d, "Hips"), (Frames{0, 10, 20}));
  EXPECT_EQ(selectedKeys(d), std::vector<std::string>{"Spine@13"});
  EXPECT_EQ(int(d["undo_depth"]), 1);
  EXPECT_TRUE(d["dirty"].get<bool>());
  // Ctrl+Z puts it back.
  s.keyDown("LEFT_CONTROL").key("Z").keyUp("LEFT_CONTROL").wait(2);
  d = run(s, "drag_key_undo");
  EXPECT_EQ(framesOfRow(d, "Spine"), (Frames{5, 10}));
  EXPECT_EQ(int(d["undo_depth"]), 0);
  // A drag to the left, 2.6 frames: 4 - 2.6 = 1.4 -> frame 1 (LowerArm.L's first key).
  Script left = opened();
  left.move(key(4, kLowerArmL)).down().path(key(4, kLowerArmL), key(1.4, kLowerArmL), 5).up().wait(2);
  d = run(left, "drag_key_left");
  EXPECT_EQ(framesOfRow(d, "LowerArm.L"), (Frames{1, 12, 20}));

  // G: Head's key at 15 clicked, G, the mouse 2.6 frames right: 17.6 rounds to 18;
  // a left click confirms. Then the same with Esc: nothing moves and no step is added.
  Script grab = opened();
  grab.click(key(15, kHead)).wait(1).key("G").path(key(15, kHead), key(17.6, kHead), 3).wait(1);
  Script cancelled = grab;
  grab.down().up().wait(2);
  d = run(grab, "grab_key");
  EXPECT_EQ(framesOfRow(d, "Head"), (Frames{10, 18}));
  EXPECT_EQ(int(d["undo_depth"]), 1);
  cancelled.key("ESCAPE").wait(2);
  d = run(cancelled, "grab_key_cancel");
  EXPECT_EQ(framesOfRow(d, "Head"), (Frames{10, 15}));
  EXPECT_EQ(int(d["undo_depth"]), 0);
  EXPECT_EQ(selectedKeys(d), std::vector<std::string>{"Head@15"});
  // A click on a joint's name selects that joint.
  Script name = opened();
  name.click({namesX(), rowY(kLowerArmL)}).wait(2);
  d = run(name, "click_name");
  EXPECT_EQ(d["selection"], json::array({"LowerArm.L"}));
}

TEST_F(DopeSheetE2e, BoxSelectThenDeleteAndUndo) {
  // A box from frame 8 on the Spine row to frame 16 on the Head row (started on empty space)
  // takes Spine@10, Head@10 and Head@15; X deletes them (Head has no keys left: its row goes).
  Script s = opened();
  const glm::dvec2 a(frameX(8), rowTop(kSpine) + 3), b(frameX(16), rowTop(kHead + 1) - 3);
  s.move(a).down().path(a, b, 6).up().wait(2);
  json d = run(s, "box_select");
  ASSERT_TRUE(d.is_object());
  EXPECT_EQ(selectedKeys(d), (std::vector<std::string>{"Spine@10", "Head@10", "Head@15"}));
  EXPECT_EQ(int(d["undo_depth"]), 0) << "selecting is not an edit";
  s.key("X").wait(2);
  d = run(s, "box_delete");
  EXPECT_EQ(framesOfRow(d, "Spine"), (Frames{5}));
  EXPECT_EQ(framesOfRow(d, "Head"), (Frames{}));
  EXPECT_EQ(d["dope_sheet"]["rows"].size(), 5u);
  EXPECT_EQ(framesOfRow(d, "Summary"), (Frames{0, 4, 5, 8, 10, 12, 16, 20, 24}));  // Hips keeps 10
  EXPECT_EQ(int(d["undo_depth"]), 1);
  s.keyDown("LEFT_CONTROL").key("Z").keyUp("LEFT_CONTROL").wait(2);
  d = run(s, "box_delete_undo");
  EXPECT_EQ(framesOfRow(d, "Spine"), (Frames{5, 10}));
  EXPECT_EQ(framesOfRow(d, "Head"), (Frames{10, 15}));
  EXPECT_EQ(int(d["undo_depth"]), 0);
  EXPECT_EQ(int(d["redo_depth"]), 1);
  // A and Alt+A select all and nothing.
  Script all = opened();
  all.move(key(30, kHips)).key("A").wait(2);
  d = run(all, "select_all");
  EXPECT_EQ(d["dope_sheet"]["selected"].size(), 3u + 2 + 2 + 4 + 3);
  all.keyDown("LEFT_ALT").key("A").keyUp("LEFT_ALT").wait(2);
  d = run(all, "select_none");
  EXPECT_EQ(d["dope_sheet"]["selected"].size(), 0u);
  EXPECT_EQ(d["selection"].size(), 0u) << "A over the dope sheet is not the viewport's select all";
}

TEST_F(DopeSheetE2e, CopyPasteAtTheCurrentFrame) {
  // Hips@10 clicked, Head@15 Shift-clicked, Ctrl+C; the current frame set to 30 in the
  // ruler; Ctrl+V: the earliest copied key lands on 30, the other 5 frames later.
  Script s = opened();
  s.click(key(10, kHips)).wait(1);
  s.move(key(15, kHead)).keyDown("LEFT_SHIFT").down().up().keyUp("LEFT_SHIFT").wait(1);
  s.keyDown("LEFT_CONTROL").key("C").keyUp("LEFT_CONTROL").wait(1);
  s.click({frameX(30), rulerY()}).wait(2);
  s.move(key(40, kSpine)).keyDown("LEFT_CONTROL").key("V").keyUp("LEFT_CONTROL").wait(2);
  json d = run(s, "copy_paste");
  ASSERT_TRUE(d.is_object());
  EXPECT_NEAR(double(d["playback"]["time"]), 30 / 24.0, 1e-9);
  EXPECT_EQ(framesOfRow(d, "Hips"), (Frames{0, 10, 20, 30}));
  EXPECT_EQ(framesOfRow(d, "Head"), (Frames{10, 15, 35}));
  EXPECT_EQ(framesOfRow(d, "Spine"), (Frames{5, 10}));
  EXPECT_EQ(selectedKeys(d), (std::vector<std::string>{"Hips@30", "Head@35"}));
  EXPECT_EQ(int(d["dope_sheet"]["clipboard_keys"]), 2);
  EXPECT_TRUE(d["selection"].empty()) << "Ctrl+C over the dope sheet is not Copy Pose";
  const int depth = d["undo_depth"];
  // Ctrl+Z undoes the paste alone.
  s.keyDown("LEFT_CONTROL").key("Z").keyUp("LEFT_CONTROL").wait(2);
  d = run(s, "copy_paste_undo");
  EXPECT_EQ(framesOfRow(d, "Hips"), (Frames{0, 10, 20}));
  EXPECT_EQ(framesOfRow(d, "Head"), (Frames{10, 15}));
  EXPECT_EQ(int(d["undo_depth"]), depth - 1);
}

TEST_F(DopeSheetE2e, ScreenshotForTheReadme) {
  // Keys of the arm selected by a box (frames 7..13 on UpperArm.L and LowerArm.L), the
  // current frame at 12.
  Script s = opened();
  s.click({frameX(12), rulerY()}).wait(2);
  const glm::dvec2 a(frameX(6.5), rowTop(kUpperArmL) + 2), b(frameX(13.5), rowTop(kLowerArmL + 1) - 2);
  s.move(a).down().path(a, b, 4).up().wait(3);
  const json d = run(s, "dope_sheet");
  ASSERT_TRUE(d.is_object());
  EXPECT_EQ(selectedKeys(d), (std::vector<std::string>{"UpperArm.L@8", "LowerArm.L@12"}));
}

TEST_F(DopeSheetE2e, XdotoolDragsAKeyThroughTheXServer) {
  if (runCommand("command -v xdotool") != 0) GTEST_SKIP() << "SKIPPED: xdotool is not installed";
  // A real user's path: View > Dope Sheet, LowerArm.L's key at 20 dragged 5 frames right,
  // Ctrl+S, Ctrl+Q; the saved file holds the key at frame 25.
  const std::string sh = dir_ + "/drive.sh";
  const auto at = [](glm::dvec2 p) { return std::to_string(std::lround(p.x)) + " " + std::to_string(std::lround(p.y)); };
  std::ofstream(sh) << "set -e\n"
                    << editorEnvironment(dir_) << KINEMA_BINARY << " edit '" << file_ << "' --size " << windowSize()
                    << " --frame-count 100000 --dump-state " << dir_
                    << "/xdotool.json & pid=$!\n"
                    << "for i in $(seq 100); do w=$(xdotool search --name 'Kinema - ' | head -1) && [ -n \"$w\" ] && break; sleep 0.1; done\n"
                    << "xdotool windowfocus --sync $w || true\nsleep 0.5\n"
                    << "xdotool mousemove --window $w " << at(itemRect(opened_, "View").centre()) << " click 1\nsleep 0.4\n"
                    << "xdotool mousemove --window $w " << at(itemRect(opened_, "View/Dope Sheet").centre())
                    << " click 1\nsleep 0.4\n"
                    << "xdotool mousemove --window $w " << at(key(20, kLowerArmL)) << "\nsleep 0.3\nxdotool mousedown 1\nsleep 0.3\n"
                    << "xdotool mousemove --window $w " << at(key(22, kLowerArmL)) << "\nsleep 0.2\n"
                    << "xdotool mousemove --window $w " << at(key(25, kLowerArmL)) << "\nsleep 0.3\nxdotool mouseup 1\nsleep 0.4\n"
                    << "xdotool key --window $w ctrl+s\nsleep 0.5\n"
                    // The editor may quit on the press, before xdotool sends the releases to
                    // its window (BadWindow): the editor's own exit status is what counts.
                    << "xdotool key --window $w ctrl+q || true\nwait $pid\n";
  std::string out, err;
  ASSERT_EQ(runCommand(xvfb() + "sh " + sh, &out, &err), 0) << err;
  const json saved = readJson(file_);
  ASSERT_TRUE(saved.is_object());
  std::vector<double> frames;
  for (const json& ch : saved["clips"][0]["channels"])
    if (ch["joint"] == "LowerArm.L")
      for (const json& t : ch["times"]) frames.push_back(std::round(double(t) * 24 * 1000) / 1000);
  EXPECT_EQ(frames, (Frames{4, 12, 25}));
}

}  // namespace
}  // namespace kinema::test
