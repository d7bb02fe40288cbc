// The main menu bar (Blender's header menus reduced to pose mode) and the Ctrl shortcuts of
// its File and Edit items. Viewport keys (numpad views, F, Home, Alt+R, R/G) belong to the
// window's input layer; the menu shows them and raises the same requests.
#include <imgui.h>

#include <algorithm>
#include "editor/model/key_codes.h"

#include "editor/panels/editor_panels.h"
#include "editor/panels/panel_layout.h"
#include "editor/model/pose_edits.h"
#include "editor/model/timeline.h"
#include "editor/viewport/viewport_controller.h"

namespace kinema {

namespace {

void undo(EditorState& state) {
  if (state.doc.dragging()) return;
  if (state.doc.undo()) state.statusMessage = "Undo";
}
void redo(EditorState& state) {
  if (state.doc.dragging()) return;
  if (state.doc.redo()) state.statusMessage = "Redo";
}

void copySelection(EditorState& state) {
  const std::vector<int>& joints = state.doc.selection.joints();
  if (joints.empty()) {
    showEditorError(state, "Copy Pose: select the joints to copy first");
    return;
  }
  state.panels.clipboard = copyPose(state.doc, joints);
  state.statusMessage = "Copied the pose of " + std::to_string(joints.size()) + " joint(s)";
}

void paste(EditorState& state, bool flipped) {
  if (state.panels.clipboard.empty()) {
    showEditorError(state, "Paste Pose: copy a pose first (Edit > Copy Pose)");
    return;
  }
  showEditorError(state, pastePose(state.doc, state.panels.clipboard, flipped));
}

void clearRotation(EditorState& state) {
  showEditorError(state, clearRotations(state.doc, state.doc.selection.joints()));
}

void addIkTargetToActive(EditorState& state) {
  const int joint = state.doc.selection.active();
  if (joint < 0) {
    showEditorError(state, "Add IK Target: select the effector joint first");
    return;
  }
  int index = -1;
  const IkSolver solver = state.panels.ikChainLength == 2 ? IkSolver::TwoBone : IkSolver::JacobianDls;
  if (const std::string error = addIkTargetAtEffector(state.doc, joint, state.panels.ikChainLength, solver, &index);
      !error.empty()) {
    showEditorError(state, error);
    return;
  }
  state.panels.selectedIkTarget = index;
}

// The IK target the Pose menu acts on: the one selected in the IK panel, else the first on
// the active joint.
int currentIkTarget(const EditorState& state) {
  const auto& targets = state.doc.ikTargets();
  const int chosen = state.panels.selectedIkTarget;
  if (chosen >= 0 && chosen < static_cast<int>(targets.size())) return chosen;
  for (size_t i = 0; i < targets.size(); ++i)
    if (targets[i].target.effector == state.doc.selection.active()) return static_cast<int>(i);
  return -1;
}

void removeCurrentIkTarget(EditorState& state) {
  const int t = currentIkTarget(state);
  if (t < 0) return;
  showEditorError(state, removeIkTarget(state.doc, t));
  state.panels.selectedIkTarget = -1;
}

void togglePin(EditorState& state) {
  const int t = currentIkTarget(state);
  if (t < 0) return;
  PoseIkTarget settings = state.doc.ikTargets()[t];
  settings.pinned = !settings.pinned;
  showEditorError(state, setIkTarget(state.doc, t, settings));
}

// Ctrl shortcuts of the File and Edit menus; not while a text field has the keyboard.
void handleMenuShortcuts(EditorState& state) {
  const ImGuiIO& io = ImGui::GetIO();
  if (!io.WantTextInput && ImGui::IsKeyPressed(keys::F1, false)) state.panels.showHelp = !state.panels.showHelp;
  if (io.WantTextInput || !io.KeyCtrl || io.KeyAlt || ImGui::IsPopupOpen("", ImGuiPopupFlags_AnyPopupId)) return;
  const auto pressed = [](int key) { return ImGui::IsKeyPressed(key, false); };
  const bool shift = io.KeyShift;
  // Over the dope sheet, Ctrl+C / Ctrl+V copy and paste keys (dope_sheet_panel.cpp).
  if (state.animationEditorContains(glm::vec2(io.MousePos.x, io.MousePos.y)) && (pressed(keys::C) || pressed(keys::V))) return;
  if (pressed(keys::N)) requestNewDocument(state);
  else if (pressed(keys::O)) requestOpenDialog(state);
  else if (pressed(keys::S)) shift ? requestSaveAs(state) : requestSave(state);
  else if (pressed(keys::Q)) requestQuit(state);
  else if (state.compare.active) return;  // the document is hidden: no undo or pose clipboard on it
  else if (pressed(keys::Z)) shift ? redo(state) : undo(state);
  else if (pressed(keys::Y)) redo(state);
  else if (pressed(keys::C)) copySelection(state);
  else if (pressed(keys::V)) paste(state, shift);
}

float viewAspect(const EditorState& state) {  // of the 3D view between the panels, which framing fills
  const PanelRect r = viewportRect(ImGui::GetIO().DisplaySize, state.bottomPanels());
  return r.w / r.h;
}

void viewItem(EditorState& state, const char* label, const char* shortcut, ViewPreset preset) {
  if (ImGui::MenuItem(label, shortcut)) applyViewPreset(state.camera, preset);
}

}  // namespace

void drawMainMenuBar(EditorState& state) {
  handleMenuShortcuts(state);
  if (!ImGui::BeginMainMenuBar()) return;
  Document& doc = state.doc;
  PanelState& p = state.panels;
  if (ImGui::BeginMenu("File")) {
    if (ImGui::MenuItem("New", "Ctrl+N")) requestNewDocument(state);
    if (ImGui::MenuItem("Open...", "Ctrl+O")) requestOpenDialog(state);
    if (ImGui::BeginMenu("Open Recent", !p.recent.entries().empty())) {
      for (const std::string& path : p.recent.entries())
        if (ImGui::MenuItem(path.c_str())) requestOpenPath(state, path);
      ImGui::EndMenu();
    }
    ImGui::Separator();
    if (ImGui::MenuItem("Save", "Ctrl+S")) requestSave(state);
    if (ImGui::MenuItem("Save As...", "Ctrl+Shift+S")) requestSaveAs(state);
    if (ImGui::BeginMenu("Export")) {
      if (ImGui::MenuItem("glTF (.gltf)...")) requestExport(state, FileDialogPurpose::ExportGltf);
      if (ImGui::MenuItem("GLB (.glb)...")) requestExport(state, FileDialogPurpose::ExportGlb);
      if (ImGui::MenuItem("BVH (.bvh)...")) requestExport(state, FileDialogPurpose::ExportBvh);
      ImGui::EndMenu();
    }
    ImGui::Separator();
    if (ImGui::MenuItem("Quit", "Ctrl+Q")) requestQuit(state);
    ImGui::EndMenu();
  }
  if (ImGui::BeginMenu("Edit")) {
    const bool idle = !doc.dragging();
    if (ImGui::MenuItem("Undo", "Ctrl+Z", false, idle && doc.canUndo())) undo(state);
    if (ImGui::MenuItem("Redo", "Ctrl+Shift+Z", false, idle && doc.canRedo())) redo(state);
    ImGui::Separator();
    const bool selected = !doc.selection.empty();
    if (ImGui::MenuItem("Copy Pose", "Ctrl+C", false, selected)) copySelection(state);
    if (ImGui::MenuItem("Paste Pose", "Ctrl+V", false, !p.clipboard.empty())) paste(state, false);
    if (ImGui::MenuItem("Paste Flipped", "Ctrl+Shift+V", false, !p.clipboard.empty())) paste(state, true);
    ImGui::Separator();
    if (ImGui::MenuItem("Clear Rotation", "Alt+R", false, selected)) clearRotation(state);
    if (ImGui::MenuItem("Reset to Rest Pose")) showEditorError(state, resetToRestPose(doc));
    ImGui::Separator();
    ImGui::MenuItem("X-Mirror", nullptr, &doc.xMirror);
    ImGui::MenuItem("Auto IK", "Ctrl+I", &state.view.autoIk);
    ImGui::EndMenu();
  }
  if (ImGui::BeginMenu("View")) {
    viewItem(state, "Front", "Numpad 1", ViewPreset::Front);
    viewItem(state, "Back", "Ctrl+Numpad 1", ViewPreset::Back);
    viewItem(state, "Right", "Numpad 3", ViewPreset::Right);
    viewItem(state, "Left", "Ctrl+Numpad 3", ViewPreset::Left);
    viewItem(state, "Top", "Numpad 7", ViewPreset::Top);
    viewItem(state, "Bottom", "Ctrl+Numpad 7", ViewPreset::Bottom);
    ImGui::Separator();
    if (ImGui::MenuItem("Orthographic", "Numpad 5", state.camera.orthographic)) toggleOrthographic(state.camera);
    ImGui::Separator();
    const std::vector<glm::mat4>& world = doc.worldTransforms();
    const float minRadius = 0.1f * std::max(jointBounds(world).radius(), 1e-3f);
    if (ImGui::MenuItem("Frame Selected", "F", false, !doc.selection.empty()))
      frameSelected(state.camera, world, doc.selection.joints(), viewAspect(state), minRadius);
    if (ImGui::MenuItem("Frame All", "Home")) ViewportController().frameAll(state.camera, jointBounds(world), viewAspect(state));
    ImGui::Separator();
    if (ImGui::MenuItem("Bones: None", "Alt+Z", !state.view.showBones)) state.view.showBones = false;
    if (ImGui::MenuItem("Bones: Solid", nullptr, state.view.showBones && !state.view.xrayBones))
      state.view.showBones = true, state.view.xrayBones = false;
    if (ImGui::MenuItem("Bones: X-Ray", nullptr, state.view.showBones && state.view.xrayBones))
      state.view.showBones = true, state.view.xrayBones = true;
    ImGui::MenuItem("Weights of the Active Joint", "Alt+W", &state.view.showWeights);
    ImGui::MenuItem("Show Limits", nullptr, &state.view.showLimits);
    ImGui::MenuItem("Show Grid", nullptr, &state.view.showGrid);
    ImGui::Separator();
    // Blender's order: Dope Sheet, then Graph Editor.
    const bool dopeSheet = state.animationEditor == AnimationEditorKind::DopeSheet;
    if (ImGui::MenuItem("Dope Sheet", nullptr, dopeSheet))
      state.animationEditor = dopeSheet ? AnimationEditorKind::None : AnimationEditorKind::DopeSheet;
    if (ImGui::MenuItem("Curve Editor", "Shift+F6", state.animationEditor == AnimationEditorKind::CurveEditor))
      state.animationEditor = state.animationEditor == AnimationEditorKind::CurveEditor ? AnimationEditorKind::None
                                                                                          : AnimationEditorKind::CurveEditor;
    ImGui::MenuItem("Onion Skin", "Alt+O", &state.onionSkin.enabled);
    ImGui::MenuItem("Motion Path", "Alt+P", &state.motionPath.enabled);
    if (ImGui::MenuItem("Onion Skin && Motion Path...")) state.onionSkinWindowOpen = true;
    if (ImGui::MenuItem("Motion Control...", "Alt+M")) state.motionControl.windowOpen = true;
    ImGui::EndMenu();
  }
  if (ImGui::BeginMenu("Pose")) {
    if (ImGui::MenuItem("Add IK Target to Selected", "Shift+I", false, doc.selection.active() >= 0)) addIkTargetToActive(state);
    const int t = currentIkTarget(state);
    if (ImGui::MenuItem("Remove IK Target", nullptr, false, t >= 0)) removeCurrentIkTarget(state);
    const bool pinned = t >= 0 && doc.ikTargets()[t].pinned;
    if (ImGui::MenuItem("Pin IK Target", nullptr, pinned, t >= 0)) togglePin(state);
    ImGui::SetNextItemWidth(80);
    ImGui::SliderInt("Chain length", &p.ikChainLength, 1, 8);
    bool unskinned = false;
    for (const MeshInstance& m : doc.scene().meshInstances) unskinned = unskinned || m.skin < 0;
    if (ImGui::MenuItem("Bind to Skeleton with Automatic Weights", "Ctrl+P", false, unskinned))
      showEditorError(state, bindUnskinnedMeshes(doc));
    // Keying (timeline.h): at the playhead, with the timeline's key preferences.
    ImGui::Separator();
    if (ImGui::MenuItem("Insert Keyframe", "I", false, !doc.selection.empty())) state.statusMessage = keySelectedJoints(state);
    if (ImGui::MenuItem("Insert Keys on All Joints")) state.statusMessage = keyAllJoints(state);
    if (ImGui::MenuItem("Delete Keyframe", "Alt+I", false, !doc.selection.empty()))
      state.statusMessage = deleteSelectedJointKeys(state);
    ImGui::MenuItem("Auto-key", nullptr, &state.doc.autoKey.enabled);
    ImGui::EndMenu();
  }
  if (ImGui::BeginMenu("Teach")) {
    if (ImGui::MenuItem("Compare Solvers", "Esc leaves", state.compare.active)) state.compare.active = !state.compare.active;
    ImGui::EndMenu();
  }
  if (ImGui::BeginMenu("Help")) {
    if (ImGui::MenuItem("Controls", "F1", p.showHelp)) p.showHelp = !p.showHelp;
    ImGui::EndMenu();
  }
  // The file's name and a dirty marker at the right end of the bar.
  const std::string name = documentTitle(state) + (doc.dirty() ? " *" : "");
  ImGui::SameLine(ImGui::GetWindowWidth() - ImGui::CalcTextSize(name.c_str()).x - 12);
  ImGui::TextDisabled("%s", name.c_str());
  ImGui::EndMainMenuBar();
}

}  // namespace kinema
