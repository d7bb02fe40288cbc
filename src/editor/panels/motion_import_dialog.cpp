// The "Import Motion" modal (File > Import Motion onto Character…): the bone map found for a
// motion file, canonical bone | source joint | target joint, with the unmapped joints of each
// side counted; a combo per row changes the source joint. Apply adds the retargeted clip
// (commands/file_commands.h applyMotionImportInEditor), Cancel drops it.
#include <imgui.h>

#include <algorithm>
#include <string>

#include "editor/commands/file_commands.h"
#include "editor/panels/editor_panels.h"
#include "editor/panels/item_names.h"

namespace kinema {

namespace {

constexpr const char* kTitle = "Import Motion";
constexpr const char* kUnmapped = "- unmapped -";

void jointCell(const Skeleton& s, int joint) {
  if (joint >= 0 && joint < s.size()) ImGui::TextUnformatted(s.names[joint].c_str());
  else ImGui::TextDisabled("%s", kUnmapped);
}

// The source joint of row `row`: a combo over the source's joints (and "unmapped").
void sourceCombo(EditorState& state, MotionImport& m, int row) {
  const Skeleton& src = m.source.skeleton;
  const int current = m.rows[row].source;
  const std::string name = std::string(kTitle) + "/" + m.rows[row].bone + "/Source";
  ImGui::SetNextItemWidth(-1);
  ImGui::PushID(row);
  const bool unmapped = current < 0;
  if (unmapped) ImGui::PushStyleColor(ImGuiCol_Text, ImGui::GetStyleColorVec4(ImGuiCol_TextDisabled));
  const bool open = ImGui::BeginCombo("##source", unmapped ? kUnmapped : src.names[current].c_str());
  if (unmapped) ImGui::PopStyleColor();
  recordItem(name);
  if (open) {
    for (int j = -1; j < src.size(); ++j) {
      ImGui::PushID(j);
      const char* label = j < 0 ? kUnmapped : src.names[j].c_str();
      if (ImGui::Selectable(label, j == current) && j != current) {
        const std::string error = setMotionImportSource(m, state.doc.skeleton(), row, j);
        state.panels.motionImportError = error;
        if (!error.empty()) state.statusMessage = "Import motion: " + error;
      }
      recordItem(name + "/" + label);
      ImGui::PopID();
    }
    ImGui::EndCombo();
  }
  ImGui::PopID();
}

}  // namespace

void drawMotionImportDialog(CommandContext& ctx) {
  EditorState& state = ctx.state;
  PanelState& p = state.panels;
  if (!p.motionImport) return;
  if (p.motionImportJustOpened && !ImGui::IsPopupOpen("", ImGuiPopupFlags_AnyPopupId)) {
    ImGui::OpenPopup(kTitle);
    p.motionImportJustOpened = false;
  }
  const ImVec2 display = ImGui::GetIO().DisplaySize;
  ImGui::SetNextWindowPos(ImVec2(display.x * 0.5f, display.y * 0.5f), ImGuiCond_Appearing, ImVec2(0.5f, 0.5f));
  ImGui::SetNextWindowSize(ImVec2(std::min(ImGui::GetFontSize() * 44.0f, display.x * 0.9f),
                                  std::min(ImGui::GetFontSize() * 36.0f, display.y * 0.9f)),
                           ImGuiCond_Appearing);
  if (!ImGui::BeginPopupModal(kTitle, nullptr, ImGuiWindowFlags_NoSavedSettings)) return;
  MotionImport& m = *p.motionImport;
  const Skeleton& target = state.doc.skeleton();
  const Skeleton& source = m.source.skeleton;
  ImGui::TextWrapped("%s", m.path.c_str());
  if (m.source.clips.size() > 1) {
    // The file's clip to retarget (kinema retarget --clip): any of them, the first by default.
    ImGui::TextUnformatted("Clip");
    ImGui::SameLine();
    ImGui::SetNextItemWidth(ImGui::GetFontSize() * 14.0f);
    const std::string current = std::to_string(m.clip) + ": " + m.source.clips[m.clip].name;
    const bool open = ImGui::BeginCombo("##clip", current.c_str());
    recordItem(std::string(kTitle) + "/Clip");
    if (open) {
      for (int c = 0; c < static_cast<int>(m.source.clips.size()); ++c) {
        const std::string label = std::to_string(c) + ": " + m.source.clips[c].name;
        if (ImGui::Selectable(label.c_str(), c == m.clip)) m.clip = c;
        recordItem(std::string(kTitle) + "/Clip/" + label);
      }
      ImGui::EndCombo();
    }
    ImGui::SameLine();
    ImGui::Text("of %d, onto %s (%d joints); bone map by %s", static_cast<int>(m.source.clips.size()),
                documentTitle(state).c_str(), target.size(), m.mapBy.c_str());
  } else {
    ImGui::Text("Clip '%s' onto %s (%d joints); bone map by %s", m.source.clips[m.clip].name.c_str(),
                documentTitle(state).c_str(), target.size(), m.mapBy.c_str());
  }
  ImGui::Text("Unmapped: %d of %d source joints, %d of %d target joints", static_cast<int>(m.unmappedSource.size()),
              source.size(), static_cast<int>(m.unmappedTarget.size()), target.size());
  recordItem(std::string(kTitle) + "/Unmapped");

  const float buttons = ImGui::GetFrameHeightWithSpacing() * (p.motionImportError.empty() ? 1.5f : 2.5f);
  const ImGuiTableFlags flags = ImGuiTableFlags_RowBg | ImGuiTableFlags_Borders | ImGuiTableFlags_ScrollY |
                                ImGuiTableFlags_SizingStretchSame;
  if (ImGui::BeginTable("##bone map", 3, flags, ImVec2(0, -buttons))) {
    ImGui::TableSetupScrollFreeze(0, 1);
    ImGui::TableSetupColumn("Bone");
    ImGui::TableSetupColumn("Source joint");
    ImGui::TableSetupColumn("Target joint");
    ImGui::TableHeadersRow();
    for (int r = 0; r < static_cast<int>(m.rows.size()); ++r) {
      const MotionImportRow row = m.rows[r];  // a copy: the combo may rebuild the rows
      ImGui::TableNextRow();
      ImGui::TableNextColumn();
      if (row.source >= 0 && row.target >= 0) ImGui::TextUnformatted(row.bone.c_str());
      else ImGui::TextDisabled("%s", row.bone.c_str());
      recordItem(std::string(kTitle) + "/" + row.bone);
      ImGui::TableNextColumn();
      if (row.target >= 0) sourceCombo(state, m, r);
      else jointCell(source, row.source);
      ImGui::TableNextColumn();
      jointCell(target, row.target);
    }
    // The joints no canonical bone names: what stays at rest (target) or is not played (source).
    for (int j : m.unmappedTarget) {
      if (std::any_of(m.rows.begin(), m.rows.end(), [j](const MotionImportRow& r) { return r.target == j; })) continue;
      ImGui::TableNextRow();
      ImGui::TableNextColumn();
      ImGui::TextDisabled("-");
      ImGui::TableNextColumn();
      ImGui::TextDisabled("%s", kUnmapped);
      ImGui::TableNextColumn();
      ImGui::TextDisabled("%s", target.names[j].c_str());
    }
    for (int j : m.unmappedSource) {
      if (std::any_of(m.rows.begin(), m.rows.end(), [j](const MotionImportRow& r) { return r.source == j; })) continue;
      ImGui::TableNextRow();
      ImGui::TableNextColumn();
      ImGui::TextDisabled("-");
      ImGui::TableNextColumn();
      ImGui::TextDisabled("%s", source.names[j].c_str());
      ImGui::TableNextColumn();
      ImGui::TextDisabled("%s", kUnmapped);
    }
    ImGui::EndTable();
  }
  if (!p.motionImportError.empty()) ImGui::TextColored(ImVec4(1.0f, 0.45f, 0.4f, 1.0f), "%s", p.motionImportError.c_str());
  // Apply adds a clip; on a clip's own map (Animation > Edit Bone Map of Clip…) it replaces it.
  const bool apply = ImGui::Button(m.replaceClip >= 0 ? "Apply (replace clip)###Apply" : "Apply",
                                   ImVec2(ImGui::GetFontSize() * (m.replaceClip >= 0 ? 11.0f : 8.5f), 0));
  recordItem(std::string(kTitle) + "/Apply");
  ImGui::SameLine();
  const bool cancel = ImGui::Button("Cancel", ImVec2(ImGui::GetFontSize() * 8.5f, 0)) ||
                      (!ImGui::IsWindowAppearing() && ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_Escape), false));
  recordItem(std::string(kTitle) + "/Cancel");
  if (apply) {
    applyMotionImportInEditor(state);
    if (!p.motionImport) ImGui::CloseCurrentPopup();
  } else if (cancel) {
    cancelMotionImport(state);
    ImGui::CloseCurrentPopup();
  }
  ImGui::EndPopup();
}

}  // namespace kinema
