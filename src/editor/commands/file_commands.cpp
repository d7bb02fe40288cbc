// New / Open / Save / Save As / Export / Quit as the menu and its shortcuts run them, the
// "discard unsaved changes?" guard, recent files, and the autosave + recovery session.
#include <cstdio>
#include <cstdlib>
#include <filesystem>

#include "editor/model/timeline.h"
#include "editor/commands/command_sets.h"
#include "editor/commands/file_commands.h"
#include "editor/model/key_codes.h"
#include "editor/model/motion_import.h"
#include "editor/viewport/viewport_controller.h"

namespace kinema {

namespace {

void rememberRecent(EditorState& state, const std::string& path) {
  std::error_code ec;
  const std::string absolute = std::filesystem::absolute(path, ec).lexically_normal().string();
  state.panels.recent.add(ec ? path : absolute);
  // A recent list that cannot be written is not worth an error popup on every save.
  state.panels.recent.save();
}

void openNow(EditorState& state, const std::string& path, UpAxis bvhUp = UpAxis::Y) {
  Result<Document> opened = openDocument(path, state.inputLimits, bvhUp);
  if (!opened) {
    showEditorError(state, opened.error());
    std::error_code ec;
    if (!std::filesystem::exists(path, ec)) {  // a recent file that went away leaves the list
      state.panels.recent.remove(path);
      state.panels.recent.save();
    }
    return;
  }
  openDocumentInEditor(state, std::move(opened.value()));
  rememberRecent(state, path);
  state.statusMessage = "Opened " + path;
}

// Runs `action` now when nothing unsaved would be lost, else asks first.
void guarded(EditorState& state, PendingFileAction action, const std::string& path = "") {
  PanelState& p = state.panels;
  p.pending = action;
  p.pendingPath = path;
  if (state.doc.needsConfirmationToDiscard()) {
    p.askDiscard = true;
    return;
  }
  runPendingFileAction(state);
}

}  // namespace

void openDocumentInEditor(EditorState& state, Document doc) {
  const KeyPreferences newKeys = state.doc.autoKey.preferences;  // the user's (Edit > Preferences), not the file's
  state.doc = std::move(doc);
  state.doc.autoKey.preferences = newKeys;
  state.tool = ToolState{};  // a running tool refers to the old skeleton
  state.hoveredJoint = -1;
  state.hoveredIkTarget = -1;
  state.clip = 0;
  state.time = 0.0;
  state.playing = false;
  state.sampleClip = false;
  state.sampledAt = {};
  state.contactSelection = {};
  state.contactDrag = FootContactDrag{};  // its drag belonged to the old document
  state.lastCleanUp.reset();
  resetTimeline(state);  // the file's playhead (or the clip's start), posed from the clip there
  // The new file framed from the current direction, as Home does.
  const float aspect = state.viewportRect.w > 0 ? state.viewportRect.z / state.viewportRect.w : 1.0f;
  ViewportController().frameAll(state.camera, jointBounds(state.world()), aspect);
  PanelState& p = state.panels;
  p.collapsed.clear();
  p.renaming = -1;
  p.renameError.clear();
}

void runPendingFileAction(EditorState& state) {
  PanelState& p = state.panels;
  const PendingFileAction action = p.pending;
  p.pending = PendingFileAction::None;
  switch (action) {
    case PendingFileAction::None: break;
    case PendingFileAction::New:
      openDocumentInEditor(state, newDocument());
      state.statusMessage = "New document";
      break;
    case PendingFileAction::Open:
      openFileDialog(p.fileDialog, FileDialogPurpose::Open, state.doc.path());
      break;
    case PendingFileAction::OpenPath: openNow(state, p.pendingPath); break;
    case PendingFileAction::Quit:
      // A clean exit (or changes the user chose to discard) leaves no recovery file behind.
      if (p.autosaver) p.autosaver->removeFiles();
      p.quitApproved = true;
      break;
  }
}

std::string documentTitle(const EditorState& state) {
  const std::string& path = state.doc.path();
  if (path.empty()) return "untitled";
  return std::filesystem::path(path).filename().string();
}

void showEditorError(EditorState& state, const std::string& message) {
  if (message.empty()) return;
  state.panels.errors.push_back(message);
  state.statusMessage = message;
  state.log.note(message, MessageLog::clockTime(), true);
}

void saveEditorPreferences(EditorState& state) {
  const std::string failed = saveUserPreferences(currentPreferences(state));
  if (!failed.empty()) showEditorError(state, "preferences: " + failed);
}

void requestNewDocument(EditorState& state) { guarded(state, PendingFileAction::New); }
void requestOpenDialog(EditorState& state) { guarded(state, PendingFileAction::Open); }
void requestOpenPath(EditorState& state, const std::string& path) { guarded(state, PendingFileAction::OpenPath, path); }
void requestQuit(EditorState& state) { guarded(state, PendingFileAction::Quit); }

void requestSave(EditorState& state) {
  if (!canSaveInPlace(state.doc)) {
    requestSaveAs(state);
    return;
  }
  if (const std::string error = saveDocument(state.doc); !error.empty()) {
    showEditorError(state, error);
    return;
  }
  rememberRecent(state, state.doc.path());
  state.statusMessage = "Saved " + state.doc.path();
}

void requestSaveAs(EditorState& state) {
  openFileDialog(state.panels.fileDialog, FileDialogPurpose::SaveAs, state.doc.path());
}

void requestExport(EditorState& state, FileDialogPurpose format) {
  openFileDialog(state.panels.fileDialog, format, state.doc.path());
}

void requestImportMotion(EditorState& state) {
  FileDialogState& d = state.panels.fileDialog;
  openFileDialog(d, FileDialogPurpose::ImportMotion, state.doc.path());
  setFileDialogField(d, "");  // the document's own name is no motion file to offer
}

// Opens the Import Motion dialog on a prepared import, or shows why it could not be prepared.
static bool openMotionImportDialog(EditorState& state, Result<MotionImport> prepared) {
  if (!prepared) {
    showEditorError(state, prepared.error());
    return false;
  }
  PanelState& p = state.panels;
  p.motionImport = std::move(prepared.value());
  p.motionImportJustOpened = true;
  p.motionImportError.clear();
  return true;
}

void startMotionImport(EditorState& state, const std::string& path) {
  if (openMotionImportDialog(state, prepareMotionImport(state.doc, path, state.inputLimits, state.panels.fileDialog.bvhUp)))
    state.statusMessage = "Import motion from " + path + " (bone map by " + state.panels.motionImport->mapBy + ")";
}

void reopenMotionImport(EditorState& state, int clip) {
  if (openMotionImportDialog(state,
                             prepareMotionImportOfClip(state.doc, clip, state.inputLimits, state.panels.fileDialog.bvhUp)))
    state.statusMessage =
        "Bone map of " + state.doc.scene().clips[clip].name + " (from " + state.panels.motionImport->path + ")";
}

void applyMotionImportInEditor(EditorState& state) {
  PanelState& p = state.panels;
  if (!p.motionImport) return;
  const std::string error = applyMotionImport(state.doc, *p.motionImport);
  if (!error.empty()) {
    p.motionImportError = error;
    showEditorError(state, error);
    return;
  }
  const std::string from = p.motionImport->path;
  p.motionImport.reset();
  p.motionImportError.clear();
  followDocumentClip(state);
  const int active = state.doc.activeClip();
  const std::vector<Clip>& clips = state.doc.scene().clips;
  state.statusMessage = "Imported motion " + (active >= 0 && active < static_cast<int>(clips.size()) ? clips[active].name : std::string()) +
                        " from " + from;
}

void cancelMotionImport(EditorState& state) {
  state.panels.motionImport.reset();
  state.panels.motionImportError.clear();
}

void finishFileDialog(EditorState& state, const std::string& path) {
  const FileDialogPurpose purpose = state.panels.fileDialog.purpose;
  if (purpose == FileDialogPurpose::ImportMotion) {
    startMotionImport(state, path);
    return;
  }
  if (purpose == FileDialogPurpose::Open) {
    openNow(state, path, state.panels.fileDialog.bvhUp);  // the discard question was asked before the dialog opened
    return;
  }
  if (purpose == FileDialogPurpose::SaveAs) {
    if (const std::string error = saveDocumentAs(state.doc, path); !error.empty()) {
      showEditorError(state, error);
      return;
    }
    rememberRecent(state, path);
    state.statusMessage = "Saved " + path;
    return;
  }
  std::vector<std::string> report;
  if (const std::string error = exportDocument(state.doc, path, &report); !error.empty()) {
    showEditorError(state, error);
    return;
  }
  state.statusMessage = "Exported " + path;
  for (const std::string& line : report) state.statusMessage += "; " + line;
  // The status line may be cut short: what the format lost also goes to stderr, in full.
  for (const std::string& line : report) std::fprintf(stderr, "kinema edit: %s: %s\n", path.c_str(), line.c_str());
}

double autosaveIntervalSeconds() {
  const char* text = std::getenv("KINEMA_AUTOSAVE_SECONDS");
  if (!text || !*text) return 60.0;
  char* end = nullptr;
  const double seconds = std::strtod(text, &end);
  return end && *end == '\0' && seconds > 0 && seconds < 1e7 ? seconds : 60.0;
}

void tickEditorSession(EditorState& state, double nowSeconds) {
  PanelState& p = state.panels;
  if (!p.recoveryChecked) {
    p.recoveryChecked = true;
    if (!p.recentLoaded) {
      p.recentLoaded = true;
      p.recent.load();  // a corrupt list is ignored; it is only a convenience
    }
    const std::string dir = defaultRecoveryDir();
    if (!dir.empty()) {
      p.autosaver.emplace(dir, autosaveIntervalSeconds());
      std::string message;
      p.recovery = findRecoverableSession(dir, &message);
      if (p.recovery) p.askRecovery = true;
      if (!message.empty()) state.statusMessage = message;
    }
  }
  // No autosave while the recovery question is open: the session's files are not ours yet.
  if (p.autosaver && !p.recovery && !p.quitApproved) {
    if (const std::string error = p.autosaver->tick(state.doc, nowSeconds); !error.empty())
      state.statusMessage = "autosave failed: " + error;
  }
}

void acceptRecovery(EditorState& state) {
  PanelState& p = state.panels;
  if (!p.recovery || !p.autosaver) return;
  Result<Document> recovered = recover(*p.recovery, *p.autosaver);
  const std::string when = p.recovery->recoveryPath;
  p.recovery.reset();
  if (!recovered) {
    showEditorError(state, recovered.error());
    return;
  }
  openDocumentInEditor(state, std::move(recovered.value()));
  state.statusMessage = "Recovered unsaved work from " + when;
}

void declineRecovery(EditorState& state) {
  PanelState& p = state.panels;
  if (!p.recovery) return;
  const std::string error = discardRecovery(*p.recovery);
  p.recovery.reset();
  showEditorError(state, error);
}

void addFileCommands(std::vector<Command>& out) {
  out.push_back(CommandDef("file.new", "New").menu("File").key(keys::N, kModCtrl).hint("a new document (asks before dropping changes)")
                    .run([](CommandContext& c) { requestNewDocument(c.state); }));
  out.push_back(CommandDef("file.open", "Open...").menu("File").key(keys::O, kModCtrl)
                    .run([](CommandContext& c) { requestOpenDialog(c.state); }));
  // File > Open Recent is drawn by the menu itself (one item per recent file).
  out.push_back(CommandDef("file.import_motion", "Import Motion onto Character...").menu("File", true)
                    .hint("a BVH, glTF or .kinema take retargeted onto this skeleton as a new clip")
                    .enabled([](const CommandContext& c) {
                      return documentShown(c) && !c.state.doc.dragging() && c.state.tool.mode == ModalTool::None &&
                             c.state.doc.skeleton().size() > 0;
                    })
                    .run([](CommandContext& c) { requestImportMotion(c.state); }));
  out.push_back(CommandDef("file.save", "Save").menu("File", true).key(keys::S, kModCtrl)
                    .hint("save the .kinema file (Save As for a new document)")
                    .run([](CommandContext& c) { requestSave(c.state); }));
  out.push_back(CommandDef("file.save_as", "Save As...").menu("File").key(keys::S, kModCtrl | kModShift)
                    .run([](CommandContext& c) { requestSaveAs(c.state); }));
  out.push_back(CommandDef("file.export_gltf", "glTF (.gltf)...").menu("File/Export").hint("export as glTF")
                    .run([](CommandContext& c) { requestExport(c.state, FileDialogPurpose::ExportGltf); }));
  out.push_back(CommandDef("file.export_glb", "GLB (.glb)...").menu("File/Export").hint("export as binary glTF")
                    .run([](CommandContext& c) { requestExport(c.state, FileDialogPurpose::ExportGlb); }));
  out.push_back(CommandDef("file.export_bvh", "BVH (.bvh)...").menu("File/Export").hint("export the timeline's clip as BVH")
                    .run([](CommandContext& c) { requestExport(c.state, FileDialogPurpose::ExportBvh); }));
  out.push_back(CommandDef("file.quit", "Quit").menu("File", true).key(keys::Q, kModCtrl)
                    .run([](CommandContext& c) { requestQuit(c.state); }));
}

}  // namespace kinema
