// End-to-end tests of the panels and dialogs: the real `kinema edit` under xvfb-run with
// Mesa's llvmpipe, driven by --script replay through the menus, the outliner, the
// properties and history panels and the file dialog, checked in the .kinema files the
// editor saves. Expected rotations are derived by hand (a rotation of A degrees about Z is
// (x, y, z, w) = (0, 0, sin(A/2), cos(A/2)); mirroring across X = 0 negates y and z).
// Widgets and menu items are clicked by name (e2e_harness.h), at 1280x720 or KINEMA_E2E_SIZE.
#include <nlohmann/json.hpp>

#include <algorithm>
#include <csignal>
#include <filesystem>
#include <cmath>
#include <fstream>
#include <thread>

#include "anim/sampling.h"
#include "editor/e2e_harness.h"
#include "io/kinema_file.h"
#include "io/scene_files.h"
#include "test_support.h"

namespace kinema::test {
namespace KINEMA_UNITY_ID {

// Scripts start as the editor opens (no front view first); one event per frame from frame 3.
struct Script : e2e::Script {
  Script() : e2e::Script(Start::AsOpened) {}
};

glm::dquat rotZ(double degrees) {
  const double h = glm::radians(degrees) / 2;
  return glm::dquat(std::cos(h), 0, 0, std::sin(h));
}
glm::dquat rotX(double degrees) {
  const double h = glm::radians(degrees) / 2;
  return glm::dquat(std::cos(h), std::sin(h), 0, 0);
}

// File > Export > `item`: the submenu opens on hover, the pointer goes along its row into the
// submenu's first entry, then clicks `item` ("GLB (.glb)..."); the file dialog is opening.
e2e::Script& exportThroughTheMenu(e2e::Script& s, const std::string& item) {
  s.clickItem("File").wait(2).moveItem("File/Export").wait(3).moveItem("File/Export/glTF (.gltf)...").wait(2);
  return s.clickItem("File/Export/" + item).wait(3);
}

class PanelsE2e : public ::testing::Test {
 protected:
  void SetUp() override {
    if (runCommand("command -v xvfb-run") != 0) GTEST_SKIP() << "SKIPPED: xvfb-run is not installed";
    dir_ = makeTempDir();
    shots_ = std::string(KINEMA_BUILD_DIR) + "/panels_e2e";
    runCommand("mkdir -p '" + shots_ + "'");
  }
  void TearDown() override {
    if (!dir_.empty()) runCommand("rm -rf '" + dir_ + "'");
  }

