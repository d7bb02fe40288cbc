#include "editor/window/imgui_input_feed.h"

#include <imgui.h>

#include <algorithm>
#include <utility>
#include <vector>

#include "editor/model/key_codes.h"

namespace kinema {

namespace {

// ImGui's named keys and the GLFW codes that drive them (model/key_codes.h copies GLFW's).
const std::pair<ImGuiKey, int> kImGuiKeys[] = {
    {ImGuiKey_Tab, keys::TAB},         {ImGuiKey_LeftArrow, keys::LEFT},   {ImGuiKey_RightArrow, keys::RIGHT},
    {ImGuiKey_UpArrow, keys::UP},      {ImGuiKey_DownArrow, keys::DOWN},   {ImGuiKey_PageUp, keys::PAGE_UP},
    {ImGuiKey_PageDown, keys::PAGE_DOWN}, {ImGuiKey_Home, keys::HOME},     {ImGuiKey_End, keys::END},
    {ImGuiKey_Insert, keys::INSERT},   {ImGuiKey_Delete, keys::DELETE},    {ImGuiKey_Backspace, keys::BACKSPACE},
    {ImGuiKey_Space, keys::SPACE},     {ImGuiKey_Enter, keys::ENTER},      {ImGuiKey_Escape, keys::ESCAPE},
    {ImGuiKey_KeyPadEnter, keys::KP_ENTER}, {ImGuiKey_A, keys::A},         {ImGuiKey_C, keys::C},
    {ImGuiKey_V, keys::V},             {ImGuiKey_X, keys::X},              {ImGuiKey_Y, keys::Y},
    {ImGuiKey_Z, keys::Z},
};

bool isShortcutLetter(int key) {
  return key == keys::A || key == keys::C || key == keys::V || key == keys::X || key == keys::Y || key == keys::Z;
}

}  // namespace

void mapImGuiKeys(ImGuiIO& io) {
  for (const auto& [imguiKey, code] : kImGuiKeys) io.KeyMap[imguiKey] = code;
}

bool imguiReadsKeyTaps(int key, int mods) {
  if (isModifierKey(key)) return true;
  if (isShortcutLetter(key)) return (mods & (kModCtrl | kModSuper)) != 0;
  for (const auto& [imguiKey, code] : kImGuiKeys)
    if (code == key) return true;
  return false;
}

void feedImGuiEvent(ImGuiIO& io, const InputEvent& e) {
  switch (e.type) {
    case InputEventType::MouseMove: io.MousePos = ImVec2(e.x, e.y); break;
    case InputEventType::ButtonDown:
    case InputEventType::ButtonUp:
      if (e.button >= 0 && e.button < IM_ARRAYSIZE(io.MouseDown)) io.MouseDown[e.button] = e.type == InputEventType::ButtonDown;
      break;
    case InputEventType::Scroll:
      io.MouseWheelH += e.x;
      io.MouseWheel += e.y;
      break;
    case InputEventType::KeyDown:
    case InputEventType::KeyUp:
      if (e.key >= 0 && e.key < IM_ARRAYSIZE(io.KeysDown)) io.KeysDown[e.key] = e.type == InputEventType::KeyDown;
      io.KeyCtrl = io.KeysDown[keys::LEFT_CONTROL] || io.KeysDown[keys::RIGHT_CONTROL] || (e.mods & kModCtrl);
      io.KeyShift = io.KeysDown[keys::LEFT_SHIFT] || io.KeysDown[keys::RIGHT_SHIFT] || (e.mods & kModShift);
      io.KeyAlt = io.KeysDown[keys::LEFT_ALT] || io.KeysDown[keys::RIGHT_ALT] || (e.mods & kModAlt);
      io.KeySuper = io.KeysDown[keys::LEFT_SUPER] || io.KeysDown[keys::RIGHT_SUPER] || (e.mods & kModSuper);
      break;
    case InputEventType::Text: io.AddInputCharactersUTF8(e.text.c_str()); break;
    case InputEventType::Command: break;  // a script's command: not ImGui's
  }
}

int feedFrameInput(std::deque<InputEvent>& queue, ImGuiIO& io, bool imguiReadsKeys,
                   const std::function<void(const InputEvent&)>& dispatch,
                   const std::function<bool(std::deque<InputEvent>&)>& prepare) {
  bool buttonChanged[IM_ARRAYSIZE(io.MouseDown)] = {};
  std::vector<int> keysChanged;  // keys ImGui reads that went down or up in this frame
  HeldInput held;                // the modifiers as of each event (shortcut letters need Ctrl)
  held.mods = (io.KeyCtrl ? kModCtrl : 0) | (io.KeyShift ? kModShift : 0) | (io.KeyAlt ? kModAlt : 0) |
              (io.KeySuper ? kModSuper : 0);
  int handled = 0;
  while (!queue.empty()) {
    if (prepare && !prepare(queue)) break;
    if (queue.empty()) break;
    const InputEvent& e = queue.front();
    const int mods = held.track(e);
    if ((e.type == InputEventType::ButtonDown || e.type == InputEventType::ButtonUp) && e.button >= 0 &&
        e.button < IM_ARRAYSIZE(io.MouseDown)) {
      if (buttonChanged[e.button]) break;
      buttonChanged[e.button] = true;
    }
    if ((e.type == InputEventType::KeyDown || e.type == InputEventType::KeyUp) && imguiReadsKeys &&
        imguiReadsKeyTaps(e.key, mods)) {
      if (std::find(keysChanged.begin(), keysChanged.end(), e.key) != keysChanged.end()) break;
      keysChanged.push_back(e.key);
    }
    feedImGuiEvent(io, e);
    dispatch(e);
    queue.pop_front();
    ++handled;
  }
  return handled;
}

}  // namespace kinema
