#pragma once
#include <string>
#include <vector>

#include "editor/commands/keymap.h"

namespace kinema {

// Help > Controls, the README's controls table, `kinema edit --list-commands` and the
// status-bar hints, all generated from the command registry and the active keymap, so
// none of them can drift from what the keys do. Mouse gestures and the keys of a running
// modal tool are not commands; they are listed beside them from one table here.

struct ControlRow {
  std::string keys;    // "Ctrl+Shift+Z, Ctrl+Y", "Left drag on empty space"; "" for an unbound command
  std::string action;  // the command's label, or what the gesture does
  std::string hint;    // the command's hint ("" when none)
  std::string menu;    // "Edit > Redo" when the command is in the main menu
  std::string id;      // the command's id; "" for a gesture
};
struct ControlGroup {
  std::string title;   // "Everywhere", "3D view", "Dope sheet (mouse over it)", ...
  std::vector<ControlRow> rows;
};

// Every command, grouped by scope in registry order (the scope's mouse gestures first),
// and what a running modal tool takes.
std::vector<ControlGroup> controlsTable(const Keymap& keymap);
// The same as markdown: a "### title" and a | Keys | Action | Menu | Command | table per group.
std::string controlsMarkdown(const Keymap& keymap);

// One line for the status bar: what the running tool, the open mode or the current
// selection accepts, with the active keymap's chords ("R Rotate, G Move Root, ...").
std::string statusHint(const EditorState& state, const Keymap& keymap);

}  // namespace kinema
