// The clip list (Blender's action list): the scene's clips in file order under the
// outliner's joint tree, the active one highlighted; shown while the scene has clips. A click chooses a clip, a double click
// renames it in place; New / Duplicate / Rename / Delete run the Clip menu's commands. The
// Clip menu lists the clips too.
#include <imgui.h>

#include <algorithm>
#include <string>

#include "editor/commands/clip_commands.h"
#include "editor/panels/command_widgets.h"
#include "editor/panels/editor_panels.h"
#include "editor/panels/item_names.h"

namespace kinema {

namespace {

constexpr int kVisibleClipRows = 5;  // more clips scroll within the list

const ImVec4 kErrorColor(1.0f, 0.45f, 0.4f, 1.0f);

// The refusal under the name field, wrapped to the panel's width.
float errorHeight(const std::string& error) {
  return ImGui::CalcTextSize(error.c_str(), nullptr, false, ImGui::GetContentRegionAvail().x).y +
         ImGui::GetStyle().ItemSpacing.y;
}

// The list's own height: its rows, the taller name field while renaming, the refusal under it.
float listAreaHeight(const EditorState& state) {
  const int rows = std::clamp(static_cast<int>(state.doc.scene().clips.size()), 1, kVisibleClipRows);
  const PanelState& p = state.panels;
  return static_cast<float>(rows) * ImGui::GetTextLineHeightWithSpacing() +
         (p.renamingClip >= 0 ? 2.0f * ImGui::GetStyle().FramePadding.y : 0.0f) +
         (p.clipRenameError.empty() ? 0.0f : errorHeight(p.clipRenameError));
}

void drawRenameField(EditorState& state) {
  PanelState& p = state.panels;
  if (p.clipRenameFocus) {
    ImGui::SetKeyboardFocusHere();
    p.clipRenameFocus = false;
  }
  ImGui::SetNextItemWidth(-1);
  const bool enter = ImGui::InputText("##clip name", p.clipRenameBuffer, sizeof(p.clipRenameBuffer),
                                      ImGuiInputTextFlags_EnterReturnsTrue | ImGuiInputTextFlags_AutoSelectAll);
  recordItem("Clips/Rename");
  if (enter) {
    finishClipRename(state);
    if (p.renamingClip >= 0) p.clipRenameFocus = true;  // refused: back into the field (Esc gives up)
  } else if (ImGui::IsItemDeactivated() && !p.clipRenameFocus) {
    p.renamingClip = -1;  // Esc or a click elsewhere cancels
    p.clipRenameError.clear();
  }
}

}  // namespace

float clipListHeight(const EditorState& state) {
  if (state.doc.scene().clips.empty()) return 0.0f;
  const ImGuiStyle& style = ImGui::GetStyle();
  // The spacing after the tree, the separator (1 px and its spacing), the "Clips" title,
  // the list and its spacing, the row of buttons.
  return 3.0f * style.ItemSpacing.y + 1.0f + ImGui::GetTextLineHeightWithSpacing() + listAreaHeight(state) +
         ImGui::GetFrameHeight();
}

void drawClipList(CommandContext& ctx) {
  EditorState& state = ctx.state;
  PanelState& p = state.panels;
  const std::vector<Clip>& clips = state.doc.scene().clips;
  if (p.renamingClip >= static_cast<int>(clips.size())) p.renamingClip = -1;  // undone or deleted
  // Without clips the joint tree keeps the whole outliner; Clip > New Clip or the first key
  // (I) makes one, and the list appears.
  if (clips.empty()) return;
  ImGui::Separator();
  ImGui::TextUnformatted("Clips");
  const ImVec2 titleMin = ImGui::GetItemRectMin();
  ImGui::BeginChild("##clips", ImVec2(0, listAreaHeight(state)));
  int chosen = -1, renamed = -1;
  for (size_t c = 0; c < clips.size(); ++c) {
    const int i = static_cast<int>(c);
    ImGui::PushID(i);
    if (p.renamingClip == i) {
      drawRenameField(state);
      if (!p.clipRenameError.empty()) {
        ImGui::PushStyleColor(ImGuiCol_Text, kErrorColor);
        ImGui::TextWrapped("%s", p.clipRenameError.c_str());
        ImGui::PopStyleColor();
      }
    } else {
      const bool clicked = ImGui::Selectable(clips[c].name.empty() ? "(unnamed)" : clips[c].name.c_str(),
                                             i == state.doc.activeClip(), ImGuiSelectableFlags_AllowDoubleClick);
      recordItem("Clips/" + clips[c].name);
      if (clicked) {
        if (ImGui::IsMouseDoubleClicked(ImGuiMouseButton_Left)) renamed = i;
        else chosen = i;
      }
    }
    ImGui::PopID();
  }
  ImGui::EndChild();
  // After the loop: a choice changes the document the rows were drawn from.
  if (chosen >= 0 && chosen != state.doc.activeClip() && !state.doc.dragging()) chooseClipInEditor(state, chosen);
  if (renamed >= 0) startClipRename(state, renamed);
  // Four buttons sharing the row, each as wide as its text needs, stretched (or squeezed)
  // together to the panel's width.
  const char* const ids[] = {"clip.new", "clip.duplicate", "clip.rename", "clip.delete"};
  const char* const shown[] = {"New", "Duplicate", "Rename", "Delete"};
  const float spacing = ImGui::GetStyle().ItemSpacing.x * 0.5f, pad = 2.0f * ImGui::GetStyle().FramePadding.x;
  float natural = 0.0f;
  for (const char* text : shown) natural += ImGui::CalcTextSize(text).x + pad;
  const float scale = std::max(ImGui::GetContentRegionAvail().x - 3 * spacing, 4.0f) / natural;
  for (int b = 0; b < 4; ++b) {
    if (b > 0) ImGui::SameLine(0, spacing);
    commandButton(ctx, ids[b], "Clips", shown[b], ImVec2((ImGui::CalcTextSize(shown[b]).x + pad) * scale, 0));
  }
  // The whole section, so a script or test finds it as it finds a panel.
  if (ItemRects* rects = namedItems())
    rects->record("Clips", glm::vec2(titleMin.x, titleMin.y),
                  glm::vec2(ImGui::GetWindowPos().x + ImGui::GetWindowContentRegionMax().x, ImGui::GetItemRectMax().y));
}

void drawClipMenuList(CommandContext& ctx) {
  EditorState& state = ctx.state;
  const std::vector<Clip>& clips = state.doc.scene().clips;
  if (clips.empty()) return;
  ImGui::Separator();
  int chosen = -1;
  for (size_t c = 0; c < clips.size(); ++c) {
    ImGui::PushID(static_cast<int>(c));
    const bool active = static_cast<int>(c) == state.doc.activeClip();
    if (ImGui::MenuItem(clips[c].name.empty() ? "(unnamed)" : clips[c].name.c_str(), nullptr, active,
                        !state.doc.dragging()))
      chosen = static_cast<int>(c);
    recordItem(state.items, "Clip/Clips/" + clips[c].name);
    ImGui::PopID();
  }
  if (chosen >= 0 && chosen != state.doc.activeClip()) chooseClipInEditor(state, chosen);
}

}  // namespace kinema
