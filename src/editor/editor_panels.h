#pragma once
#include <string>

#include "editor/editor_state.h"
#include "editor/file_dialog.h"

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
void drawSessionDialogs(EditorState& state);  // file dialog, discard / recover modals, errors, help

// Older panels kept for the joint list view and playback.
void drawJointListPanel(EditorState& state);
void drawTimelinePanel(EditorState& state);
void drawCurveEditorPanel(EditorState& state);  // curve editor in the animation editor area (Shift+F6)
void drawViewportHelp(const EditorState& state, float fps);

// File actions, shared by the menu and its shortcuts (drawMainMenuBar handles Ctrl+N, O,
// S, Shift+S, Q, Z, Shift+Z, Y, C, V, Shift+V itself). Anything that would drop unsaved
// changes asks first. The window's close button calls requestQuit() and closes once
// state.panels.quitApproved is set.
void requestNewDocument(EditorState& state);
void requestOpenDialog(EditorState& state);
void requestOpenPath(EditorState& state, const std::string& path);
void requestSave(EditorState& state);
void requestSaveAs(EditorState& state);
void requestExport(EditorState& state, FileDialogPurpose format);
void requestQuit(EditorState& state);
// Shows a one-line error in the error popup (and the status bar).
void showEditorError(EditorState& state, const std::string& message);

// Called by drawEditorPanels each frame: on the first call, loads the recent files and
// looks for a crashed session's recovery file (offered in a modal); afterwards writes the
// autosave every KINEMA_AUTOSAVE_SECONDS (default 60) while the document is dirty.
void tickEditorSession(EditorState& state, double nowSeconds);
// Autosave interval in seconds: KINEMA_AUTOSAVE_SECONDS when it is a positive number, else 60.
double autosaveIntervalSeconds();

// The document's file name ("untitled" for a new one), for titles and questions.
std::string documentTitle(const EditorState& state);

// The steps behind the session dialogs' buttons.
void runPendingFileAction(EditorState& state);  // after "discard changes?" said yes (or nothing to lose)
void finishFileDialog(EditorState& state, const std::string& path);  // open / save as / export to `path`
void acceptRecovery(EditorState& state);
void declineRecovery(EditorState& state);

}  // namespace kinema
