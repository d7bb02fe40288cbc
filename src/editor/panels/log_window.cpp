// View > Log: every status-bar message and error of the session, in full and wrapped, with
// the time it came (the status bar elides long ones to its width).
#include <imgui.h>

#include <algorithm>

#include "editor/panels/editor_panels.h"
#include "editor/panels/item_names.h"
#include "editor/panels/panel_layout.h"

namespace kinema {

void drawLogWindow(EditorState& state) {
  if (!state.logWindowOpen) return;
  const PanelRect& v = state.layout.viewport;
  // In the 3D view's lower left, at most as large as the view.
  const ImVec2 size(std::min(scaled(state, 560.0f), v.w - scaled(state, 32.0f)),
                    std::min(scaled(state, 260.0f), v.h - scaled(state, 32.0f)));
  ImGui::SetNextWindowPos(ImVec2(v.x + scaled(state, 16.0f), std::max(v.y, v.bottom() - size.y - scaled(state, 16.0f))),
                          ImGuiCond_Appearing);
  ImGui::SetNextWindowSize(ImVec2(std::max(size.x, 200.0f), std::max(size.y, 100.0f)), ImGuiCond_Appearing);
  if (!ImGui::Begin("Log", &state.logWindowOpen, ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_NoCollapse)) {
    ImGui::End();
    return;
  }
  recordWindow("Log");
  const std::vector<LogEntry>& entries = state.log.entries();
  if (ImGui::SmallButton("Copy all")) {
    std::string all;
    for (const LogEntry& e : entries) all += e.time + "  " + e.text + "\n";
    ImGui::SetClipboardText(all.c_str());
  }
  recordItem("Log/Copy all");
  ImGui::SameLine();
  ImGui::TextDisabled("%d message(s)", static_cast<int>(entries.size()));
  ImGui::BeginChild("##log entries", ImVec2(0, 0), true);
  const bool atBottom = ImGui::GetScrollY() >= ImGui::GetScrollMaxY();
  const float textX = ImGui::CalcTextSize("00:00:00").x + ImGui::GetStyle().ItemSpacing.x * 2;
  for (size_t i = 0; i < entries.size(); ++i) {
    const LogEntry& e = entries[i];
    ImGui::TextDisabled("%s", e.time.c_str());
    ImGui::SameLine(textX);
    ImGui::PushTextWrapPos(0.0f);
    if (e.error) ImGui::PushStyleColor(ImGuiCol_Text, ImVec4(1.0f, 0.45f, 0.4f, 1.0f));
    ImGui::TextUnformatted(e.text.c_str());
    if (e.error) ImGui::PopStyleColor();
    ImGui::PopTextWrapPos();
    recordItem("Log/" + std::to_string(i));
  }
  if (atBottom) ImGui::SetScrollHereY(1.0f);  // follows new messages unless scrolled up
  ImGui::EndChild();
  ImGui::End();
}

}  // namespace kinema
