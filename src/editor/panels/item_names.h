#pragma once
#include <imgui.h>

#include <string>

#include "editor/model/item_rects.h"

namespace kinema {

// Records the last ImGui item (the widget just drawn) under `name` in `rects`: call it right
// after the widget. The e2e tests and --script click widgets by these names.
inline void recordItem(ItemRects& rects, const std::string& name) {
  const ImVec2 a = ImGui::GetItemRectMin(), b = ImGui::GetItemRectMax();
  rects.record(name, glm::vec2(a.x, a.y), glm::vec2(b.x, b.y));
}

}  // namespace kinema
