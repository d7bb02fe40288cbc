// End-to-end test of File > Import Motion onto Character… (issue 21) in the real `kinema edit`
// under xvfb-run: on the default character the script opens the menu item, types the CMU
// take's path into the file dialog, applies the bone map in the "Import Motion" modal,
// undoes and redoes the import, and saves; a second run opens the saved file and plays the
// imported clip.
#include "editor/e2e_harness.h"

namespace kinema::test {
namespace KINEMA_UNITY_ID {

using namespace e2e;

class MotionImportE2e : public TempDirSuite<MotionImportE2e> {
 public:
  static constexpr const char* kShotFolder = "motion_import_e2e";
};

TEST_F(MotionImportE2e, CmuTakeImportedThroughTheMenuUndoesRedoesSavesAndReopens) {
  KINEMA_REQUIRE_SHARED_DATA();
  const std::string take = sharedDataDir() + "/bvh/cmu_01_01_first720.bvh";
  const std::string saved = dir_ + "/imported.kinema";

  // How many clips the default character starts with.
  Script none(Script::Start::AsOpened);
  none.wait(2);
  const json start = runEditor(dir_, shotDir(), none, "start");
  ASSERT_TRUE(start.is_object());
  const size_t before = start["clips"].size();

  Script s(Script::Start::AsOpened);
  s.wait(2);
  s.menu("File", "Import Motion onto Character...");
  s.type(take).key("ENTER").wait(4);  // the file dialog's path field, then the bone-map modal
  s.clickItem("Import Motion/Apply").wait(3);
  s.chord("Z", {"ctrl"}).wait(2);           // the import undone
  s.chord("Z", {"ctrl", "shift"}).wait(2);  // and redone
  s.saveAs(saved);
  const json d = runEditor(dir_, shotDir(), s, "imported");
  ASSERT_TRUE(d.is_object());
  ASSERT_TRUE(d["items"].contains("Import Motion/Apply")) << "the modal was drawn";
  ASSERT_EQ(d["clips"].size(), before + 1) << d["clips"].dump();
  const std::string name = d["clips"].back();
  EXPECT_EQ(name, "motion") << "named after the source clip (the BVH reader names its clip \"motion\")";
  EXPECT_EQ(d["timeline"]["clip_name"], name) << "made the active clip";
  EXPECT_EQ(d["playback"]["clip"], static_cast<int>(before));
  EXPECT_EQ(d["undo_depth"], 1) << "one undo step";
  EXPECT_EQ(d["redo_depth"], 0);
  EXPECT_FALSE(bool(d["dirty"])) << "saved";

  // Reopened: the clip is in the file, active, and plays (the hips move).
  Script r(Script::Start::AsOpened);
  r.wait(2);
  r.clickItem("Timeline/Play").wait(20);
  r.clickItem("Timeline/Play").wait(3);
  const json o = runEditor(dir_, shotDir(), r, "reopened", saved);
  ASSERT_TRUE(o.is_object());
  EXPECT_EQ(o["clips"], d["clips"]);
  EXPECT_EQ(o["timeline"]["clip_name"], name);
  EXPECT_GT(double(o["playback"]["time"]), 0.1) << "it played";
}

}  // namespace
}  // namespace kinema::test
