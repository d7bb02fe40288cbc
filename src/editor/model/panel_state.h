#pragma once
#include <optional>
#include <string>
#include <vector>

#include "core/rotation.h"
#include "editor/model/document_files.h"
#include "editor/model/file_dialog_state.h"
#include "editor/model/motion_import.h"
#include "editor/model/pose_clipboard.h"
#include "editor/model/recovery_file.h"

namespace kinema {

// What the panels remember between frames that is not part of the document: widget
// buffers, open dialogs, the clipboard, recent files, autosave and recovery.
enum class PendingFileAction { None, New, Open, OpenPath, Quit };

struct PanelState {
  // The history step the History panel last showed as the current one: when an undo, a redo
  // or a new step moves it, the panel scrolls that row into view.
  int historyShownPosition = -1;
  // Properties > Deformers: the lattice control point whose x, y, z the fields edit and key
  // (the flat index FfdLattice::index; clamped to the lattice shown).
  int latticePoint = 0;
  // Properties > Deformers > Pick centre: the soft pull (mesh instance, deformer) whose centre
  // the next left click on the body in the 3D view sets; -1: no pick pending.
  int softPullPickInstance = -1, softPullPickDeformer = -1;
  // Outliner
  char search[128] = {};
  std::vector<bool> collapsed;  // by joint
  int renaming = -1;            // the joint whose name is being edited inline
  bool renameFocus = false;
  char renameBuffer[256] = {};
  std::string renameError;

  // Properties
  int propertiesJoint = -1;  // the joint the properties panel showed last frame (-1: "Select a joint")
  EulerOrder eulerOrder = EulerOrder::XYZ;
  bool quaternionEntry = false;
  bool dragging = false;  // a property drag is one undo step: begun on activate, committed on release
  float heldEuler[3] = {};  // the Euler field's own numbers while it is held
  int heldJoint = -1;
  float typedQuaternion[4] = {};  // x y z w being typed, applied when the field is left
  bool quaternionEditing = false;  // typed but not applied yet
  int quaternionJoint = -1;
  char nameBuffer[256] = {};
  int nameJoint = -1;
  bool nameEditing = false;

  // Clip list (the outliner's Clips section): the clip whose name is edited inline.
  int renamingClip = -1;
  bool clipRenameFocus = false;
  char clipRenameBuffer[256] = {};
  std::string clipRenameError;
  // A menu, combo or other non-modal popup was open at the end of the last frame: the Esc
  // that closes it (closePopupsOnEscape) reaches no tool or command.
  bool popupOpen = false;

  // IK panel (the target it shows is the active joint's: active_ik_target.h)
  int ikChainLength = 2;  // for "Add IK Target" (pose.add_ik_target)

  // Files
  FileDialogState fileDialog;
  RecentFiles recent;
  bool recentLoaded = false;
  PoseClipboard clipboard;
  // An action waiting for "Discard unsaved changes?" to be answered.
  PendingFileAction pending = PendingFileAction::None;
  std::string pendingPath;
  bool askDiscard = false;  // OpenPopup on the next frame
  bool resumeAfterSaveAs = false;  // "Save first" needed Save As: the action waits for it
  // File > Import Motion onto Character…: the file read and its bone map, shown in the
  // "Import Motion" modal until Apply or Cancel (motion_import.h).
  std::optional<MotionImport> motionImport;
  bool motionImportJustOpened = false;  // OpenPopup on the next draw
  std::string motionImportError;        // why the last Apply changed nothing (shown in the modal)

  // Autosave and recovery
  std::optional<Autosaver> autosaver;
  bool recoveryChecked = false;
  std::optional<RecoverableSession> recovery;  // offered in a modal until answered
  bool askRecovery = false;

  // Errors: every failure lands here and shows in a popup (never only on stderr).
  std::vector<std::string> errors;
  bool showHelp = false;
  bool quitApproved = false;  // the window closes once this is set
  std::string lastAction;     // the last menu action, for the status bar
};

}  // namespace kinema