  // Recent files and recovery files stay inside the test's folder.
  std::string environment() const { return e2e::editorEnvironment(dir_ + "/config", dir_ + "/state"); }
  std::string command(const e2e::Script& script, const std::string& name, const std::string& file) {
    const std::string scriptPath = dir_ + "/" + name + ".jsonl";
    std::ofstream(scriptPath) << script.text();
    return environment() + KINEMA_BINARY + " edit " + (file.empty() ? "" : "'" + file + "' ") + "--size " +
           e2e::windowSize() + " --script " + scriptPath + " --screenshot " + shots_ + "/" + name + ".png";
  }
  // Runs the editor on `file` (default character when empty); the last frame goes to
  // build/panels_e2e/NAME.png.
  void run(const e2e::Script& script, const std::string& name, const std::string& file = "") {
    std::string out, err;
    const int rc = runCommand(e2e::xvfb() + command(script, name, file), &out, &err);
    EXPECT_EQ(rc, 0) << err;
  }
  // run() plus --dump-state: the editor's state at exit as JSON.
  nlohmann::json runAndDump(const e2e::Script& script, const std::string& name) {
    std::string out, err;
    const std::string dump = dir_ + "/" + name + ".json";
    const int rc = runCommand(e2e::xvfb() + command(script, name, "") + " --dump-state " + dump, &out, &err);
    EXPECT_EQ(rc, 0) << err;
    nlohmann::json j = nlohmann::json::parse(readFile(dump), nullptr, false);
    EXPECT_TRUE(j.is_object()) << dump;
    return j.is_object() ? j : nlohmann::json::object();
  }
  static glm::dquat dumpedRotation(const nlohmann::json& d, const std::string& joint) {
    for (const nlohmann::json& j : d["joints"])
      if (j["name"] == joint) return glm::dquat(j["rotation"][3], j["rotation"][0], j["rotation"][1], j["rotation"][2]);
    ADD_FAILURE() << "no joint " << joint;
    return glm::dquat(NAN, NAN, NAN, NAN);
  }
  Scene saved(const std::string& path) {
    Result<Scene> scene = loadKinemaFile(path);
    EXPECT_TRUE(scene.ok()) << scene.error();
    return scene ? scene.value() : Scene{};
  }
  static glm::dquat rotation(const Scene& s, const std::string& joint) {
    const int j = s.skeleton.find(joint);
    if (j < 0 || j >= s.pose.size()) {
      ADD_FAILURE() << "no pose for " << joint;
      return glm::dquat(NAN, NAN, NAN, NAN);
    }
    return glm::dquat(s.pose.local[j].rotation);
  }
  std::string dir_, shots_;
};

#define EXPECT_ROTATION(actual, expected)                                                      \
  do {                                                                                         \
    const glm::dquat a_ = (actual), e_ = (expected);                                           \
    EXPECT_NEAR(std::abs(glm::dot(a_, e_)), 1.0, 1e-5) << "got (" << a_.x << ", " << a_.y << ", " \
                                                       << a_.z << ", " << a_.w << ")";         \
  } while (0)

TEST_F(PanelsE2e, EulerEntrySaveAsAndReopenRoundTripThePose) {
  Script edit;
  edit.select("UpperArm.L").euler(2, 40.0).saveAs(dir_ + "/a.kinema");
  run(edit, "euler_entry");
  const Scene a = saved(dir_ + "/a.kinema");
  ASSERT_EQ(a.pose.size(), a.skeleton.size());
  EXPECT_ROTATION(rotation(a, "UpperArm.L"), rotZ(40.0));
  for (int j = 0; j < a.skeleton.size(); ++j)
    if (a.skeleton.names[j] != "UpperArm.L") EXPECT_ROTATION(glm::dquat(a.pose.local[j].rotation), glm::dquat(1, 0, 0, 0));

  // Reopen it and save it again under another name: the same skeleton and pose come back.
  Script again;
  again.saveAs("b.kinema");  // relative to the folder of the open file
  run(again, "reopen", dir_ + "/a.kinema");
  const Scene b = saved(dir_ + "/b.kinema");
  ASSERT_EQ(b.skeleton.names, a.skeleton.names);
  ASSERT_EQ(b.pose.size(), a.pose.size());
  for (int j = 0; j < a.pose.size(); ++j) {
    EXPECT_ROTATION(glm::dquat(b.pose.local[j].rotation), glm::dquat(a.pose.local[j].rotation));
    EXPECT_LT(glm::length(b.pose.local[j].translation - a.pose.local[j].translation), 1e-6f);
  }
}

TEST_F(PanelsE2e, EulerOrderZxyAndQuaternionEntry) {
  // ZXY: R = Rz * Rx * Ry. X 30 then Z 50 gives Rz(50) Rx(30).
  Script zxy;
  zxy.select("UpperArm.L").clickItem("Properties/Rotation mode").wait(2).clickItem("Properties/Rotation mode/ZXY").wait(2);
  zxy.euler(0, 30.0).euler(2, 50.0).saveAs(dir_ + "/zxy.kinema");
  run(zxy, "euler_zxy");
  EXPECT_ROTATION(rotation(saved(dir_ + "/zxy.kinema"), "UpperArm.L"), rotZ(50.0) * rotX(30.0));

  // Quaternion (x, y, z, w) = (1, 0, 1, 0) typed: normalised on entry to (0.7071, 0, 0.7071, 0),
  // a half turn about (1, 0, 1) / sqrt 2; one undo step.
  Script quat;
  quat.select("Hand.R").clickItem("Properties/Rotation mode").wait(2);
  quat.clickItem("Properties/Rotation mode/Quaternion").wait(2);
  quat.clickItem("Properties/Quaternion/0").wait(1).type("1").clickItem("Properties/Quaternion/3").wait(1).type("0");
  quat.clickItem("Properties/Quaternion/2").wait(1).type("1").key("ENTER").wait(3).saveAs(dir_ + "/quat.kinema");
  const nlohmann::json d = runAndDump(quat, "quaternion_entry");
  EXPECT_EQ(d["undo_depth"], 1);
  const double h = std::sqrt(0.5);
  EXPECT_ROTATION(rotation(saved(dir_ + "/quat.kinema"), "Hand.R"), glm::dquat(0, h, 0, h));
  EXPECT_NEAR(glm::length(rotation(saved(dir_ + "/quat.kinema"), "Hand.R")), 1.0, 1e-6);
}

TEST_F(PanelsE2e, JointLimitEnabledInThePropertiesIsSavedAndUndoable) {
  Script s;
  s.select("LowerArm.L").clickItem("Properties/Limit enabled").wait(2).saveAs(dir_ + "/limited.kinema");
  s.chord("Z", {"ctrl"}).wait(2).saveAs("unlimited.kinema");
  run(s, "joint_limit");
  const Scene limited = saved(dir_ + "/limited.kinema");
  const JointLimit* limit = limited.ik.limitOf(limited.skeleton.find("LowerArm.L"));
  ASSERT_NE(limit, nullptr);
  // Enabling starts from a 45 degree cone with +-45 degrees of twist.
  EXPECT_EQ(limit->type, JointLimitType::Cone);
  EXPECT_NEAR(limit->coneAngle, M_PI / 4, 1e-5);
  EXPECT_NEAR(limit->twistMin, -M_PI / 4, 1e-5);
  EXPECT_NEAR(limit->twistMax, M_PI / 4, 1e-5);
  for (int j = 0; j < limited.skeleton.size(); ++j)
    if (limited.skeleton.names[j] != "LowerArm.L") {
      EXPECT_EQ(limited.ik.limitOf(j), nullptr) << j;
    }
  const Scene undone = saved(dir_ + "/unlimited.kinema");
  EXPECT_EQ(undone.ik.limitOf(undone.skeleton.find("LowerArm.L")), nullptr);
}

TEST_F(PanelsE2e, CtrlZUndoesOneEntryAndTheHistoryPanelJumps) {
  Script s;
  s.select("UpperArm.L").euler(2, 10.0).euler(0, 20.0).euler(1, 30.0);
  s.chord("Z", {"ctrl"}).wait(2).saveAs(dir_ + "/undone.kinema");
  // History rows: (original), 1 = Z 10, 2 = X 20, 3 = Y 30 (redoable after the undo).
  s.clickItem("History/1").wait(2).saveAs("jumped.kinema");
  run(s, "undo_history");
  // After Ctrl+Z: X 20 and Z 10 in the order XYZ, R = Rx(20) Rz(10).
  EXPECT_ROTATION(rotation(saved(dir_ + "/undone.kinema"), "UpperArm.L"), rotX(20.0) * rotZ(10.0));
  EXPECT_ROTATION(rotation(saved(dir_ + "/jumped.kinema"), "UpperArm.L"), rotZ(10.0));
}

TEST_F(PanelsE2e, PasteFlippedMirrorsTheArm) {
  Script s;
  s.select("UpperArm.L").euler(2, 40.0).chord("C", {"ctrl"}).wait(1);
  s.select("UpperArm.R").chord("V", {"ctrl", "shift"}).wait(2).saveAs(dir_ + "/flipped.kinema");
  run(s, "paste_flipped");
  const Scene f = saved(dir_ + "/flipped.kinema");
  EXPECT_ROTATION(rotation(f, "UpperArm.L"), rotZ(40.0));
  EXPECT_ROTATION(rotation(f, "UpperArm.R"), rotZ(-40.0));  // (w, x, -y, -z) of Rz(40)
}

TEST_F(PanelsE2e, ResetToRestPoseThroughTheEditMenu) {
  Script s;
  s.select("UpperArm.L").euler(2, 40.0).select("Hand.R").euler(0, 15.0);
  s.menu("Edit", "Reset to Rest Pose").saveAs(dir_ + "/rest.kinema");
  run(s, "reset_rest");
  const Scene r = saved(dir_ + "/rest.kinema");
  ASSERT_EQ(r.pose.size(), r.skeleton.size());
  for (int j = 0; j < r.skeleton.size(); ++j) {
    EXPECT_ROTATION(glm::dquat(r.pose.local[j].rotation), glm::dquat(r.skeleton.rest[j].rotation));
    EXPECT_LT(glm::length(r.pose.local[j].translation - r.skeleton.rest[j].translation), 1e-6f) << j;
  }
}

TEST_F(PanelsE2e, RenameThroughTheOutlinerAndRefuseADuplicate) {
  Script s;
  s.doubleClickItem("Outliner/UpperArm.L").wait(2).type("Humerus.L").key("ENTER").wait(3);
  // A duplicate name is refused (the field stays with the reason); Escape leaves it.
  s.doubleClickItem("Outliner/LowerArm.L").wait(2).type("Hips").key("ENTER").wait(3);
  run(s, "rename_refused");  // the reason under the field, for the eye
  s.key("ESCAPE").wait(3);
  s.saveAs(dir_ + "/renamed.kinema");
  run(s, "rename");
  const Scene r = saved(dir_ + "/renamed.kinema");
  EXPECT_GE(r.skeleton.find("Humerus.L"), 0);
  EXPECT_EQ(r.skeleton.find("UpperArm.L"), -1);
  EXPECT_GE(r.skeleton.find("LowerArm.L"), 0);
  EXPECT_EQ(r.skeleton.parents[r.skeleton.find("LowerArm.L")], r.skeleton.find("Humerus.L"));
}

TEST_F(PanelsE2e, OutlinerSearchShowsMatchesWithTheirAncestors) {
  // "hand.r" leaves Hips, Spine, Chest, UpperChest, Shoulder.R, UpperArm.R, LowerArm.R,
  // Hand.R: the match is row 7, the last; it is clicked, turned and saved.
  Script s;
  s.clickItem("Outliner/Search").wait(1).type("hand.r").wait(2).clickItem("Outliner/Hand.R").wait(1).euler(2, 15.0);
  s.saveAs(dir_ + "/searched.kinema");
  const nlohmann::json d = runAndDump(s, "outliner_search");
  // The rows the outliner drew in the last frame (the search still typed), top to bottom.
  std::vector<std::pair<double, std::string>> rows;
  for (const auto& [name, rect] : d["items"].items())
    if (name.rfind("Outliner/", 0) == 0 && name != "Outliner/Search" && name.find('/', 9) == std::string::npos &&
        e2e::drawnLast(d, name))
      rows.emplace_back(double(rect["y"]), name.substr(9));
  std::sort(rows.begin(), rows.end());
  std::vector<std::string> shown;
  for (const auto& row : rows) shown.push_back(row.second);
  EXPECT_EQ(shown, (std::vector<std::string>{"Hips", "Spine", "Chest", "UpperChest", "Shoulder.R", "UpperArm.R",
                                             "LowerArm.R", "Hand.R"}));
  const Scene r = saved(dir_ + "/searched.kinema");
  EXPECT_ROTATION(rotation(r, "Hand.R"), rotZ(15.0));
  EXPECT_ROTATION(rotation(r, "Hand.L"), glm::dquat(1, 0, 0, 0));
}

TEST_F(PanelsE2e, AddIkTargetThroughThePoseMenuIsSaved) {
  Script s;
  s.select("Hand.L").menu("Pose", "Add IK Target to Selected");
  s.saveAs(dir_ + "/ik.kinema");
  run(s, "add_ik_target");
  const Scene r = saved(dir_ + "/ik.kinema");
  ASSERT_EQ(r.ik.targets.size(), 1u);
  const IkTarget& t = r.ik.targets[0];
  EXPECT_EQ(t.effector, r.skeleton.find("Hand.L"));
  // Placed where the hand is: the rest translations summed up the chain (no rotations).
  glm::vec3 hand(0.0f);
  for (int j = t.effector; j >= 0; j = r.skeleton.parents[j]) hand += r.skeleton.rest[j].translation;
  EXPECT_LT(glm::length(t.position - hand), 1e-4f);
}

TEST_F(PanelsE2e, IkPanelSettingsAndTypedTargetPositionMoveTheChain) {
  Script s;
  s.select("Hand.L").clickItem("IK Targets/Add IK Target to Selected").wait(2).clickItem("IK Targets/Chain length/+").wait(2);
  s.clickItem("IK Targets/Pinned").wait(2);
  s.clickItem("IK Targets/Solver").wait(2).clickItem("IK Targets/Solver/fabrik").wait(2);
  // Off the arm's line (a straight chain pulled along itself is the solvers' singular case);
  // the panel scrolled down first, should the position's row be below its bottom.
  s.scrollPanel("IK Targets", -10);
  s.doubleClickItem("IK Targets/Position/0").wait(1).type("0.5").key("ENTER").wait(4);
  s.doubleClickItem("IK Targets/Position/1").wait(1).type("1.3").key("ENTER").wait(4);
  const nlohmann::json d = runAndDump(s, "ik_panel");
  ASSERT_EQ(d["ik_targets"].size(), 1u);
  const nlohmann::json& t = d["ik_targets"][0];
  EXPECT_EQ(t["effector"], "Hand.L");
  EXPECT_EQ(t["chain_length"], 3);
  EXPECT_EQ(t["root"], "Shoulder.L");  // three bones up from the hand
  EXPECT_EQ(t["pinned"], true);
  EXPECT_EQ(t["solver"], "fabrik");
  EXPECT_EQ(d["undo_depth"], 6);  // add, chain, pin, solver, position x, position y: one step each
  // The target moved to (0.5, 1.3, 0) (z as placed at the hand) and the hand followed.
  const auto world = [&](const std::string& name) {
    for (const nlohmann::json& j : d["joints"])
      if (j["name"] == name) return glm::dvec3(j["world_position"][0], j["world_position"][1], j["world_position"][2]);
    return glm::dvec3(NAN);
  };
  const glm::dvec3 target(t["position"][0], t["position"][1], t["position"][2]);
  EXPECT_NEAR(target.x, 0.5, 1e-6);
  EXPECT_NEAR(target.y, 1.3, 1e-6);
  EXPECT_NEAR(target.z, 0.0, 1e-6);
  EXPECT_LT(glm::length(world("Hand.L") - target), 2e-3);
  // Bone lengths stay those of the default character (src/core/default_character.cpp puts
  // the left arm's joints at x = 0.17, 0.45, 0.71 on one line).
  EXPECT_NEAR(glm::length(world("Hand.L") - world("LowerArm.L")), 0.26, 1e-4);
  EXPECT_NEAR(glm::length(world("LowerArm.L") - world("UpperArm.L")), 0.28, 1e-4);
}

TEST_F(PanelsE2e, OpenBvhAndGltfThroughTheFileMenu) {
  KINEMA_REQUIRE_SHARED_DATA();
  for (const std::string file : {"/bvh/cmu_01_01_first720.bvh", "/gltf/CesiumMan.glb"}) {
    const std::string path = sharedDataDir() + file;
    Script s;
    s.menu("File", "Open...").wait(1).type(path).key("ENTER").wait(4);
    s.saveAs(dir_ + "/opened.kinema");
    run(s, "open_menu_" + lowerExtension(path).substr(1));
    const Result<Scene> original = loadScene(path);
    ASSERT_TRUE(original.ok()) << original.error();
    EXPECT_EQ(saved(dir_ + "/opened.kinema").skeleton.names, original->skeleton.names) << file;
    std::remove((dir_ + "/opened.kinema").c_str());
  }
}

TEST_F(PanelsE2e, OpenErrorsShowInThePopupAndTheEditorCarriesOn) {
  writeFile(dir_ + "/broken.bvh", "HIERARCHY\nROOT Hips\n{\n  OFFSET 0 zero 0\n");
  Script s;
  s.chord("O", {"ctrl"}).wait(2).type(dir_ + "/missing.bvh").key("ENTER").wait(4);
  s.key("ESCAPE").wait(3);  // closes the first error
  s.chord("O", {"ctrl"}).wait(2).type(dir_ + "/broken.bvh").key("ENTER").wait(4);
  const nlohmann::json d = runAndDump(s, "open_errors");
  // The missing file's error was dismissed; the broken file's error waits in the popup,
  // naming the file; the default character is still open and unchanged.
  ASSERT_EQ(d["errors"].size(), 1u) << d["errors"];
  const std::string error = d["errors"][0];
  EXPECT_NE(error.find("broken.bvh"), std::string::npos) << error;
  EXPECT_EQ(d["path"], "");
  EXPECT_EQ(d["dirty"], false);
  bool hasHips = false;
  for (const nlohmann::json& j : d["joints"]) hasHips = hasHips || j["name"] == "Hips";
  EXPECT_TRUE(hasHips);
}

TEST_F(PanelsE2e, NewAsksBeforeDiscardingUnsavedChanges) {
  // Dirty: Ctrl+N opens "Discard unsaved changes?"; Esc cancels and the edit stays.
  Script dirty;
  dirty.select("UpperArm.L").euler(2, 40.0).chord("N", {"ctrl"}).wait(3);
  run(dirty, "discard_question");  // the modal, for the eye
  dirty.key("ESCAPE").wait(3);
  const nlohmann::json kept = runAndDump(dirty, "discard_cancelled");
  EXPECT_EQ(kept["dirty"], true);
  EXPECT_ROTATION(dumpedRotation(kept, "UpperArm.L"), rotZ(40.0));
  // Clean (just saved): Ctrl+N starts the new document at once.
  Script clean;
  clean.select("UpperArm.L").euler(2, 40.0).saveAs(dir_ + "/kept.kinema").chord("N", {"ctrl"}).wait(3);
  const nlohmann::json fresh = runAndDump(clean, "new_after_save");
  EXPECT_EQ(fresh["path"], "");
  EXPECT_EQ(fresh["dirty"], false);
  EXPECT_ROTATION(dumpedRotation(fresh, "UpperArm.L"), glm::dquat(1, 0, 0, 0));
}

TEST_F(PanelsE2e, SaveFirstSavesThroughSaveAsThenStartsTheNewDocument) {
  Script s;
  s.select("UpperArm.L").euler(2, 40.0).chord("N", {"ctrl"}).wait(3);
  s.clickItem("Discard unsaved changes?/Save first").wait(3);  // in the centred question
  s.type(dir_ + "/first.kinema").key("ENTER").wait(4);
  const nlohmann::json d = runAndDump(s, "save_first");
  EXPECT_ROTATION(rotation(saved(dir_ + "/first.kinema"), "UpperArm.L"), rotZ(40.0));
  EXPECT_EQ(d["path"], "");  // then New went on
  EXPECT_EQ(d["dirty"], false);
  EXPECT_ROTATION(dumpedRotation(d, "UpperArm.L"), glm::dquat(1, 0, 0, 0));
}

TEST_F(PanelsE2e, SaveAsAsksBeforeReplacingAFile) {
  writeFile(dir_ + "/taken.kinema", "keep me");
  Script s;
  s.select("UpperArm.L").euler(2, 40.0).saveAs(dir_ + "/taken.kinema");
  run(s, "replace_question");  // "Replace file?" is showing
  EXPECT_EQ(readFile(dir_ + "/taken.kinema"), "keep me");
  s.key("ESCAPE").wait(3).key("ESCAPE").wait(3);  // no, then close the dialog
  const nlohmann::json d = runAndDump(s, "replace_declined");
  EXPECT_EQ(readFile(dir_ + "/taken.kinema"), "keep me");
  EXPECT_EQ(d["dirty"], true);
}

TEST_F(PanelsE2e, ExportGlbAndBvhThroughTheFileMenuCarryThePose) {
  // No clips on the default character: the working pose goes out as a one-key clip.
  const std::pair<std::string, std::string> formats[] = {{"GLB (.glb)...", "/posed.glb"}, {"BVH (.bvh)...", "/posed.bvh"}};
  for (const auto& [item, name] : formats) {
    Script s;
    s.select("UpperArm.L").euler(2, 40.0);
    exportThroughTheMenu(s, item).type(dir_ + name).key("ENTER").wait(4);
    const nlohmann::json d = runAndDump(s, "export_" + name.substr(name.size() - 3));
    EXPECT_EQ(d["dirty"], true) << "exporting is not saving";
    const Result<Scene> exported = loadScene(dir_ + name);
    ASSERT_TRUE(exported.ok()) << exported.error();
    ASSERT_FALSE(exported->clips.empty()) << name;
    Pose pose = Pose::rest(exported->skeleton);
    sampleClip(exported->clips[0], 0.0f, pose);
    const int arm = exported->skeleton.find("UpperArm.L");
    ASSERT_GE(arm, 0) << name;
    EXPECT_ROTATION(glm::dquat(pose.local[arm].rotation), rotZ(40.0));
    EXPECT_ROTATION(glm::dquat(pose.local[exported->skeleton.find("UpperArm.R")].rotation), glm::dquat(1, 0, 0, 0));
  }
}

TEST_F(PanelsE2e, QuitClosesAtOnceWhenCleanAndAsksWhenDirty) {
  // Events run to frame ~1000 (the last a mouse move over the outliner); a quit that goes
  // through ends the run long before.
  Script clean;
  clean.chord("Q", {"ctrl"}).wait(1000).moveItem("Outliner");
  EXPECT_LT(runAndDump(clean, "quit_clean")["frames"].get<long long>(), 100);
  Script dirty;
  dirty.select("UpperArm.L").euler(2, 40.0).chord("Q", {"ctrl"}).wait(3).key("ESCAPE").wait(101).moveItem("Outliner");
  const nlohmann::json d = runAndDump(dirty, "quit_dirty");
  EXPECT_GT(d["frames"].get<long long>(), 100);
  EXPECT_EQ(d["dirty"], true);
}

TEST_F(PanelsE2e, OpenRecentReopensTheLastFile) {
  KINEMA_REQUIRE_SHARED_DATA();
  const std::string bvh = sharedDataDir() + "/bvh/games105_walk60.bvh";
  Script open;
  open.chord("O", {"ctrl"}).wait(2).type(bvh).key("ENTER").wait(4).chord("N", {"ctrl"}).wait(3);
  EXPECT_EQ(runAndDump(open, "recent_first")["path"], "");  // New after Open: the list keeps the file
  // File > Open Recent > its first entry (named by the path the recent list holds).
  const nlohmann::json list = e2e::readJson(dir_ + "/config/kinema/recent.json");
  ASSERT_TRUE(list.contains("recent") && !list["recent"].empty()) << list;
  const std::string entry = "File/Open Recent/" + list["recent"][0].get<std::string>();
  Script recent;
  recent.clickItem("File").wait(2).moveItem("File/Open Recent").wait(3).moveItem(entry).wait(2);
  recent.clickItem(entry).wait(3);
  const nlohmann::json d = runAndDump(recent, "recent_reopen");
  EXPECT_EQ(std::filesystem::path(d["path"].get<std::string>()).lexically_normal(),
            std::filesystem::path(bvh).lexically_normal());
}

TEST_F(PanelsE2e, KillDashNineThenRestartOffersTheRecoveryFile) {
  // Run 1 edits, autosaves every 0.2 s and is killed with SIGKILL while it waits.
  Script edit;
  edit.select("UpperArm.L").euler(2, 40.0).wait(100000).moveItem("Outliner");
  const std::string pidFile = dir_ + "/pid", doneFile = dir_ + "/done";
  runCommand("(" + e2e::xvfb() + "sh -c \"KINEMA_AUTOSAVE_SECONDS=0.2 " + command(edit, "recovery_crash", "") +
             " & echo \\$! > " + pidFile + "; wait; touch " + doneFile + "\" > " + dir_ + "/crash.log 2>&1 &)");
  // Wait for an autosave that holds the edit (an earlier one may predate it: frames are slow
  // under llvmpipe on a busy machine, and the interval counts replayed 1/60 s frames).
  const std::string recoveryDir = dir_ + "/state/kinema/recovery";
  bool autosaved = false;
  for (int i = 0; i < 1200 && !autosaved; ++i) {
    std::this_thread::sleep_for(std::chrono::milliseconds(100));
    std::string listing;
    if (runCommand("ls '" + recoveryDir + "'/recovery-*.kinema 2>/dev/null", &listing) != 0 || listing.empty()) continue;
    const Result<Scene> autosave = loadKinemaFile(listing.substr(0, listing.find('\n')));
    const int arm = autosave ? autosave->skeleton.find("UpperArm.L") : -1;
    autosaved = arm >= 0 && arm < autosave->pose.size() &&
                std::abs(glm::dot(glm::dquat(autosave->pose.local[arm].rotation), rotZ(40.0))) > 1.0 - 1e-6 &&
                runCommand("test -s '" + pidFile + "'") == 0;
  }
  ASSERT_TRUE(autosaved) << "no autosave with the edit appeared in " << recoveryDir << ": " << readFile(dir_ + "/crash.log");
  const long pid = std::stol(readFile(pidFile));
  ASSERT_GT(pid, 1);
  ASSERT_EQ(::kill(static_cast<pid_t>(pid), SIGKILL), 0);
  for (int i = 0; i < 300 && runCommand("test -e '" + doneFile + "'") != 0; ++i)
    std::this_thread::sleep_for(std::chrono::milliseconds(100));

  // Run 2 finds the file and shows "Recover unsaved work from <time>?" (screenshot);
  // Enter recovers, then the recovered pose is saved.
  Script offer;
  offer.wait(5);
  run(offer, "recovery_offer");
  Script accept;
  accept.wait(3).key("ENTER").wait(4).saveAs(dir_ + "/recovered.kinema");
  run(accept, "recovery_accept");
  const Scene r = saved(dir_ + "/recovered.kinema");
  EXPECT_ROTATION(rotation(r, "UpperArm.L"), rotZ(40.0));
}

}  // namespace
}  // namespace kinema::test

