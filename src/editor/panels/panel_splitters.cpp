// The boundaries between the panels move with the mouse, as Blender's area edges do: a thin
// window straddles each boundary (above the panels, which stay at the back), and
// dragging it moves the splitter within the limits of editor_layout.h (dragSplitter). The
// sizes are state.preferences.panels, saved with the preferences on exit.
#include <imgui.h>

#include <string>
#include <vector>

#include "editor/panels/editor_panels.h"
#include "editor/panels/item_names.h"
#include "editor/panels/panel_layout.h"

namespace kinema {

namespace {

struct Edge {
  Splitter which;
  PanelRect zone;
  bool vertical;  // a vertical boundary: dragged left and right
  const char* name;
};

}  // namespace

void drawPanelSplitters(EditorState& state) {
  const EditorLayout& l = state.layout;
  const float t = scaled(state, kSplitterThickness), h = t * 0.5f;
  std::vector<Edge> edges = {
      {Splitter::LeftColumn, {l.outliner.right() - h, l.panelArea.y, t, l.panelArea.h}, true, "Splitter/Left column"},
      {Splitter::RightColumn, {l.properties.x - h, l.panelArea.y, t, l.panelArea.h}, true, "Splitter/Right column"},
      {Splitter::OutlinerHistory, {l.history.x, l.history.y - h, l.history.w, t}, false, "Splitter/Outliner"},
      {Splitter::PropertiesIk, {l.ikTargets.x, l.ikTargets.y - h, l.ikTargets.w, t}, false, "Splitter/Properties"},
  };
  if (state.bottomPanels().animationEditor)
    edges.push_back({Splitter::AnimationEditor, {l.animationEditor.x, l.animationEditor.y - h, l.animationEditor.w, t},
                     false, "Splitter/Animation editor"});
  const ImGuiIO& io = ImGui::GetIO();
  for (const Edge& e : edges) {
    placeNextWindow(e.zone);
    ImGui::PushStyleVar(ImGuiStyleVar_WindowPadding, ImVec2(0, 0));
    ImGui::PushStyleVar(ImGuiStyleVar_WindowMinSize, ImVec2(1, 1));
    ImGui::PushStyleVar(ImGuiStyleVar_WindowBorderSize, 0.0f);
    // Without NoBringToFrontOnFocus, which ImGui puts at the back of the display order when
    // created: the splitters must lie over the panels.
    ImGui::Begin((std::string("##") + e.name).c_str(), nullptr,
                 (kPanelFlags & ~ImGuiWindowFlags_NoBringToFrontOnFocus) | ImGuiWindowFlags_NoDecoration |
                     ImGuiWindowFlags_NoBackground | ImGuiWindowFlags_NoFocusOnAppearing | ImGuiWindowFlags_NoNav);
    ImGui::InvisibleButton("##drag", ImVec2(e.zone.w, e.zone.h));
    recordItem(e.name);
    const bool active = ImGui::IsItemActive(), hovered = ImGui::IsItemHovered();
    if (active || hovered) {
      ImGui::SetMouseCursor(e.vertical ? ImGuiMouseCursor_ResizeEW : ImGuiMouseCursor_ResizeNS);
      const ImU32 c = ImGui::GetColorU32(active ? ImGuiCol_SeparatorActive : ImGuiCol_SeparatorHovered);
      ImGui::GetWindowDrawList()->AddRectFilled(ImVec2(e.zone.x, e.zone.y), ImVec2(e.zone.right(), e.zone.bottom()), c);
    }
    if (active) {
      const float at = e.vertical ? io.MousePos.x : io.MousePos.y;
      state.preferences.panels = dragSplitter(state.preferences.panels, e.which, at, io.DisplaySize.x,
                                              io.DisplaySize.y, state.bottomPanels(), l.metrics);
    }
    ImGui::End();
    ImGui::PopStyleVar(3);
  }
}

}  // namespace kinema
