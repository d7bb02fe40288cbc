#pragma once
#include <map>
#include <string>

#include "core/math.h"

namespace kinema {

// Where each named widget was last drawn (window pixels, origin top left), so a --script can
// click a widget by its name ("View/Dope Sheet", "Timeline/Play") whatever the layout, and
// the state dump can list them. Names are ImGui-id-like paths: window or menu, then label.
struct ItemRect {
  glm::vec2 min{0.0f}, max{0.0f};
  long long frame = -1;  // the frame it was last drawn in
  glm::vec2 centre() const { return (min + max) * 0.5f; }
};

struct ItemRects {
  std::map<std::string, ItemRect> items;
  long long frame = 0;  // the frame being drawn (set by the window each frame)

  void record(const std::string& name, glm::vec2 min, glm::vec2 max) { items[name] = ItemRect{min, max, frame}; }
  // The rectangle drawn most recently under `name`; nullptr when it was never drawn.
  const ItemRect* find(const std::string& name) const {
    const auto it = items.find(name);
    return it == items.end() ? nullptr : &it->second;
  }
};

}  // namespace kinema
