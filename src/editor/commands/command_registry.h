#pragma once
#include <functional>
#include <string>
#include <vector>

#include "editor/commands/command_context.h"
#include "editor/commands/key_chord.h"

namespace kinema {

// Where a command's keys apply. A key pressed over the dope sheet or the curve editor goes
// to that editor's commands first, over the 3D view to the viewport's; Global commands
// apply everywhere after those. While Teach > Compare Solvers is open, its commands take
// the keys and then the Global ones (editor_input.h keyScopes). In lattice edit mode (Tab)
// the 3D view's keys go to LatticeEdit first, so G, I and A act on the lattice's points, not
// on the joints. A Property command takes its key while the mouse is over a keyable field
// of the Properties panel (I keys that property, as in Blender).
enum class CommandScope { Global, Viewport, DopeSheet, CurveEditor, Compare, LatticeEdit, Property };
const char* toString(CommandScope scope);      // "global", "viewport", ...
const char* scopeTitle(CommandScope scope);    // "Everywhere", "3D view", "Dope sheet", ...

// One user action by name: the main menu, keys, panel buttons, Help > Controls, the
// status-bar hints and --script command events all run it through here.
struct Command {
  std::string id;     // "file.save", "pose.pin_ik_target": area, then what it does
  std::string label;  // "Save", "Pin IK Target": the menu item's text
  // Where it appears in the main menu: "File", "File/Export" (a submenu); "" for none.
  // Items keep the registry's order; separatorBefore draws a line above the item.
  std::string menu;
  bool separatorBefore = false;
  std::vector<KeyChord> keys;  // the default chords; the keymap may change them
  CommandScope scope = CommandScope::Global;
  std::string hint;  // what it does, one line for Help > Controls ("" : the label says it)
  // Whether it can run now (null: always). A disabled command's menu item is greyed and its
  // key falls through to the next scope.
  std::function<bool(const CommandContext&)> enabled;
  // For toggles: whether it is on (a check mark in the menu). Null: not a toggle.
  std::function<bool(const CommandContext&)> checked;
  std::function<void(CommandContext&)> run;

  bool isEnabled(const CommandContext& ctx) const { return !enabled || enabled(ctx); }
  bool isChecked(const CommandContext& ctx) const { return checked && checked(ctx); }
};

// The commands, in menu order. Ids are unique.
class CommandRegistry {
 public:
  // "" or why not: an empty id or label, an id already there, or no run function.
  std::string add(Command command);
  const Command* find(const std::string& id) const;  // nullptr when no command has the id
  const std::vector<Command>& all() const { return commands_; }

 private:
  std::vector<Command> commands_;
};

// Every command of the editor (built once; commands/*_commands.cpp define them by area).
const CommandRegistry& editorCommands();

// Runs `id` when it exists and is enabled. Returns "" when it ran, else one line saying why
// not ("no command 'x'", "Pin IK Target is not available now").
std::string runCommand(const CommandRegistry& registry, const std::string& id, CommandContext& ctx);

}  // namespace kinema
