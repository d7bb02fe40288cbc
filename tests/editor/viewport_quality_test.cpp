// The 3D view's antialiasing rule (model/viewport_quality.h): one sample per pixel while
// the picture moves, full multisampling once it holds still, and always for a screenshot.
#include <gtest/gtest.h>

#include "editor/model/editor_state.h"
#include "editor/model/viewport_quality.h"

namespace kinema {
namespace KINEMA_UNITY_ID {

TEST(ViewportQuality, StillPictureIsMultisampledAndMovingOneIsNot) {
  EXPECT_GE(kStillViewportSamples, 4);
  EXPECT_EQ(kMovingViewportSamples, 1);
  EXPECT_EQ(viewportSamples(ViewportQuality::Still), kStillViewportSamples);
  EXPECT_EQ(viewportSamples(ViewportQuality::Moving), kMovingViewportSamples);
}

TEST(ViewportQuality, NothingMovingIsStill) {
  EditorState s;
  EXPECT_EQ(viewportQuality(s, false), ViewportQuality::Still);
}

TEST(ViewportQuality, EveryModalToolMovesThePictureEvenOnAFrameWithoutChange) {
  for (ModalTool tool : {ModalTool::Rotate, ModalTool::Grab, ModalTool::BoxSelect, ModalTool::IkDrag,
                         ModalTool::GizmoDrag, ModalTool::Navigate}) {
    EditorState s;
    s.tool.mode = tool;
    EXPECT_EQ(viewportQuality(s, false), ViewportQuality::Moving) << modalToolName(tool);
    s.tool.mode = ModalTool::None;  // the drag ended: the same picture again, at full quality
    EXPECT_EQ(viewportQuality(s, false), ViewportQuality::Still) << modalToolName(tool);
  }
}

TEST(ViewportQuality, PlaybackMovesThePictureUntilItStops) {
  EditorState s;
  s.playing = true;
  EXPECT_EQ(viewportQuality(s, false), ViewportQuality::Moving);
  s.playing = false;
  EXPECT_EQ(viewportQuality(s, false), ViewportQuality::Still);
}

TEST(ViewportQuality, AChangedViewMovesForOneFrame) {
  // A wheel zoom, a numpad view, a scrubbed playhead: the frame that shows the change is
  // drawn fast, the next one (nothing changed) at full quality.
  EditorState s;
  EXPECT_EQ(viewportQuality(s, true), ViewportQuality::Moving);
  EXPECT_EQ(viewportQuality(s, false), ViewportQuality::Still);
}

TEST(ViewportQuality, AScreenshotIsAlwaysTheStillPicture) {
  EditorState s;
  s.playing = true;
  s.tool.mode = ModalTool::IkDrag;
  EXPECT_EQ(viewportQuality(s, true, true), ViewportQuality::Still);
}

}  // namespace
}  // namespace kinema