namespace kinema::test {
namespace KINEMA_UNITY_ID {

// Issue 9: a clip authored in the editor (UpperArm.L keyed at Rz(40) on frame 1 and Rz(-20)
// on frame 24 with I, the Right key stepping between) goes out through File > Export as
// GLB and BVH; read back, frame 12 (0.5 s) is the eased blend of the two keys (Bezier with
// auto-clamped handles, the default: flat end handles, so the quaternion components move
// by s = 3u^2 - 2u^3 at u = 11/23, then normalised), about Z by
// 2 atan2((1 - s) sin 20 + s sin -10, (1 - s) cos 20 + s cos -10) degrees. The status bar
// shows the export and its report.
TEST_F(PanelsE2e, TheAuthoredClipExportsThroughTheFileMenu) {
  const std::pair<std::string, std::string> formats[] = {{"GLB (.glb)...", "/authored.glb"},
                                                        {"BVH (.bvh)...", "/authored.bvh"}};
  for (const auto& [item, name] : formats) {
    Script s;
    s.select("UpperArm.L").euler(2, 40.0).select("UpperArm.L").key("I").wait(1);
    for (int i = 0; i < 23; ++i) s.key("RIGHT").wait(1);
    s.select("UpperArm.L").euler(2, -20.0).select("UpperArm.L").key("I").wait(1);
    exportThroughTheMenu(s, item).type(dir_ + name).key("ENTER").wait(4);
    const nlohmann::json d = runAndDump(s, "export_authored_" + name.substr(name.size() - 3));
    EXPECT_EQ(d["timeline"]["frame"], 24);
    EXPECT_NE(d["status"].get<std::string>().find("Exported"), std::string::npos) << d["status"];
    const Result<Scene> exported = loadScene(dir_ + name);
    ASSERT_TRUE(exported.ok()) << exported.error();
    ASSERT_FALSE(exported->clips.empty()) << name;
    const int arm = exported->skeleton.find("UpperArm.L");
    ASSERT_GE(arm, 0) << name;
    const double u = 11.0 / 23, sm = 3 * u * u - 2 * u * u * u, h0 = glm::radians(20.0), h1 = glm::radians(-10.0);
    const double eased = glm::degrees(2 * std::atan2((1 - sm) * std::sin(h0) + sm * std::sin(h1),
                                                     (1 - sm) * std::cos(h0) + sm * std::cos(h1)));
    for (const auto& [time, degrees] : {std::pair<float, double>{1.0f / 24, 40.0}, {0.5f, eased}, {1.0f, -20.0}}) {
      Pose pose = Pose::rest(exported->skeleton);
      sampleClip(exported->clips[0], time, pose);
      EXPECT_ROTATION(glm::dquat(pose.local[arm].rotation), rotZ(degrees));
    }
  }
}

}  // namespace
}  // namespace kinema::test
