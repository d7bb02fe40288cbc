// End-to-end test of the clip list (issue 18) in the real `kinema edit` under xvfb-run: on
// Fox.glb (Survey, Walk, Run) the script duplicates, renames, deletes, undoes and redoes
// through the clip list and the keys, then chooses Run by a click on its row and plays it.
// The dump must list the clips in order with Run playing, and the fox's joints must be
// where `kinema pose Fox.glb --clip 2 --time T` (the CLI's own sampling and FK) puts them at
// the dumped time T.
#include "editor/e2e_harness.h"

namespace kinema::test {
namespace KINEMA_UNITY_ID {

using namespace e2e;

class ClipListE2e : public TempDirSuite<ClipListE2e> {
 public:
  static constexpr const char* kShotFolder = "clip_list_e2e";
};

TEST_F(ClipListE2e, FoxsRunChosenInTheClipListPlaysAndListEditsUndo) {
  KINEMA_REQUIRE_SHARED_DATA();
  const std::string fox = sharedDataDir() + "/gltf/Fox.glb";
  Script s(Script::Start::AsOpened);
  s.wait(2);
  s.command("clip.duplicate").wait(2);  // Survey.001, right after Survey, active
  s.doubleClickItem("Clips/Survey.001").wait(2);
  s.type("Idle").key("ENTER").wait(2);  // renamed in place
  s.clickItem("Clips/Delete Clip").wait(2);  // Idle gone, Walk active
  s.chord("Z", {"ctrl"}).wait(2);  // Idle back, active
  s.chord("Z", {"ctrl"}).wait(2);  // Survey.001 again
  s.chord("Z", {"ctrl", "shift"}).wait(2);  // Idle again; the delete stays redoable
  s.clickItem("Clips/Run").wait(2);  // chosen: an undo step, the redo tail dropped
  s.clickItem("Timeline/Play").wait(24);
  s.clickItem("Timeline/Play").wait(3);  // pause: on a whole frame, posed from Run there
  const json d = runEditor(dir_, shotDir(), s, "fox_run", fox);
  ASSERT_TRUE(d.is_object());

  EXPECT_EQ(d["clips"], json({"Survey", "Idle", "Walk", "Run"}));
  EXPECT_EQ(d["playback"]["clip"], 3);
  EXPECT_EQ(d["timeline"]["clip_name"], "Run");
  EXPECT_FALSE(bool(d["playback"]["playing"]));
  EXPECT_EQ(d["undo_depth"], 3);  // duplicate, rename, choose
  EXPECT_EQ(d["redo_depth"], 0);
  EXPECT_TRUE(bool(d["dirty"]));
  const double t = d["playback"]["time"];
  EXPECT_GT(t, 0.1) << "it played";

  // Run is clip 2 of the file: the CLI samples it at the dumped time.
  std::string out, err;
  char time[32];
  std::snprintf(time, sizeof time, "%.17g", t);
  ASSERT_EQ(runCommand(std::string(KINEMA_BINARY) + " pose '" + fox + "' --clip 2 --time " + time + " --json", &out, &err), 0)
      << err;
  const json pose = json::parse(out);
  int compared = 0;
  double farthestFromSurvey = 0.0;
  ASSERT_EQ(runCommand(std::string(KINEMA_BINARY) + " pose '" + fox + "' --clip 0 --time " + time + " --json", &out, &err), 0)
      << err;
  const json survey = json::parse(out);
  for (size_t i = 0; i < pose["joints"].size(); ++i) {
    const json& j = pose["joints"][i];
    const glm::dvec3 cli(j["world"][12], j["world"][13], j["world"][14]);
    const json& o = survey["joints"][i]["world"];
    farthestFromSurvey = std::max(farthestFromSurvey, glm::length(cli - glm::dvec3(o[12], o[13], o[14])));
    for (const json& e : d["joints"])
      if (e["name"] == j["name"]) {
        expectNear(vec3(e["world_position"]), cli, 1e-3, j["name"].get<std::string>());
        ++compared;
      }
  }
  EXPECT_GT(compared, 10);
  EXPECT_GT(farthestFromSurvey, 1.0) << "Run and Survey differ there, so the comparison tells them apart";
}

}  // namespace
}  // namespace kinema::test
