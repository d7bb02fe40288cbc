#pragma once
#include <string>
#include <vector>

#include <imgui.h>

#include "render/pixel_rect.h"

namespace kinema {

// One frame's ImGui draw lists, copied, to find what the next frame draws differently.
struct ImGuiDrawSnapshot {
  struct List {
    std::string owner;  // the window's name (ImDrawList::_OwnerName)
    std::vector<ImDrawVert> vertices;
    std::vector<ImDrawIdx> indices;
    std::vector<ImDrawCmd> commands;
  };
  bool valid = false;
  ImVec2 displayPos{0, 0}, displaySize{0, 0};
  ImTextureID fontTexture = nullptr;
  std::vector<List> lists;
};

// The window pixels (ImGui's display coordinates, origin top left) where `now` draws
// differently from the frame `last` holds; replaces *last with a copy of `now`. Lists are
// matched window by window; in each, the triangles both frames draw alike at the start and
// at the end are skipped (what a changed value leaves of a panel). Between them, two runs of
// the same length are compared triangle by triangle and only the differing triangles count;
// runs of other lengths count whole. Counted triangles (in both frames) add their bounds,
// clipped to their commands' rectangles, to boxes joined when 16 pixels apart or closer, so
// one window may give several rectangles.
// Triangles with a texture other than `fontTexture` are taken as changed every frame (their
// picture may change without their vertices), as is everything after a user callback. The
// whole display when the windows, their order, the display or the font texture changed, or
// nothing was kept.
std::vector<PixelRect> imguiDamage(const ImDrawData& now, ImTextureID fontTexture, ImGuiDrawSnapshot& last);

}  // namespace kinema
