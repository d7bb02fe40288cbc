#pragma once
#include "core/math.h"
#include "editor/model/editor_state.h"
#include "editor/viewport/viewport_view.h"

namespace kinema {

class Keymap;
class ViewportTools;

// What a command runs on: the editor's state and the parts of the window it needs. The
// window fills one each frame and hands it to the input routing and the panels; tests make
// their own. A command never keeps it.
struct CommandContext {
  explicit CommandContext(EditorState& s) : state(s) {}
  EditorState& state;
  // The viewport's modal tools: tool.rotate / tool.grab start theirs here. Null: those
  // commands are disabled (a model-only test).
  ViewportTools* tools = nullptr;
  // The 3D view this frame (window pixels): framing fills its aspect, tools project into it.
  ViewportView view;
  glm::vec2 mouse{0.0f};  // the last mouse position, window pixels (a dope-sheet move starts there)
  // The active bindings, for the shortcuts menus and hints show; null: none shown.
  const Keymap* keymap = nullptr;
};

}  // namespace kinema
