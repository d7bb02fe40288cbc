// End-to-end tests of the one playhead (issue 17): the real `kinema edit FILE` under
// xvfb-run. A .kinema file saved at frame 10 opens at frame 10 with that frame's pose on
// screen; a glTF file opens on its clip's first frame, posed (checked against `kinema pose
// --time 0`, the CLI's own evaluation); pausing playback is no edit.
#include <cmath>

#include "editor/e2e_harness.h"
#include "editor/model/document_files.h"
#include "editor/model/editor_state.h"
#include "editor/model/pose_edits.h"
#include "editor/model/timeline.h"

namespace kinema::test {
namespace KINEMA_UNITY_ID {

using namespace e2e;

class PlayheadE2e : public FrontViewSuite<PlayheadE2e> {
 public:
  static constexpr const char* kShotFolder = "playhead_e2e";
};

// The default character with UpperArm.L keyed (linear) at frames 1 and 20, saved with the
// playhead on frame 10; the arm's rotation there is slerp(qA, qB, 9/19).
const glm::quat kQa = glm::angleAxis(0.4f, glm::vec3(0, 0, 1)), kQb = glm::angleAxis(1.3f, glm::vec3(1, 0, 0));
std::string savedAtFrameTen(const std::string& dir) {
  EditorState s;
  s.doc = newDocument();
  resetTimeline(s);
  s.doc.autoKey.preferences.interpolation = Interpolation::Linear;
  const int arm = s.doc.skeleton().find("UpperArm.L");
  s.doc.selection.click(arm);
  goToFrame(s, 1);
  EXPECT_EQ(setJointRotation(s.doc, arm, kQa), "");
  keySelectedJoints(s);
  goToFrame(s, 20);
  EXPECT_EQ(setJointRotation(s.doc, arm, kQb), "");
  keySelectedJoints(s);
  goToFrame(s, 10);
  const std::string path = dir + "/frame10.kinema";
  EXPECT_EQ(saveDocumentAs(s.doc, path), "");
  return path;
}

// Regression: the timeline opened on frame 1 while the pose saved on frame 10 was shown.
TEST_F(PlayheadE2e, AFileSavedOnFrameTenOpensOnFrameTenWithItsPose) {
  const std::string file = savedAtFrameTen(dir_);
  const json d = run(Script().wait(2), "frame10", file);
  ASSERT_TRUE(d.is_object());
  EXPECT_EQ(d["timeline"]["frame"], 10);
  EXPECT_FALSE(bool(d["playback"]["playing"]));
  expectRotation(rotationIn(d, "UpperArm.L"), glm::dquat(glm::slerp(kQa, kQb, 9.0f / 19.0f)), 1e-5, "UpperArm.L on frame 10");
  EXPECT_FALSE(bool(d["dirty"]));
  EXPECT_EQ(d["undo_depth"], 0);
}

// Regression: a glTF file opened in the rest pose at frame 0 until the user scrubbed. Its
// joints must be where `kinema pose FILE --time 0` puts them (the CLI samples and runs FK
// without the editor).
TEST_F(PlayheadE2e, AGltfFileOpensOnItsFirstFramePosedAsTheCliEvaluatesIt) {
  KINEMA_REQUIRE_SHARED_DATA();
  const std::string fox = sharedDataDir() + "/gltf/Fox.glb";
  const json d = run(Script().wait(2), "fox_open", fox);
  ASSERT_TRUE(d.is_object());
  EXPECT_EQ(d["timeline"]["frame"], 0);
  EXPECT_EQ(d["timeline"]["fps"], 24.0);  // no frame grid in the file: Blender's 24
  std::string out, err;
  ASSERT_EQ(runCommand(std::string(KINEMA_BINARY) + " pose '" + fox + "' --time 0 --json", &out, &err), 0) << err;
  const json pose = json::parse(out);
  int compared = 0;
  for (const json& j : pose["joints"]) {
    const json& w = j["world"];
    const glm::dvec3 cli(w[12], w[13], w[14]);
    for (const json& e : d["joints"])
      if (e["name"] == j["name"]) {
        expectNear(vec3(e["world_position"]), cli, 1e-3, j["name"].get<std::string>());
        ++compared;
      }
  }
  EXPECT_GT(compared, 10);
}

// Space plays and Space pauses (in the 3D view), then the timeline's Play / Pause button
// does the same: the document stays clean with nothing to undo, the playhead on a frame.
TEST_F(PlayheadE2e, PausingRecordsNoUndoStepAndLeavesTheFileClean) {
  KINEMA_REQUIRE_SHARED_DATA();
  const std::string cesium = sharedDataDir() + "/gltf/CesiumMan.glb";
  const json& v = front_["viewport"];
  const glm::dvec2 centre{double(v["x"]) + double(v["width"]) / 2, double(v["y"]) + double(v["height"]) / 2};
  // Play is the timeline's third button (after |< and <), on its top row (1280x720: the
  // timeline is the 40 px above the 24 px status bar).
  const glm::dvec2 play{312, 720 - 24 - 40 + 9};
  Script s;
  s.move(centre).key("SPACE").wait(20).key("SPACE").wait(3);
  s.click(play).wait(20).click(play).wait(3);
  const json d = run(s, "pause_clean", cesium);
  ASSERT_TRUE(d.is_object());
  EXPECT_FALSE(bool(d["playback"]["playing"]));
  EXPECT_GT(int(d["timeline"]["frame"]), 0);  // it played
  EXPECT_FALSE(bool(d["dirty"]));
  EXPECT_EQ(d["undo_depth"], 0);
  EXPECT_EQ(d["title"], "Kinema - CesiumMan.glb");  // no unsaved-changes marker
  const double t = d["playback"]["time"];
  EXPECT_NEAR(t * 24.0, std::round(t * 24.0), 1e-3) << "paused on a whole frame";
}

}  // namespace
}  // namespace kinema::test
