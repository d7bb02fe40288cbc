#pragma once
#include <imgui.h>

#include <string>

#include "editor/commands/command_registry.h"

namespace kinema {

// ImGui widgets that run a command of the registry (editorCommands()), so a button, its
// menu item and its key do the same thing. Each is drawn greyed while the command is
// disabled and recorded in state.items under "WINDOW/LABEL" (the command's label) for
// scripts that click by name (item_names.h).

// A main-menu item: the label, the active keymap's first chord as its shortcut, a check
// mark for toggles. `itemName`: "File/Save".
void commandMenuItem(CommandContext& ctx, const Command& command, const std::string& itemName);
// A button showing `shown` (default: the command's label). True when it was clicked (and
// the command ran).
bool commandButton(CommandContext& ctx, const std::string& id, const std::string& window, const char* shown = nullptr,
                   ImVec2 size = ImVec2(0, 0));
// A selectable drawn selected while the (toggle) command is checked.
bool commandSelectable(CommandContext& ctx, const std::string& id, const std::string& window, const char* shown,
                       ImVec2 size = ImVec2(0, 0));

}  // namespace kinema
