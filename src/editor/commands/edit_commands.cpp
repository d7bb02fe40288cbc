// The Edit menu's commands: undo / redo, the pose clipboard, clearing and resetting the
// pose, X-mirror and auto-IK. Each edit is one undo step of the document.
#include "editor/commands/command_sets.h"
#include "editor/commands/file_commands.h"
#include "editor/model/key_codes.h"
#include "editor/model/pose_edits.h"
#include "editor/model/timeline.h"

namespace kinema {

namespace {

// Undo and redo wait for a drag to end (the drag is one step once committed).
bool hasClipboard(const CommandContext& c) { return documentShown(c) && !c.state.panels.clipboard.empty(); }

void copySelection(EditorState& state) {
  const std::vector<int>& joints = state.doc.selection.joints();
  state.panels.clipboard = copyPose(state.doc, joints);
  state.statusMessage = "Copied the pose of " + std::to_string(joints.size()) + " joint(s)";
}

}  // namespace

void addEditCommands(std::vector<Command>& out) {
  out.push_back(CommandDef("edit.undo", "Undo").menu("Edit").key(keys::Z, kModCtrl)
                    .enabled([](const CommandContext& c) { return documentIdle(c) && c.state.doc.canUndo(); })
                    .run([](CommandContext& c) {
                      const bool showedClip = c.state.doc.poseRevision() == c.state.animatedPoseRevision;
                      if (!c.state.doc.undo()) return;
                      c.state.statusMessage = "Undo";
                      followDocumentClip(c.state);  // an undone clip list change: its active clip again
                      // The pose showed the clip (not an unkeyed pose of the user's): show the clip as it is now.
                      if (showedClip && !c.state.playing) poseAtPlayhead(c.state);
                    }));
  out.push_back(CommandDef("edit.redo", "Redo").menu("Edit").key(keys::Z, kModCtrl | kModShift).key(keys::Y, kModCtrl)
                    .enabled([](const CommandContext& c) { return documentIdle(c) && c.state.doc.canRedo(); })
                    .run([](CommandContext& c) {
                      const bool showedClip = c.state.doc.poseRevision() == c.state.animatedPoseRevision;
                      if (!c.state.doc.redo()) return;
                      c.state.statusMessage = "Redo";
                      followDocumentClip(c.state);
                      if (showedClip && !c.state.playing) poseAtPlayhead(c.state);
                    }));
  out.push_back(CommandDef("edit.copy_pose", "Copy Pose").menu("Edit", true).key(keys::C, kModCtrl)
                    .hint("copy the selected joints' pose").enabled(hasJointSelection)
                    .run([](CommandContext& c) { copySelection(c.state); }));
  out.push_back(CommandDef("edit.paste_pose", "Paste Pose").menu("Edit").key(keys::V, kModCtrl).enabled(hasClipboard)
                    .run([](CommandContext& c) {
                      showEditorError(c.state, pastePose(c.state.doc, c.state.panels.clipboard, false));
                    }));
  out.push_back(CommandDef("edit.paste_flipped", "Paste Flipped").menu("Edit").key(keys::V, kModCtrl | kModShift)
                    .hint("paste mirrored across X (left onto right)").enabled(hasClipboard)
                    .run([](CommandContext& c) {
                      showEditorError(c.state, pastePose(c.state.doc, c.state.panels.clipboard, true));
                    }));
  out.push_back(CommandDef("edit.clear_rotation", "Clear Rotation").menu("Edit", true).key(keys::R, kModAlt)
                    .scope(CommandScope::Viewport).hint("the selected joints back to their rest rotation")
                    .enabled(hasJointSelection)
                    .run([](CommandContext& c) {
                      showEditorError(c.state, clearRotations(c.state.doc, c.state.doc.selection.joints()));
                    }));
  out.push_back(CommandDef("edit.reset_pose", "Reset to Rest Pose").menu("Edit").enabled(documentShown)
                    .run([](CommandContext& c) { showEditorError(c.state, resetToRestPose(c.state.doc)); }));
  out.push_back(CommandDef("edit.x_mirror", "X-Mirror").menu("Edit", true)
                    .hint("edits also pose the mirror partner (Hand.L <-> Hand.R)").enabled(documentShown)
                    .checked([](const CommandContext& c) { return c.state.doc.xMirror; })
                    .run([](CommandContext& c) { c.state.doc.xMirror = !c.state.doc.xMirror; }));
  out.push_back(CommandDef("edit.auto_ik", "Auto IK").menu("Edit").key(keys::I, kModCtrl).scope(CommandScope::Viewport)
                    .hint("dragging a joint moves it by IK up the chain").enabled(documentShown)
                    .checked([](const CommandContext& c) { return c.state.view.autoIk; })
                    .run([](CommandContext& c) { c.state.view.autoIk = !c.state.view.autoIk; }));
  // Blender's Edit > Preferences (Ctrl+Comma): UI scale, theme, 3D line scale, loop, new keys.
  out.push_back(CommandDef("edit.preferences", "Preferences...").menu("Edit", true).key(keys::COMMA, kModCtrl)
                    .hint("UI scale, theme, presentation preset, loop, new keys")
                    .checked([](const CommandContext& c) { return c.state.preferencesWindowOpen; })
                    .run([](CommandContext& c) { c.state.preferencesWindowOpen = !c.state.preferencesWindowOpen; }));
}

}  // namespace kinema
