#include "editor/panels/command_widgets.h"

#include "editor/commands/keymap.h"
#include "editor/panels/item_names.h"

namespace kinema {

namespace {

const Command* commandOf(const std::string& id) {
  const Command* c = editorCommands().find(id);
  IM_ASSERT(c && "a panel names a command the registry does not have");
  return c;
}

}  // namespace

void commandMenuItem(CommandContext& ctx, const Command& c, const std::string& itemName) {
  const std::string shortcut = ctx.keymap ? ctx.keymap->shortcut(c.id) : std::string();
  const bool clicked =
      ImGui::MenuItem(c.label.c_str(), shortcut.empty() ? nullptr : shortcut.c_str(), c.isChecked(ctx), c.isEnabled(ctx));
  recordItem(ctx.state.items, itemName);
  if (clicked) c.run(ctx);
}

bool commandButton(CommandContext& ctx, const std::string& id, const std::string& window, const char* shown, ImVec2 size) {
  const Command* c = commandOf(id);
  const bool enabled = c && c->isEnabled(ctx);
  ImGui::BeginDisabled(!enabled);
  const bool clicked = ImGui::Button(shown ? shown : c ? c->label.c_str() : id.c_str(), size);
  ImGui::EndDisabled();
  if (!c) return false;
  recordItem(ctx.state.items, window + "/" + c->label);
  if (clicked && enabled) c->run(ctx);
  return clicked && enabled;
}

bool commandSelectable(CommandContext& ctx, const std::string& id, const std::string& window, const char* shown,
                       ImVec2 size) {
  const Command* c = commandOf(id);
  const bool enabled = c && c->isEnabled(ctx);
  ImGui::BeginDisabled(!enabled);
  const bool clicked = ImGui::Selectable(shown, c && c->isChecked(ctx), 0, size);
  ImGui::EndDisabled();
  if (!c) return false;
  recordItem(ctx.state.items, window + "/" + c->label);
  if (clicked && enabled) c->run(ctx);
  return clicked && enabled;
}

}  // namespace kinema
