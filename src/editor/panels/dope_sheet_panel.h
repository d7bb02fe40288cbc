#pragma once
#include "editor/model/editor_state.h"

namespace kinema {

// The dope sheet in the animation editor area (EditorState::layout.animationEditor, model/editor_layout.h) while
// state.animationEditor is DopeSheet: joint names, the frame ruler, the keys as diamonds and
// the current frame. Mouse and keys act on it while the mouse is over it (README controls).
void drawDopeSheetPanel(EditorState& state);

}  // namespace kinema
