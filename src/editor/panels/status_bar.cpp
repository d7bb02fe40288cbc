// The status bar: the active joint and selection, what the current tool does, how each IK
// target's last solve went, the last message, and the frame rate.
#include <imgui.h>

#include <string>

#include "editor/panels/editor_panels.h"
#include "editor/panels/panel_layout.h"

namespace kinema {

namespace {

const char* toolHint(const EditorState& state) {
  if (state.compare.active)
    return "Compare: Right step, Shift+Right iteration, Space play, End run, R reset, drag the target, Esc leaves";
  switch (state.tool.mode) {
    case ModalTool::Rotate: return "Rotate: move the mouse, X/Y/Z constrain, click/Enter confirms, Esc cancels";
    case ModalTool::Grab: return "Move: move the mouse, X/Y/Z constrain, click/Enter confirms, Esc cancels";
    case ModalTool::BoxSelect: return "Box select: release to select (Shift adds, Ctrl removes)";
    case ModalTool::IkDrag: return "IK drag: the chain follows; release to drop, Esc cancels";
    case ModalTool::GizmoDrag: return "Gizmo: drag a ring to rotate about its axis";
    case ModalTool::Navigate: return "View: orbit / pan";
    case ModalTool::None: break;
  }
  return state.doc.selection.active() >= 0 ? "R rotate, G move root, Alt+R clear, Shift+click add" : "Click a joint to select it";
}

}  // namespace

void drawStatusBar(EditorState& state, float fps) {
  const Document& doc = state.doc;
  const PanelRect r = statusBarRect(ImGui::GetIO().DisplaySize);
  ImGui::SetNextWindowPos(ImVec2(r.x, r.y), ImGuiCond_Always);
  ImGui::SetNextWindowSize(ImVec2(r.w, r.h), ImGuiCond_Always);
  ImGui::PushStyleVar(ImGuiStyleVar_WindowPadding, ImVec2(8, 4));
  ImGui::Begin("##status", nullptr, kPanelFlags | ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_NoBringToFrontOnFocus);
  const int active = doc.selection.active();
  if (active >= 0 && active < doc.skeleton().size())
    ImGui::Text("%s (%d selected)", doc.skeleton().names[active].c_str(), static_cast<int>(doc.selection.joints().size()));
  else
    ImGui::TextDisabled("nothing selected");
  ImGui::SameLine(0, 24);
  ImGui::TextDisabled("%s", toolHint(state));
  for (const IkTargetReport& report : doc.lastIkReports()) {
    ImGui::SameLine(0, 24);
    const std::string name = report.target < 0 ? "auto-IK" : "IK " + std::to_string(report.target);
    ImGui::Text("%s: %d it, err %.1e, %.2f ms", name.c_str(), report.iterations, report.error, report.milliseconds);
  }
  if (!state.statusMessage.empty()) {
    ImGui::SameLine(0, 24);
    ImGui::TextUnformatted(state.statusMessage.c_str());
  }
  const std::string rate = std::to_string(static_cast<int>(fps + 0.5f)) + " fps";
  ImGui::SameLine(r.w - ImGui::CalcTextSize(rate.c_str()).x - 10);
  ImGui::TextDisabled("%s", rate.c_str());
  ImGui::End();
  ImGui::PopStyleVar();
}

}  // namespace kinema
