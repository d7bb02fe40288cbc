#pragma once
#include <vector>

#include "editor/commands/command_registry.h"
#include "editor/commands/keymap.h"
#include "editor/model/input_events.h"
#include "render/skeleton_draw_list.h"

namespace kinema {

// Where a key-down is looked up, in order: the scope under the mouse (the dope sheet or
// curve editor when over them, else the 3D view), then Global; Teach > Compare Solvers'
// own keys, then Global, while that mode is open. Over the 3D view, lattice edit mode's
// keys come before the viewport's, and before those the Properties field under the mouse
// (I keys it) when there is one. None while a dope-sheet or curve-editor
// mouse gesture runs (its Esc / Enter are the panel's).
std::vector<CommandScope> keyScopes(const EditorState& state, glm::vec2 mouse);

// Runs the command `keymap` binds to `chord` in the first of `scopes` where one is bound
// and enabled (a disabled one lets the key through to the next scope). Returns it, or
// nullptr when none ran.
const Command* runChord(const Keymap& keymap, CommandContext& ctx, KeyChord chord, const std::vector<CommandScope>& scopes);

// Every input event of the editor, live or from a --script, in one place:
// - Teach > Compare Solvers (while open) or the viewport's tools (ctx.tools) see the mouse,
//   and a running modal tool takes every key;
// - any other key-down that ImGui does not want (keyboardCaptured: a text field or modal
//   popup has the keyboard) runs the command ctx.keymap binds to it (runChord, keyScopes);
// - a script's command event runs its command by id.
class EditorInput {
 public:
  // `list`: the skeleton as drawn last frame (picking). `mouseCaptured` / `keyboardCaptured`:
  // ImGui wants the mouse / keyboard (as of the frame the user saw).
  void handle(CommandContext& ctx, const InputEvent& e, const SkeletonDrawList& list, bool mouseCaptured,
              bool keyboardCaptured);
  const HeldInput& held() const { return held_; }

 private:
  HeldInput held_;
};

}  // namespace kinema
