// The View menu's commands: the numpad views, orthographic, framing, what the 3D view
// draws (bones, weights, limits, grid), the animation editors, onion skin, motion path and
// motion control. Display settings, none of them an undo step.
#include <algorithm>

#include "editor/commands/command_sets.h"
#include "editor/commands/file_commands.h"
#include "editor/model/key_codes.h"
#include "editor/viewport/viewport_controller.h"

namespace kinema {

namespace {

float aspect(const CommandContext& c) { return c.view.size.x / std::max(c.view.size.y, 1.0f); }

Command viewPreset(const char* id, const char* label, int key, int mods, ViewPreset preset, bool separatorBefore = false) {
  return CommandDef(id, label).menu("View", separatorBefore).key(key, mods).scope(CommandScope::Viewport)
      .enabled(documentShown)
      .run([preset](CommandContext& c) { applyViewPreset(c.state.camera, preset); });
}

// A display switch: a toggle in the View menu, optionally on a key in the 3D view.
Command viewToggle(const char* id, const char* label, bool separatorBefore, bool EditorState::*member) {
  return CommandDef(id, label).menu("View", separatorBefore).enabled(documentShown)
      .checked([member](const CommandContext& c) { return c.state.*member; })
      .run([member](CommandContext& c) { c.state.*member = !(c.state.*member); });
}

void toggleAnimationEditor(EditorState& s, AnimationEditorKind kind) {
  s.animationEditor = s.animationEditor == kind ? AnimationEditorKind::None : kind;
}

}  // namespace

void addViewCommands(std::vector<Command>& out) {
  out.push_back(viewPreset("view.front", "Front", keys::KP_1, 0, ViewPreset::Front));
  out.push_back(viewPreset("view.back", "Back", keys::KP_1, kModCtrl, ViewPreset::Back));
  out.push_back(viewPreset("view.right", "Right", keys::KP_3, 0, ViewPreset::Right));
  out.push_back(viewPreset("view.left", "Left", keys::KP_3, kModCtrl, ViewPreset::Left));
  out.push_back(viewPreset("view.top", "Top", keys::KP_7, 0, ViewPreset::Top));
  out.push_back(viewPreset("view.bottom", "Bottom", keys::KP_7, kModCtrl, ViewPreset::Bottom));
  out.push_back(CommandDef("view.orthographic", "Orthographic").menu("View", true).key(keys::KP_5)
                    .scope(CommandScope::Viewport).hint("perspective / orthographic").enabled(documentShown)
                    .checked([](const CommandContext& c) { return c.state.camera.orthographic; })
                    .run([](CommandContext& c) { toggleOrthographic(c.state.camera); }));
  out.push_back(CommandDef("view.frame_selected", "Frame Selected").menu("View", true).key(keys::F)
                    .scope(CommandScope::Viewport).hint("the selected joints fill the view (all joints when none)")
                    .enabled(documentShown)
                    .run([](CommandContext& c) {
                      const std::vector<glm::mat4>& world = c.state.world();
                      frameSelected(c.state.camera, world, c.state.doc.selection.joints(), aspect(c),
                                    0.1f * std::max(jointBounds(world).radius(), 1e-3f));
                    }));
  out.push_back(CommandDef("view.frame_all", "Frame All").menu("View").key(keys::HOME).scope(CommandScope::Viewport)
                    .enabled(documentShown)
                    .run([](CommandContext& c) {
                      ViewportController().frameAll(c.state.camera, jointBounds(c.state.world()), aspect(c));
                    }));
  out.push_back(CommandDef("view.bones_none", "Bones: None").menu("View", true).hint("the body alone")
                    .enabled(documentShown)
                    .checked([](const CommandContext& c) { return !c.state.view.showBones; })
                    .run([](CommandContext& c) { c.state.view.showBones = false; }));
  out.push_back(CommandDef("view.bones_solid", "Bones: Solid").menu("View").enabled(documentShown)
                    .checked([](const CommandContext& c) { return c.state.view.showBones && !c.state.view.xrayBones; })
                    .run([](CommandContext& c) { c.state.view.showBones = true, c.state.view.xrayBones = false; }));
  out.push_back(CommandDef("view.bones_xray", "Bones: X-Ray").menu("View").hint("bones drawn over the body")
                    .enabled(documentShown)
                    .checked([](const CommandContext& c) { return c.state.view.showBones && c.state.view.xrayBones; })
                    .run([](CommandContext& c) { c.state.view.showBones = true, c.state.view.xrayBones = true; }));
  // Alt+Z, Blender's x-ray toggle, cycles the three.
  out.push_back(CommandDef("view.cycle_bones", "Cycle Bones").key(keys::Z, kModAlt).scope(CommandScope::Viewport)
                    .hint("bones solid -> x-ray -> none -> solid").enabled(documentShown)
                    .run([](CommandContext& c) {
                      ViewOptions& v = c.state.view;
                      if (!v.showBones) v.showBones = true, v.xrayBones = false;
                      else if (!v.xrayBones) v.xrayBones = true;
                      else v.showBones = false;
                    }));
  out.push_back(CommandDef("view.weights", "Weights of the Active Joint").menu("View").key(keys::W, kModAlt)
                    .scope(CommandScope::Viewport).hint("the active joint's skin weights as heat colours")
                    .enabled(documentShown)
                    .checked([](const CommandContext& c) { return c.state.view.showWeights; })
                    .run([](CommandContext& c) { c.state.view.showWeights = !c.state.view.showWeights; }));
  out.push_back(CommandDef("view.limits", "Show Limits").menu("View").hint("joint-limit cones of the selection")
                    .enabled(documentShown)
                    .checked([](const CommandContext& c) { return c.state.view.showLimits; })
                    .run([](CommandContext& c) { c.state.view.showLimits = !c.state.view.showLimits; }));
  out.push_back(CommandDef("view.grid", "Show Grid").menu("View").enabled(documentShown)
                    .checked([](const CommandContext& c) { return c.state.view.showGrid; })
                    .run([](CommandContext& c) { c.state.view.showGrid = !c.state.view.showGrid; }));
  // Blender's order: Dope Sheet, then Graph Editor. Both in the area under the 3D view.
  out.push_back(CommandDef("view.dope_sheet", "Dope Sheet").menu("View", true).hint("the clip's keys under the 3D view")
                    .enabled(documentShown)
                    .checked([](const CommandContext& c) { return c.state.animationEditor == AnimationEditorKind::DopeSheet; })
                    .run([](CommandContext& c) { toggleAnimationEditor(c.state, AnimationEditorKind::DopeSheet); }));
  out.push_back(CommandDef("view.curve_editor", "Curve Editor").menu("View").key(keys::F6, kModShift)
                    .hint("the selected joints' curves under the 3D view").enabled(documentShown)
                    .checked([](const CommandContext& c) { return c.state.animationEditor == AnimationEditorKind::CurveEditor; })
                    .run([](CommandContext& c) { toggleAnimationEditor(c.state, AnimationEditorKind::CurveEditor); }));
  out.push_back(CommandDef("view.onion_skin", "Onion Skin").menu("View").key(keys::O, kModAlt).scope(CommandScope::Viewport)
                    .hint("ghost poses before and after the current frame").enabled(documentShown)
                    .checked([](const CommandContext& c) { return c.state.onionSkin.enabled; })
                    .run([](CommandContext& c) { c.state.onionSkin.enabled = !c.state.onionSkin.enabled; }));
  out.push_back(CommandDef("view.motion_path", "Motion Path").menu("View").key(keys::P, kModAlt).scope(CommandScope::Viewport)
                    .hint("the active joint's path through the clip").enabled(documentShown)
                    .checked([](const CommandContext& c) { return c.state.motionPath.enabled; })
                    .run([](CommandContext& c) { c.state.motionPath.enabled = !c.state.motionPath.enabled; }));
  out.push_back(viewToggle("view.onion_skin_settings", "Onion Skin & Motion Path...", false, &EditorState::onionSkinWindowOpen));
  out.push_back(CommandDef("view.motion_control", "Motion Control...").menu("View").key(keys::M, kModAlt)
                    .scope(CommandScope::Viewport).hint("the active joint's speed along its path").enabled(documentShown)
                    .checked([](const CommandContext& c) { return c.state.motionControl.windowOpen; })
                    .run([](CommandContext& c) { c.state.motionControl.windowOpen = !c.state.motionControl.windowOpen; }));
  out.push_back(CommandDef("view.presentation", "Presentation Mode").menu("View", true)
                    .hint("text twice as large and thicker 3D lines, for a projector (saved in the preferences)")
                    .checked([](const CommandContext& c) { return isPresentation(c.state.preferences); })
                    .run([](CommandContext& c) {
                      const UserPreferences& p = c.state.preferences;
                      c.state.preferences = isPresentation(p) ? deskPreset(p) : presentationPreset(p);
                      saveEditorPreferences(c.state);
                    }));
  out.push_back(CommandDef("view.log", "Log...").menu("View")
                    .hint("every message of the session in full, with its time")
                    .checked([](const CommandContext& c) { return c.state.logWindowOpen; })
                    .run([](CommandContext& c) { c.state.logWindowOpen = !c.state.logWindowOpen; }));
}

}  // namespace kinema
