#pragma once
#include "editor/editor_state.h"

namespace kinema {

// Immediate-mode ImGui panels over EditorState. Each draws one window and edits the state
// it is given; the editor issue adds more panels beside these.
void drawJointListPanel(EditorState& state);
void drawTimelinePanel(EditorState& state);
void drawViewportHelp(const EditorState& state, float fps);

}  // namespace kinema
