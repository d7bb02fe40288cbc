#pragma once
#include <map>
#include <set>
#include <string>
#include <vector>

#include "editor/commands/command_registry.h"

namespace kinema {

// The active key bindings: each command's default chords (command_registry.h) as a user
// keymap file overrides them, like Blender's keymap preferences. A chord runs at most one
// command per scope.
//
// The file, $XDG_CONFIG_HOME/kinema/keymap.txt (or ~/.config/kinema/keymap.txt), has one
// binding a line; '#' starts a comment:
//   tool.rotate = Shift+R      # the first line naming a command replaces its default keys,
//   tool.rotate = F9           # later ones add more
//   view.cycle_bones = none    # no key at all
// A bad line (unknown command, a chord that does not parse, a chord another command of the
// same scope holds) is reported as "FILE:LINE: why" and skipped; the other lines apply.
class Keymap {
 public:
  explicit Keymap(const CommandRegistry& registry = editorCommands());  // the defaults

  const CommandRegistry& registry() const { return *registry_; }
  // Applies a keymap file's text; returns its problems, one line each.
  std::vector<std::string> apply(const std::string& text, const std::string& source);

  // "" or why not: an unknown command, an invalid chord, or one another command of the
  // same scope holds (Keymap::holder).
  std::string bind(const std::string& id, KeyChord chord);
  void unbind(const std::string& id);  // every chord of the command
  // The command of `scope` bound to `chord`, nullptr when none.
  const Command* holder(CommandScope scope, KeyChord chord) const;

  const std::vector<KeyChord>& chords(const std::string& id) const;  // empty when none
  std::string shortcut(const std::string& id) const;  // the first chord as text ("" when none)
  // Every chord as text, joined by `separator` ("Ctrl+Shift+Z, Ctrl+Y").
  std::string shortcuts(const std::string& id, const std::string& separator = ", ") const;

 private:
  const CommandRegistry* registry_;
  std::map<std::string, std::vector<KeyChord>> bindings_;  // command id -> chords, in order
};

// kinemaConfigDir()/keymap.txt; "" when no config folder is known.
std::string userKeymapPath();
// The defaults overridden by the user's keymap file when there is one (none is no problem);
// problems ("FILE:LINE: why", or an unreadable file) are appended to `problems`.
Keymap loadUserKeymap(const CommandRegistry& registry, std::vector<std::string>& problems);

}  // namespace kinema
