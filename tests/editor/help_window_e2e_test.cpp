// Help > Controls closes with Esc (issue 39, 10): F1 opens the window, which takes the
// keyboard; Esc then closes it, as a Blender pop-up closes. Before, only its close button did.
#include "editor/e2e_harness.h"

namespace kinema::test {
namespace KINEMA_UNITY_ID {

using namespace e2e;

class HelpWindowE2e : public TempDirSuite<HelpWindowE2e> {
 public:
  static constexpr const char* kShotFolder = "help_window_e2e";
};

TEST_F(HelpWindowE2e, F1OpensControlsAndEscClosesThem) {
  Script open;
  open.wait(2).key("F1").wait(3);
  const json shown = runEditor(dir_, shotDir(), open, "controls_open");
  ASSERT_TRUE(shown.is_object());
  EXPECT_EQ(shown["help_window"], true);
  Script closed = open;
  closed.key("ESCAPE").wait(3);
  const json d = runEditor(dir_, shotDir(), closed, "controls_closed");
  ASSERT_TRUE(d.is_object());
  EXPECT_EQ(d["help_window"], false);
  EXPECT_EQ(d["popup_open"], false);
}

}  // namespace
}  // namespace kinema::test
