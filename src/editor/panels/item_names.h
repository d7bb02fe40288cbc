#pragma once
#include <imgui.h>

#include <algorithm>
#include <string>

#include "editor/model/item_rects.h"

namespace kinema {

// Names the widget just drawn, so --script and the e2e tests click it by name whatever the
// layout (model/item_rects.h). The window points ImGui's io.UserData at EditorState::items;
// without it (tools drawing panels alone) nothing is recorded. Names are paths: the window
// or menu, then the label ("Properties/Rotation", "IK Targets/Solver/FABRIK").
inline ItemRects* namedItems() { return static_cast<ItemRects*>(ImGui::GetIO().UserData); }

inline void recordItem(const std::string& name) {
  if (ItemRects* rects = namedItems()) {
    const ImVec2 a = ImGui::GetItemRectMin(), b = ImGui::GetItemRectMax();
    rects->record(name, glm::vec2(a.x, a.y), glm::vec2(b.x, b.y));
  }
}

// The same into a given table (the command widgets pass the editor state's).
inline void recordItem(ItemRects& rects, const std::string& name) {
  const ImVec2 a = ImGui::GetItemRectMin(), b = ImGui::GetItemRectMax();
  rects.record(name, glm::vec2(a.x, a.y), glm::vec2(b.x, b.y));
}

// Names the window being drawn, its whole rectangle ("History", "IK Targets"), so a script
// finds a panel's empty space or its title bar (to scroll it) and a test checks where the
// 3D view lies between the panels. Call it between Begin and End.
inline void recordWindow(const std::string& name) {
  if (ItemRects* rects = namedItems()) {
    const ImVec2 a = ImGui::GetWindowPos(), s = ImGui::GetWindowSize();
    rects->record(name, glm::vec2(a.x, a.y), glm::vec2(a.x + s.x, a.y + s.y));
  }
}

// After a labelled slider or drag of `width` pixels (0: the default item width): names its
// frame alone, not the label beside it, so that a point `at` a fraction of it is that
// fraction along the slider ("Curve Editor/T" at [0.99, 0.5] is its right end).
inline void recordFrame(const std::string& name, float width = 0.0f) {
  if (ItemRects* rects = namedItems()) {
    const ImVec2 a = ImGui::GetItemRectMin();
    const float w = width > 0.0f ? width : ImGui::CalcItemWidth();
    rects->record(name, glm::vec2(a.x, a.y), glm::vec2(a.x + w, a.y + ImGui::GetFrameHeight()));
  }
}

// After DragFloat3 / InputFloat4 and the like (n fields in one widget, default item width):
// also names each field "name/0" .. "name/n-1", laid out as ImGui 1.86 lays them out
// (PushMultiItemsWidths: equal widths, the last takes the rounding, inner spacing between).
// Call it where the widget's item width is still in force (no SetNextItemWidth before it).
inline void recordFields(const std::string& name, int n) {
  recordItem(name);
  ItemRects* rects = namedItems();
  if (!rects || n < 1) return;
  const ImGuiStyle& style = ImGui::GetStyle();
  const float full = ImGui::CalcItemWidth(), spacing = style.ItemInnerSpacing.x;
  const float one = std::max(1.0f, float(int((full - spacing * (n - 1)) / n)));
  const ImVec2 a = ImGui::GetItemRectMin();
  const float h = ImGui::GetFrameHeight();
  float x = a.x;
  for (int i = 0; i < n; ++i) {
    const float w = i + 1 < n ? one : std::max(1.0f, float(int(full - (one + spacing) * (n - 1))));
    rects->record(name + "/" + std::to_string(i), glm::vec2(x, a.y), glm::vec2(x + w, a.y + h));
    x += w + spacing;
  }
}

// After InputInt / InputFloat with step buttons: names the field "name", and its buttons
// "name/-" and "name/+" (square, frame-height buttons right of the field, as ImGui draws them).
// `width`: what SetNextItemWidth gave the widget, 0 for the default item width.
inline void recordStepper(const std::string& name, float width = 0.0f) {
  ItemRects* rects = namedItems();
  if (!rects) return;
  const ImGuiStyle& style = ImGui::GetStyle();
  const ImVec2 a = ImGui::GetItemRectMin();
  const float h = ImGui::GetFrameHeight(), full = width > 0.0f ? width : ImGui::CalcItemWidth();
  const float field = std::max(1.0f, full - 2.0f * (h + style.ItemInnerSpacing.x));
  rects->record(name, glm::vec2(a.x, a.y), glm::vec2(a.x + field, a.y + h));
  const float minus = a.x + field + style.ItemInnerSpacing.x, plus = minus + h + style.ItemInnerSpacing.x;
  rects->record(name + "/-", glm::vec2(minus, a.y), glm::vec2(minus + h, a.y + h));
  rects->record(name + "/+", glm::vec2(plus, a.y), glm::vec2(plus + h, a.y + h));
}

// ImGui::Combo with its entries named too: the closed combo is `name`, each entry in the open
// list `name/ENTRY` (so a script picks "Curve Editor/Interpolation/TCB"). Same look as Combo.
inline bool namedCombo(const char* id, const std::string& name, int* current, const char* const entries[], int count) {
  const bool open = ImGui::BeginCombo(id, *current >= 0 && *current < count ? entries[*current] : "",
                                      ImGuiComboFlags_HeightLargest);  // every entry in view, none scrolled out
  recordItem(name);
  if (!open) return false;
  bool changed = false;
  for (int i = 0; i < count; ++i) {
    ImGui::PushID(i);
    if (ImGui::Selectable(entries[i], i == *current) && i != *current) {
      *current = i;
      changed = true;
    }
    if (i == *current) ImGui::SetItemDefaultFocus();
    recordItem(name + "/" + entries[i]);
    ImGui::PopID();
  }
  ImGui::EndCombo();
  return changed;
}

}  // namespace kinema
