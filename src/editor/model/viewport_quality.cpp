#include "editor/model/viewport_quality.h"

#include "editor/model/editor_state.h"

namespace kinema {

ViewportQuality viewportQuality(const EditorState& state, bool sceneChanged, bool stillPicture) {
  if (stillPicture) return ViewportQuality::Still;
  const bool moving = state.playing || state.tool.mode != ModalTool::None || sceneChanged;
  return moving ? ViewportQuality::Moving : ViewportQuality::Still;
}

int viewportSamples(ViewportQuality quality) {
  return quality == ViewportQuality::Moving ? kMovingViewportSamples : kStillViewportSamples;
}

}  // namespace kinema
