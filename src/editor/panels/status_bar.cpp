// The status bar: the active joint and selection, what the current tool does, how each IK
// target's last solve went, the last message, and the frame rate.
#include <imgui.h>

#include <string>

#include "editor/commands/controls_help.h"
#include "editor/panels/editor_panels.h"
#include "editor/panels/panel_layout.h"

namespace kinema {

void drawStatusBar(CommandContext& ctx, float fps) {
  EditorState& state = ctx.state;
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
  // What the tool, the mode or the selection takes now, in the active keymap (controls_help.h).
  if (ctx.keymap) ImGui::TextDisabled("%s", statusHint(state, *ctx.keymap).c_str());
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
