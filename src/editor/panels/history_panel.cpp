// The undo history: every step by label, the applied ones bright, the redoable ones dim;
// clicking a step undoes or redoes up to it (Blender's Undo History).
#include <imgui.h>

#include <string>

#include "editor/panels/editor_panels.h"
#include "editor/panels/item_names.h"
#include "editor/panels/panel_layout.h"
#include "editor/model/timeline.h"

namespace kinema {

void drawHistoryPanel(EditorState& state) {
  Document& doc = state.doc;
  const PanelRect r = state.layout.history;
  ImGui::SetNextWindowPos(ImVec2(r.x, r.y), ImGuiCond_Always);
  ImGui::SetNextWindowSize(ImVec2(r.w, r.h), ImGuiCond_Always);
  if (!ImGui::Begin("History", nullptr, kPanelFlags)) {
    ImGui::End();
    return;
  }
  recordWindow("History");
  const std::vector<std::string> labels = doc.historyLabels();
  const int position = doc.historyPosition();
  const bool moved = position != state.panels.historyShownPosition;
  state.panels.historyShownPosition = position;
  int jump = -1;
  // Row k (0 = the original document) is the state with k steps applied.
  for (int k = 0; k <= static_cast<int>(labels.size()); ++k) {
    ImGui::PushID(k);
    const bool applied = k <= position;
    if (!applied) ImGui::PushStyleColor(ImGuiCol_Text, ImGui::GetStyle().Colors[ImGuiCol_TextDisabled]);
    const std::string label = k == 0 ? "(original)" : std::to_string(k) + ". " + labels[k - 1];
    if (ImGui::Selectable(label.c_str(), k == position)) jump = k;
    if (k == position && moved) ImGui::SetScrollHereY(0.5f);  // the current step in view, as Blender keeps it
    recordItem("History/" + std::to_string(k));  // by step: "History/0" is (original)
    if (!applied) ImGui::PopStyleColor();
    ImGui::PopID();
  }
  if (ImGui::GetScrollY() >= ImGui::GetScrollMaxY() && position == static_cast<int>(labels.size()))
    ImGui::SetScrollHereY(1.0f);  // keep the newest step in view
  if (jump >= 0 && jump != position && !doc.dragging()) {
    if (doc.jumpToHistory(jump)) state.statusMessage = "History: " + std::to_string(jump) + " step(s) applied";
    followDocumentClip(state);  // the active clip of that step
  }
  ImGui::End();
}

}  // namespace kinema
