// The History panel follows the current step (issue 39, item 10): after 60 rotations and 50
// undos the current row (step 10) is inside the panel, not scrolled away below it as before.
#include "editor/e2e_harness.h"

namespace kinema::test {
namespace KINEMA_UNITY_ID {

using namespace e2e;

class HistoryPanelE2e : public TempDirSuite<HistoryPanelE2e> {
 public:
  static constexpr const char* kShotFolder = "history_panel_e2e";
};

TEST_F(HistoryPanelE2e, TheCurrentStepStaysInViewAfterFiftyUndos) {
  Script s;
  s.wait(2).clickItem("Outliner/Hand.L").wait(2);
  // R over the 3D view (below the figure), 1 degree typed, Enter: one step each.
  for (int i = 0; i < 60; ++i) s.move({600.0, 560.0}).wait(1).key("R").wait(1).key("1").key("ENTER").wait(1);
  for (int i = 0; i < 50; ++i) s.chord("Z", {"ctrl"}).wait(1);
  s.wait(3);
  const json d = runEditor(dir_, shotDir(), s, "fifty_undos");
  ASSERT_TRUE(d.is_object());
  ASSERT_EQ(d["undo_depth"], 10) << "60 rotations, 50 undone";
  ASSERT_EQ(d["redo_depth"], 50);
  const Rect panel = itemRect(d, "History"), row = itemRect(d, "History/10");
  EXPECT_GE(row.y, panel.y) << "the current step above the panel";
  EXPECT_LE(row.bottom(), panel.bottom()) << "the current step below the panel";
}

}  // namespace
}  // namespace kinema::test
