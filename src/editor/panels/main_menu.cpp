// The main menu bar (Blender's header menus reduced to pose mode), drawn from the command
// registry: each command with a menu path is an item there, in the registry's order, with
// the active keymap's shortcut. The keys themselves are dispatched by the window's input
// routing (commands/editor_input.h), not here. Two entries are not commands: File > Open
// Recent (one item per recent file), the Pose menu's chain-length slider and the Clip
// menu's list of clips.
#include <imgui.h>

#include <algorithm>

#include "editor/commands/keymap.h"
#include "editor/panels/command_widgets.h"
#include "editor/panels/editor_panels.h"
#include "editor/panels/item_names.h"
#include "editor/panels/panel_layout.h"

namespace kinema {

namespace {

const CommandRegistry& registryOf(const CommandContext& ctx) {
  return ctx.keymap ? ctx.keymap->registry() : editorCommands();
}

// What the menus hold besides commands, drawn right after the command `id`.
void drawExtrasAfter(CommandContext& ctx, const std::string& id) {
  EditorState& state = ctx.state;
  PanelState& p = state.panels;
  if (id == "file.open") {
    const bool open = ImGui::BeginMenu("Open Recent", !p.recent.entries().empty());
    if (!open) recordItem(state.items, "File/Open Recent");
    if (open) {
      for (const std::string& path : p.recent.entries()) {
        const bool clicked = ImGui::MenuItem(path.c_str());
        recordItem(state.items, "File/Open Recent/" + path);
        if (clicked) requestOpenPath(state, path);
      }
      ImGui::EndMenu();
    }
  } else if (id == "pose.pin_ik_target") {
    // The chain length new IK targets get (Add IK Target, Shift+I, the IK panel).
    ImGui::SetNextItemWidth(scaled(state, 80));
    ImGui::SliderInt("Chain length", &p.ikChainLength, 1, 8);
    recordItem(state.items, "Pose/Chain length");
  } else if (id == "clip.next") {
    drawClipMenuList(ctx);  // the clips by name, the active one checked
  }
}

// The items of menu `path` ("File", "File/Export"): its commands in registry order, a
// submenu where the first command of one comes.
void drawMenuItems(CommandContext& ctx, const std::string& path) {
  const std::vector<Command>& all = registryOf(ctx).all();
  std::vector<std::string> submenusDrawn;
  bool first = true;
  for (const Command& c : all) {
    const bool here = c.menu == path;
    const bool inSubmenu = c.menu.size() > path.size() + 1 && c.menu.compare(0, path.size() + 1, path + "/") == 0;
    if (!here && !inSubmenu) continue;
    if (c.separatorBefore && !first) ImGui::Separator();
    first = false;
    if (here) {
      commandMenuItem(ctx, c, path + "/" + c.label);
      drawExtrasAfter(ctx, c.id);
      continue;
    }
    const std::string sub = c.menu.substr(0, c.menu.find('/', path.size() + 1));
    if (std::find(submenusDrawn.begin(), submenusDrawn.end(), sub) != submenusDrawn.end()) continue;
    submenusDrawn.push_back(sub);
    const bool open = ImGui::BeginMenu(sub.substr(path.size() + 1).c_str());
    if (!open) recordItem(ctx.state.items, sub);  // an open one's last item is its popup
    if (open) {
      drawMenuItems(ctx, sub);
      ImGui::EndMenu();
    }
  }
}

// The top-level menus in the order their first command comes: File, Edit, View, ...
std::vector<std::string> menuTitles(const CommandRegistry& registry) {
  std::vector<std::string> titles;
  for (const Command& c : registry.all()) {
    if (c.menu.empty()) continue;
    const std::string title = c.menu.substr(0, c.menu.find('/'));
    if (std::find(titles.begin(), titles.end(), title) == titles.end()) titles.push_back(title);
  }
  return titles;
}

}  // namespace

void drawMainMenuBar(CommandContext& ctx) {
  if (!ImGui::BeginMainMenuBar()) return;
  EditorState& state = ctx.state;
  for (const std::string& title : menuTitles(registryOf(ctx))) {
    // The title's rectangle from the bar's cursor before and after it: once a menu is open
    // ImGui's last item is its popup, not the title.
    const ImVec2 before = ImGui::GetCursorScreenPos();
    if (ImGui::BeginMenu(title.c_str())) {
      drawMenuItems(ctx, title);
      ImGui::EndMenu();
    }
    const float top = ImGui::GetWindowPos().y;
    state.items.record(title, glm::vec2(before.x, top),
                       glm::vec2(ImGui::GetCursorScreenPos().x - ImGui::GetStyle().ItemSpacing.x,
                                 top + ImGui::GetWindowHeight()));
  }
  // The file's name and a dirty marker at the right end of the bar.
  const std::string name = documentTitle(state) + (state.doc.dirty() ? " *" : "");
  ImGui::SameLine(ImGui::GetWindowWidth() - ImGui::CalcTextSize(name.c_str()).x - 12);
  ImGui::TextDisabled("%s", name.c_str());
  ImGui::EndMainMenuBar();
}

}  // namespace kinema
