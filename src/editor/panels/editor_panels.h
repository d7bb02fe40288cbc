#pragma once
#include <string>

#include "editor/commands/file_commands.h"
#include "editor/model/editor_state.h"
#include "editor/panels/file_dialog.h"

namespace kinema {

// Immediate-mode ImGui panels over EditorState. Each draws one window and edits the state
// it is given. The window calls drawEditorPanels() once per frame between ImGui::NewFrame()
// and ImGui::Render(); it draws everything below in a fixed layout.
void drawEditorPanels(EditorState& state, float fps);

void drawMainMenuBar(EditorState& state);     // File / Edit / View / Pose / Help
void drawOutlinerPanel(EditorState& state);   // joint tree, search, select, rename
void drawPropertiesPanel(EditorState& state); // active joint: rotation, location, limits
void drawIkTargetsPanel(EditorState& state);  // IK targets and their settings
void drawHistoryPanel(EditorState& state);    // undo stack, click to jump
void drawStatusBar(EditorState& state, float fps);
void drawSessionDialogs(EditorState& state);
void drawAnimationDisplayWindows(EditorState& state);  // onion skin & motion path settings, motion control  // file dialog, discard / recover modals, errors, help

// Older panels kept for the joint list view and playback.
void drawJointListPanel(EditorState& state);
void drawTimelinePanel(EditorState& state);
void drawCurveEditorPanel(EditorState& state);  // curve editor in the animation editor area (Shift+F6)
void drawViewportHelp(const EditorState& state, float fps);

}  // namespace kinema
