// View > Onion Skin & Motion Path... and View > Motion Control...: two small floating windows
// over the 3D view (the settings live in EditorState; the drawing in animation_display.cpp).
#include <imgui.h>

#include <algorithm>

#include "editor/panels/editor_panels.h"
#include "editor/panels/item_names.h"
#include "editor/model/motion_control.h"
#include "editor/panels/panel_layout.h"
#include "editor/model/timeline.h"

namespace kinema {

namespace {

glm::vec4 lastItemRect() {
  const ImVec2 a = ImGui::GetItemRectMin(), b = ImGui::GetItemRectMax();
  return glm::vec4(a.x, a.y, b.x - a.x, b.y - a.y);
}

void colorEdit(const char* label, glm::vec3& c) { ImGui::ColorEdit3(label, &c.x, ImGuiColorEditFlags_NoInputs); }

void drawOnionSkinWindow(EditorState& state) {
  if (!state.onionSkinWindowOpen) return;
  const PanelRect v = state.layout.viewport;
  ImGui::SetNextWindowPos(ImVec2(v.x + 10.0f, v.y + 10.0f), ImGuiCond_Appearing);
  if (!ImGui::Begin("Onion Skin & Motion Path", &state.onionSkinWindowOpen, ImGuiWindowFlags_AlwaysAutoResize)) {
    ImGui::End();
    return;
  }
  recordWindow("Onion Skin & Motion Path");
  OnionSkinSettings& o = state.onionSkin;
  ImGui::Checkbox("Onion skin (Alt+O)", &o.enabled);
  ImGui::PushItemWidth(90.0f);
  ImGui::SliderInt("Before", &o.before, 0, 10);
  recordItem("Onion Skin & Motion Path/Before");
  ImGui::SliderInt("After", &o.after, 0, 10);
  recordItem("Onion Skin & Motion Path/After");
  ImGui::DragInt("Step (frames)", &o.step, 0.2f, 1, 120);
  recordItem("Onion Skin & Motion Path/Step");
  o.step = std::max(o.step, 1);
  ImGui::SliderFloat("Opacity", &o.opacity, 0.05f, 1.0f, "%.2f");
  ImGui::PopItemWidth();
  colorEdit("Before colour", o.beforeColor);
  ImGui::SameLine();
  colorEdit("After colour", o.afterColor);
  ImGui::Checkbox("Ghosts of the body (meshes)", &o.bodies);
  if (ImGui::IsItemHovered()) ImGui::SetTooltip("Off, or without meshes: the ghosts are bones");
  ImGui::Separator();
  MotionPathSettings& p = state.motionPath;
  ImGui::Checkbox("Motion path of the active joint (Alt+P)", &p.enabled);
  ImGui::Checkbox("Whole clip", &p.wholeClip);
  if (!p.wholeClip) {
    ImGui::PushItemWidth(90.0f);
    ImGui::DragInt("Frames before", &p.before, 0.5f, 0, 100000);
    ImGui::DragInt("Frames after", &p.after, 0.5f, 0, 100000);
    ImGui::PopItemWidth();
  }
  if (!state.hasMotion()) ImGui::TextDisabled("The file has no clip.");
  ImGui::End();
}

void drawMotionControlWindow(EditorState& state) {
  MotionControlSettings& m = state.motionControl;
  if (!m.windowOpen) return;
  const PanelRect v = state.layout.viewport;
  ImGui::SetNextWindowPos(ImVec2(v.x + 10.0f, v.y + 10.0f), ImGuiCond_Appearing);
  if (!ImGui::Begin("Motion Control", &m.windowOpen, ImGuiWindowFlags_AlwaysAutoResize)) {
    ImGui::End();
    return;
  }
  const int joint = state.doc.selection.active();
  const Clip* clip = state.hasMotion() ? &state.doc.scene().clips[state.clip] : nullptr;
  const int channel = clip && joint >= 0 ? translationChannelIndex(*clip, joint) : -1;
  if (!clip) ImGui::TextDisabled("The file has no clip.");
  else if (joint < 0) ImGui::TextDisabled("Select a joint with translation keys.");
  else if (channel < 0) ImGui::TextDisabled("%s has no translation keys.", state.doc.skeleton().names[joint].c_str());
  else ImGui::Text("%s: translation path, %d keys", state.doc.skeleton().names[joint].c_str(),
                   clip->channels[channel].keyCount());
  ImGui::TextDisabled("Distance along the path over time:");
  const char* names[] = {"Constant speed", "Ease in/out (sine)", "Ease in/out (parabolic)"};
  const MotionControlProfile profiles[] = {MotionControlProfile::ConstantSpeed, MotionControlProfile::SineEase,
                                           MotionControlProfile::ParabolicEase};
  for (int i = 0; i < 3; ++i) {
    if (ImGui::RadioButton(names[i], m.profile == profiles[i])) m.profile = profiles[i];
    m.profileRects[i] = lastItemRect();
  }
  ImGui::Checkbox("Ticks at equal times", &m.showTicks);
  const bool usable = channel >= 0 && clip->channels[channel].keyCount() >= 2;
  if (!usable) ImGui::BeginDisabled();
  if (ImGui::Button("Apply (bake a key per frame)")) {
    const std::string error = applyMotionControl(state.doc, state.clip, joint, m.profile);
    if (!error.empty()) showEditorError(state, error);
    else {
      state.statusMessage = std::string("Motion control: ") + names[static_cast<int>(m.profile)];
      poseAtPlayhead(state);  // the pose follows the re-timed channel at the current frame
    }
  }
  m.applyRect = lastItemRect();
  if (!usable) ImGui::EndDisabled();
  ImGui::End();
}

}  // namespace

void drawAnimationDisplayWindows(EditorState& state) {
  drawOnionSkinWindow(state);
  drawMotionControlWindow(state);
}

}  // namespace kinema
