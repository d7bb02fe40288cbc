#pragma once
#include <deque>
#include <functional>

#include "editor/model/input_events.h"

struct ImGuiIO;

namespace kinema {

// Dear ImGui 1.86 has no input queue: it samples io.KeysDown / io.MouseDown once per frame,
// so it sees a press only if the key is still down at the next NewFrame. The editor's own
// handlers (tools, keymap commands) take events one by one and lose nothing; ImGui needs a
// press and a release of one key or button in different frames only when it reads them.

// Sets io.KeyMap (ImGui's named keys read through io.KeysDown, indexed by GLFW key codes).
void mapImGuiKeys(ImGuiIO& io);

// Whether ImGui acts on taps of `key` with modifiers `mods` (InputMods bits): its mapped keys
// (Tab, arrows, Home/End, Delete, Backspace, Enter, Esc...), the modifiers, and the letters
// of its shortcuts (Ctrl+A/C/V/X/Y/Z) with Ctrl or Super held. Plain letters reach text
// fields as characters, not as key taps.
bool imguiReadsKeyTaps(int key, int mods);

// Feeds one event to ImGui's IO (mouse position, buttons, wheel, keys, modifiers, UTF-8 text).
void feedImGuiEvent(ImGuiIO& io, const InputEvent& e);

// One frame's share of the queued events, fed to ImGui and then to `dispatch` one by one in
// queue order. The frame stops before an event that would undo a change ImGui has to see
// (the release of a button pressed this frame; of a key it reads, while `imguiReadsKeys`:
// it has the keyboard or a popup open, or a panel gesture polls Esc / Enter through it);
// that event and the rest wait for the next frame. A
// tap of a key ImGui does not read is handled at once, so keymap commands keep pace with the
// fastest typing at any frame rate. `prepare` (optional) runs on the front event before it
// is judged (a script's widget name becomes a position; it may push a move in front) and
// returns false to stop the frame. Returns how many events were handled.
int feedFrameInput(std::deque<InputEvent>& queue, ImGuiIO& io, bool imguiReadsKeys,
                   const std::function<void(const InputEvent&)>& dispatch,
                   const std::function<bool(std::deque<InputEvent>&)>& prepare = nullptr);

}  // namespace kinema
