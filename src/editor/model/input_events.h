#pragma once
#include <functional>
#include <string>
#include <vector>

#include "core/math.h"
#include "core/result.h"

namespace kinema {

// One input event, as the window's GLFW callbacks report it or as a --script file replays
// it. Both paths feed the same handler, so scripted tests exercise the real input code.
// Command (scripts only) runs a command of the editor by its id (commands/command_registry.h)
// as if its menu item or key had been used.
enum class InputEventType { MouseMove, ButtonDown, ButtonUp, KeyDown, KeyUp, Scroll, Text, Command };

// Modifier bits, the same values as GLFW's GLFW_MOD_*.
enum InputMods : int { kModShift = 1, kModCtrl = 2, kModAlt = 4, kModSuper = 8 };

struct InputEvent {
  long long frame = 0;  // the frame it is handled in (scripts); 0 for live events
  InputEventType type = InputEventType::MouseMove;
  float x = 0, y = 0;   // mouse position in window pixels (origin top left); scroll offsets
  int button = 0;       // 0 left, 1 right, 2 middle (GLFW's numbering)
  int key = -1;         // GLFW key code; see keyCodeFromName
  int mods = 0;         // InputMods bits
  std::string text;     // Text: UTF-8 characters typed; Command: the command's id
  // Scripts: a widget by name (model/item_rects.h); x, y are then the point `at` (fractions of
  // the widget's rectangle) where it was last drawn, filled in when the event is handled.
  std::string item;
  glm::vec2 at{0.5f, 0.5f};
};

// What the event stream says is held: scripts press modifier keys as their own key events
// (with no mods bits), GLFW sets the bits too; both count. Also the last mouse position,
// since button and key events carry none.
struct HeldInput {
  int mods = 0;             // InputMods bits of the modifier keys held down
  glm::vec2 mouse{0.0f};    // window pixels, origin top left
  // Takes in one event; returns its modifiers (the held keys' plus the event's own bits).
  int track(const InputEvent& e);
};
bool isModifierKey(int key);  // Shift, Ctrl, Alt, Super (left or right)

const char* toString(InputEventType type);  // "mouse_move", "button_down", ...
// GLFW key names without the GLFW_KEY_ prefix ("R", "LEFT_SHIFT", "KP_1", "ESCAPE") <-> codes.
int keyCodeFromName(const std::string& name);  // -1 when unknown
std::string keyNameFromCode(int code);         // "" when unknown

// Parses a script: a JSON array of events, or one JSON event object per line (blank lines
// and lines starting with # or // are skipped). See docs/cli.md for the fields. Events come
// back sorted by frame (stable). Errors name `source`, the event (and line) and the field.
// `isCommand` says whether a "command" event's id names a command (the model does not know
// the registry); without it every id is taken.
using CommandIdCheck = std::function<bool(const std::string& id)>;
Result<std::vector<InputEvent>> parseInputScript(const std::string& text, const std::string& source,
                                                 const CommandIdCheck& isCommand = nullptr);
Result<std::vector<InputEvent>> loadInputScript(const std::string& path, const CommandIdCheck& isCommand = nullptr);

}  // namespace kinema
