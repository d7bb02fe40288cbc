// The outliner: the joint tree (collapsible, indented by parent) with a search box that
// keeps matching joints and their ancestors; click selects (Shift toggles), double-click
// renames in place. The clip list sits under the tree (clip_list_panel.cpp).
#include <imgui.h>

#include <cstdio>

#include "editor/panels/editor_panels.h"
#include "editor/panels/item_names.h"
#include "editor/model/outliner_rows.h"
#include "editor/panels/panel_layout.h"
#include "editor/model/pose_edits.h"

namespace kinema {

namespace {

void startRename(PanelState& p, int joint, const std::string& name) {
  p.renaming = joint;
  p.renameFocus = true;
  p.renameError.clear();
  std::snprintf(p.renameBuffer, sizeof(p.renameBuffer), "%s", name.c_str());
}

}  // namespace

void drawOutlinerPanel(CommandContext& ctx) {
  EditorState& state = ctx.state;
  Document& doc = state.doc;
  PanelState& p = state.panels;
  const Skeleton& s = doc.skeleton();
  const PanelRect r = state.layout.outliner;
  ImGui::SetNextWindowPos(ImVec2(r.x, r.y), ImGuiCond_Always);
  ImGui::SetNextWindowSize(ImVec2(r.w, r.h), ImGuiCond_Always);
  if (!ImGui::Begin("Outliner", nullptr, kPanelFlags)) {
    ImGui::End();
    return;
  }
  recordWindow("Outliner");
  ImGui::SetNextItemWidth(-1);
  ImGui::InputTextWithHint("##search", "search joints", p.search, sizeof(p.search));
  recordItem("Outliner/Search");
  if (static_cast<int>(p.collapsed.size()) != s.size()) p.collapsed.assign(static_cast<size_t>(s.size()), false);
  if (p.renaming >= s.size()) p.renaming = -1;

  ImGui::BeginChild("##tree", ImVec2(0, -clipListHeight(state)));
  const std::vector<OutlinerRow> rows = outlinerRows(s, p.search, p.collapsed);
  if (rows.empty()) ImGui::TextDisabled(s.empty() ? "no joints" : "no joint matches");
  const float toggleWidth = ImGui::CalcTextSize("+").x + 2.0f * ImGui::GetStyle().FramePadding.x;
  for (const OutlinerRow& row : rows) {
    const int i = row.joint;
    ImGui::PushID(i);
    const float indent = static_cast<float>(row.depth) * scaled(state, kOutlinerIndent) + 0.001f;
    ImGui::Indent(indent);
    if (row.hasChildren && p.search[0] == '\0') {
      if (ImGui::SmallButton(p.collapsed[i] ? "+" : "-")) p.collapsed[i] = !p.collapsed[i];
      recordItem("Outliner/" + s.names[i] + "/Collapse");
    } else {
      ImGui::Dummy(ImVec2(toggleWidth, 1.0f));
    }
    ImGui::SameLine();
    if (p.renaming == i) {
      if (p.renameFocus) {
        ImGui::SetKeyboardFocusHere();
        p.renameFocus = false;
      }
      ImGui::SetNextItemWidth(-1);
      const bool enter = ImGui::InputText("##rename", p.renameBuffer, sizeof(p.renameBuffer),
                                          ImGuiInputTextFlags_EnterReturnsTrue | ImGuiInputTextFlags_AutoSelectAll);
      recordItem("Outliner/Rename");
      if (enter) {
        // The model validates (non-empty, unique); a refusal keeps the field open with the reason.
        p.renameError = renameJoint(doc, i, p.renameBuffer);
        if (p.renameError.empty()) p.renaming = -1;
        else p.renameFocus = true;  // Enter left the field: back into it to fix the name (Esc gives up)
      } else if (ImGui::IsItemDeactivated() && !p.renameFocus) {
        p.renaming = -1;  // Esc or a click elsewhere cancels
        p.renameError.clear();
      }
    } else {
      if (!row.matches) ImGui::PushStyleColor(ImGuiCol_Text, ImGui::GetStyle().Colors[ImGuiCol_TextDisabled]);
      const bool clicked = ImGui::Selectable(s.names[i].c_str(), doc.selection.isSelected(i),
                                             ImGuiSelectableFlags_AllowDoubleClick);
      recordItem("Outliner/" + s.names[i]);
      if (!row.matches) ImGui::PopStyleColor();
      if (clicked) {
        if (ImGui::IsMouseDoubleClicked(ImGuiMouseButton_Left)) startRename(p, i, s.names[i]);
        else if (ImGui::GetIO().KeyShift) doc.selection.shiftClick(i);
        else doc.selection.click(i);
      }
    }
    ImGui::Unindent(indent);
    if (p.renaming == i && !p.renameError.empty())
      ImGui::TextColored(ImVec4(1.0f, 0.45f, 0.4f, 1.0f), "%s", p.renameError.c_str());
    ImGui::PopID();
  }
  ImGui::EndChild();
  drawClipList(ctx);
  ImGui::End();
}

}  // namespace kinema
