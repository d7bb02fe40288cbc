// The Pose menu's commands and the 3D view's posing keys: IK targets (always the active
// joint's, model/active_ik_target.h), binding meshes, keyframes at the playhead, auto-key,
// select all / none, and the R / G modal tools.
#include <algorithm>

#include "editor/commands/command_sets.h"
#include "editor/commands/file_commands.h"
#include "editor/model/active_ik_target.h"
#include "editor/model/key_codes.h"
#include "editor/model/pose_edits.h"
#include "editor/model/shape_keys.h"
#include "editor/model/timeline.h"
#include "editor/viewport/viewport_tools.h"

namespace kinema {

namespace {

bool hasActiveJoint(const CommandContext& c) { return documentShown(c) && c.state.doc.selection.active() >= 0; }
bool hasActiveIkTarget(const CommandContext& c) { return documentShown(c) && activeIkTarget(c.state.doc) >= 0; }
bool idleTool(const CommandContext& c) {
  return documentShown(c) && c.tools && c.state.tool.mode == ModalTool::None && !c.state.doc.dragging();
}

bool hasUnskinnedMesh(const CommandContext& c) {
  if (!documentShown(c)) return false;
  for (const MeshInstance& m : c.state.doc.scene().meshInstances)
    if (m.skin < 0) return true;
  return false;
}

void addIkTargetToActiveJoint(EditorState& state) {
  Document& doc = state.doc;
  const int joint = doc.selection.active();
  if (joint < 0) return showEditorError(state, "Add IK Target: select the effector joint first");
  // One target per effector, so the active joint names its target (active_ik_target.h).
  if (activeIkTarget(doc) >= 0)
    return showEditorError(state, "Add IK Target: " + doc.skeleton().names[joint] +
                                      " has one already (Pose > Remove IK Target first)");
  const int length = std::max(1, state.panels.ikChainLength);
  // Two bones get the closed-form solver.
  const IkSolver solver = length == 2 ? IkSolver::TwoBone : IkSolver::JacobianDls;
  if (const std::string error = addIkTargetAtEffector(doc, joint, length, solver); !error.empty())
    return showEditorError(state, error);
  state.statusMessage = "Added an IK target on " + doc.skeleton().names[joint];
}

}  // namespace

void addPoseCommands(std::vector<Command>& out) {
  out.push_back(CommandDef("pose.add_ik_target", "Add IK Target to Selected").menu("Pose").key(keys::I, kModShift)
                    .scope(CommandScope::Viewport)
                    .hint("an IK target on the active joint, the chain length of the IK panel (Blender's Add IK)")
                    .enabled(hasActiveJoint)
                    .run([](CommandContext& c) { addIkTargetToActiveJoint(c.state); }));
  out.push_back(CommandDef("pose.remove_ik_target", "Remove IK Target").menu("Pose").hint("the active joint's IK target")
                    .enabled(hasActiveIkTarget)
                    .run([](CommandContext& c) {
                      showEditorError(c.state, removeIkTarget(c.state.doc, activeIkTarget(c.state.doc)));
                    }));
  out.push_back(CommandDef("pose.pin_ik_target", "Pin IK Target").menu("Pose")
                    .hint("the active joint's IK target holds its effector while other things move")
                    .enabled(hasActiveIkTarget)
                    .checked([](const CommandContext& c) {
                      const int t = activeIkTarget(c.state.doc);
                      return t >= 0 && c.state.doc.ikTargets()[t].pinned;
                    })
                    .run([](CommandContext& c) {
                      const int t = activeIkTarget(c.state.doc);
                      PoseIkTarget settings = c.state.doc.ikTargets()[t];
                      settings.pinned = !settings.pinned;
                      showEditorError(c.state, setIkTarget(c.state.doc, t, settings));
                    }));
  // The Pose menu's chain-length slider sits here (drawn by the menu: a setting, not an action).
  out.push_back(CommandDef("pose.bind_automatic_weights", "Bind to Skeleton with Automatic Weights").menu("Pose")
                    .key(keys::P, kModCtrl).scope(CommandScope::Viewport)
                    .hint("bind the unskinned meshes (Blender's Ctrl+P, With Automatic Weights)")
                    .enabled(hasUnskinnedMesh)
                    .run([](CommandContext& c) {
                      const std::string error = bindUnskinnedMeshes(c.state.doc);
                      if (!error.empty()) showEditorError(c.state, error);
                      else c.state.statusMessage = "Bound to the skeleton with automatic weights";
                    }));
  // Keying (timeline.h): at the playhead, with the timeline's key preferences.
  out.push_back(CommandDef("anim.insert_keyframe", "Insert Keyframe").menu("Pose", true).key(keys::I)
                    .scope(CommandScope::Viewport).hint("key the selected joints at the current frame")
                    .enabled(hasJointSelection)
                    .run([](CommandContext& c) { c.state.statusMessage = keySelectedJoints(c.state); }));
  out.push_back(CommandDef("anim.insert_shape_keys", "Insert Shape Keys").menu("Pose")
                    .hint("key every morph target's weight (the shape sliders) at the current frame")
                    .enabled([](const CommandContext& c) {
                      for (int i = 0; i < static_cast<int>(c.state.doc.scene().meshInstances.size()); ++i)
                        if (shapeCount(c.state.doc, i) > 0) return true;
                      return false;
                    })
                    .run([](CommandContext& c) { c.state.statusMessage = keyAllShapes(c.state); }));
  out.push_back(CommandDef("anim.insert_keys_all", "Insert Keys on All Joints").menu("Pose").enabled(documentShown)
                    .run([](CommandContext& c) { c.state.statusMessage = keyAllJoints(c.state); }));
  out.push_back(CommandDef("anim.delete_keyframe", "Delete Keyframe").menu("Pose").key(keys::I, kModAlt)
                    .scope(CommandScope::Viewport).hint("the selected joints' keys at the current frame")
                    .enabled(hasJointSelection)
                    .run([](CommandContext& c) { c.state.statusMessage = deleteSelectedJointKeys(c.state); }));
  out.push_back(CommandDef("anim.auto_key", "Auto-key").menu("Pose").hint("every posing edit also keys (same undo step)")
                    .enabled(documentShown)
                    .checked([](const CommandContext& c) { return c.state.doc.autoKey.enabled; })
                    .run([](CommandContext& c) { c.state.doc.autoKey.enabled = !c.state.doc.autoKey.enabled; }));
  // Selection and the modal tools: keys of the 3D view, no menu.
  out.push_back(CommandDef("select.all", "Select All").key(keys::A).scope(CommandScope::Viewport).enabled(documentShown)
                    .run([](CommandContext& c) { c.state.doc.selection.selectAll(c.state.doc.skeleton().size()); }));
  out.push_back(CommandDef("select.none", "Select None").key(keys::A, kModAlt).scope(CommandScope::Viewport)
                    .enabled(documentShown)
                    .run([](CommandContext& c) { c.state.doc.selection.clear(); }));
  out.push_back(CommandDef("select.box", "Box Select").key(keys::B).scope(CommandScope::Viewport)
                    .hint("the next drag selects the joints in a box, even from over a bone")
                    .enabled([](const CommandContext& c) { return idleTool(c); })
                    .run([](CommandContext& c) { c.tools->armBoxSelect(c.state); }));
  out.push_back(CommandDef("tool.rotate", "Rotate").key(keys::R).scope(CommandScope::Viewport)
                    .hint("rotate the selection with the mouse (then X/Y/Z, typed degrees)")
                    .enabled([](const CommandContext& c) {
                      return idleTool(c) && !c.state.doc.selection.empty() && !c.state.lattice.active;
                    })
                    .run([](CommandContext& c) { c.tools->startRotate(c.state, c.view); }));
  out.push_back(CommandDef("tool.grab", "Move Root").key(keys::G).scope(CommandScope::Viewport)
                    .hint("move the root joint with the mouse (then X/Y/Z)")
                    .enabled([](const CommandContext& c) { return idleTool(c) && c.state.doc.skeleton().size() > 0; })
                    .run([](CommandContext& c) { c.tools->startGrab(c.state); }));
}

}  // namespace kinema
