#pragma once
#include <string>

#include "editor/model/editor_state.h"
#include "editor/model/file_dialog_state.h"

namespace kinema {

// File actions behind the file.* commands (the File menu and its keys; command_sets.h).
// Anything that would drop unsaved changes asks first. The window's close button calls requestQuit() and closes once
// state.panels.quitApproved is set.
void requestNewDocument(EditorState& state);
void requestOpenDialog(EditorState& state);
void requestOpenPath(EditorState& state, const std::string& path);
void requestSave(EditorState& state);
void requestSaveAs(EditorState& state);
void requestExport(EditorState& state, FileDialogPurpose format);
// File > Import Motion onto Character…: the file dialog for a motion file; once one is chosen
// its bone map shows in the "Import Motion" modal (or the error popup says why not).
void requestImportMotion(EditorState& state);
// Reads `path` for the modal (motion_import.h prepareMotionImport); an error goes to the popup.
void startMotionImport(EditorState& state, const std::string& path);
// The modal's Apply: the retargeted clip becomes a new active clip (one undo step) and the
// modal closes; on failure nothing changes and the reason stays in the modal (and the popup).
void applyMotionImportInEditor(EditorState& state);
// Animation > Edit Bone Map of Clip…: the Import Motion dialog on the map clip `clip` keeps
// (prepareMotionImportOfClip); Apply replaces the clip.
void reopenMotionImport(EditorState& state, int clip);
// Animation > Clean Up Motion…: the window open, Add Foot Contact's range from the playhead.
void openCleanUpWindow(EditorState& state);
void cancelMotionImport(EditorState& state);
void requestQuit(EditorState& state);
// A freshly loaded document (opened, new, recovered, or the file `kinema edit` was given)
// replaces the old one: tools, hover and panel state that pointed into the old skeleton
// are reset, the timeline stands where the file saved it or on the clip's start frame and
// the document is posed from the clip there before anything is drawn (resetTimeline), and
// the view frames the new skeleton from the current direction.
void openDocumentInEditor(EditorState& state, Document doc);
// Shows a one-line error in the error popup (and the status bar).
void showEditorError(EditorState& state, const std::string& message);
// Writes currentPreferences(state) to the user's preferences file; a failure is shown.
void saveEditorPreferences(EditorState& state);

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
