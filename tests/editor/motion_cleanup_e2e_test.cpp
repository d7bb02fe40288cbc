// End-to-end test of the foot contacts on the timeline and Animation > Clean Up Motion…
// (issue 21) in the real `kinema edit` under Xvfb: the CMU take imported onto the default
// character shows its detected contacts on the strip over the timeline; a drag moves a left
// contact's end, a click selects a right contact and the Clean Up window's button deletes it;
// Clean Up (foot locking and key reduction) runs as one step, is undone and redone; the file
// is saved and reopened with its bone map, its edited contacts and the cleaned clip.
#include "editor/e2e_harness.h"

#include "editor/model/document_files.h"
#include "editor/model/motion_import.h"

namespace kinema::test {
namespace KINEMA_UNITY_ID {

using namespace e2e;

class MotionCleanupE2e : public TempDirSuite<MotionCleanupE2e> {
 public:
  static constexpr const char* kShotFolder = "motion_cleanup_e2e";
};

json intervals(const std::vector<ContactInterval>& list) {
  json a = json::array();
  for (const ContactInterval& c : list) a.push_back(json::array({c.first, c.last}));
  return a;
}

TEST_F(MotionCleanupE2e, ContactsEditedOnTheTimelineCleanUpUndoRedoSaveReopen) {
  KINEMA_REQUIRE_SHARED_DATA();
  const std::string take = sharedDataDir() + "/bvh/cmu_01_01_first720.bvh";
  const std::string saved = dir_ + "/cleaned.kinema";

  // The contacts the import detects, computed here through the model (no window).
  Document expected = newDocument();
  Result<MotionImport> prepared = prepareMotionImport(expected, take);
  ASSERT_TRUE(prepared) << prepared.error();
  ASSERT_EQ(applyMotionImport(expected, prepared.value()), "");
  const FootContacts detected = expected.scene().clips[expected.activeClip()].contacts;
  ASSERT_GE(detected.feet[0].size(), 2u) << "the walk plants the left foot more than once";
  ASSERT_GE(detected.feet[1].size(), 1u);

  Script s(Script::Start::AsOpened);
  s.wait(2);
  s.menu("File", "Import Motion onto Character...");
  s.type(take).key("ENTER").wait(4);
  s.clickItem("Import Motion/Apply").wait(3);
  // Drag left contact 1's end (its right edge) to the bar's middle.
  s.moveItem("Contacts/left/1", {0.995, 0.5}).wait(1).down().wait(1);
  s.moveItem("Contacts/left/1", {0.5, 0.5}).wait(1).up().wait(2);
  // Select right contact 0 on the strip, delete it with the Clean Up window's button.
  s.clickItem("Contacts/right/0").wait(2);
  s.menu("Animation", "Clean Up Motion...");
  s.clickItem("Clean Up Motion/Delete Foot Contact").wait(2);
  s.clickItem("Clean Up Motion/Apply Clean Up").wait(3);
  s.chord("Z", {"ctrl"}).wait(2);           // the clean-up undone
  s.chord("Z", {"ctrl", "shift"}).wait(2);  // and redone
  s.saveAs(saved);
  const json d = runEditor(dir_, shotDir(), s, "cleaned");
  ASSERT_TRUE(d.is_object());
  const json& t = d["timeline"];
  const json& c = t["contacts"];
  ASSERT_TRUE(bool(c["shown"])) << "the strip shows the imported clip's contacts";
  EXPECT_EQ(c["bone_map_file"], take);
  EXPECT_EQ(c["bone_map_pairs"], prepared->map.pairs.size());

  // Left contact 1 keeps its start; its end moved to about its middle (a frame either way
  // for the pixel the mouse landed on).
  std::vector<ContactInterval> left = detected.feet[0];
  ASSERT_EQ(c["left"].size(), left.size());
  const ContactInterval was = left[1];
  EXPECT_EQ(c["left"][1][0], was.first);
  const int middle = (was.first + was.last) / 2;
  EXPECT_NEAR(c["left"][1][1].get<int>(), middle, 1) << c["left"].dump();
  left[1].last = c["left"][1][1].get<int>();
  EXPECT_EQ(c["left"], intervals(left));
  // Right contact 0 deleted.
  std::vector<ContactInterval> right(detected.feet[1].begin() + 1, detected.feet[1].end());
  EXPECT_EQ(c["right"], intervals(right));

  // Clean Up ran (and came back with redo): fewer keys, less skate, the key count the clip has.
  ASSERT_TRUE(t.contains("clean_up")) << "the figure's numbers";
  const json& cu = t["clean_up"];
  EXPECT_LT(cu["keys_after"].get<int>(), cu["keys_before"].get<int>());
  EXPECT_LT(cu["skate_after"].get<double>(), cu["skate_before"].get<double>());
  EXPECT_LE(cu["max_position_error"].get<double>(), 0.01 + 1e-6);
  EXPECT_EQ(t["key_count"], cu["keys_after"]);
  EXPECT_TRUE(d["items"].contains("Clean Up Motion/Figure/keys")) << "the before/after figure was drawn";
  EXPECT_EQ(d["undo_depth"], 4) << "import, end drag, delete, clean up; the click that selected adds none";
  EXPECT_EQ(d["redo_depth"], 0);
  EXPECT_FALSE(bool(d["dirty"])) << "saved";

  // Reopened: the map, the edited contacts and the cleaned clip are in the file.
  Script r(Script::Start::AsOpened);
  r.wait(3);
  const json o = runEditor(dir_, shotDir(), r, "reopened", saved);
  ASSERT_TRUE(o.is_object());
  const json& oc = o["timeline"]["contacts"];
  EXPECT_EQ(o["clips"], d["clips"]);
  EXPECT_EQ(o["timeline"]["clip_name"], t["clip_name"]);
  EXPECT_EQ(oc["left"], c["left"]);
  EXPECT_EQ(oc["right"], c["right"]);
  EXPECT_EQ(oc["bone_map_pairs"], c["bone_map_pairs"]);
  EXPECT_EQ(oc["bone_map_file"], take);
  EXPECT_EQ(o["timeline"]["key_count"], t["key_count"]);
  EXPECT_TRUE(bool(oc["shown"]));
}

}  // namespace
}  // namespace kinema::test
