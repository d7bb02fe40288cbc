// The window's input feed (window/imgui_input_feed.h) without a window: a headless ImGui
// context, events queued as GLFW's callbacks queue them, frames run as the editor runs them.
// No press is lost: the editor's handlers get every event in queue order, and ImGui sees a
// tap of a key it reads (press and release within one frame) as a press in a frame of its own.
#include <gtest/gtest.h>
#include <imgui.h>

#include <deque>
#include <string>
#include <vector>

#include "editor/model/key_codes.h"
#include "editor/window/imgui_input_feed.h"

namespace kinema {
namespace KINEMA_UNITY_ID {

InputEvent key(InputEventType type, int code, int mods = 0) {
  InputEvent e;
  e.type = type;
  e.key = code;
  e.mods = mods;
  return e;
}
void tap(std::deque<InputEvent>& q, int code, int mods = 0) {
  q.push_back(key(InputEventType::KeyDown, code, mods));
  q.push_back(key(InputEventType::KeyUp, code, mods));
}
std::string describe(const InputEvent& e) {
  return std::string(toString(e.type)) + ":" + (e.type == InputEventType::Text ? e.text : keyNameFromCode(e.key));
}

class ImGuiInputFeed : public ::testing::Test {
 protected:
  void SetUp() override {
    ImGui::CreateContext();
    ImGuiIO& io = ImGui::GetIO();
    io.IniFilename = nullptr;
    io.DisplaySize = ImVec2(640, 480);
    io.DeltaTime = 1.0f / 5.0f;  // a 5 fps machine
    unsigned char* pixels = nullptr;
    int w = 0, h = 0;
    io.Fonts->GetTexDataAsRGBA32(&pixels, &w, &h);  // NewFrame needs a built font atlas
    mapImGuiKeys(io);
  }
  void TearDown() override { ImGui::DestroyContext(); }

  // One editor frame: this frame's share of the queue, then ImGui's frame, in which
  // `duringFrame` asks ImGui what it saw.
  template <typename F>
  int frame(bool imguiReadsKeys, F duringFrame) {
    const int n = feedFrameInput(queue, ImGui::GetIO(), imguiReadsKeys,
                                 [&](const InputEvent& e) { handled.push_back(describe(e)); });
    ImGui::NewFrame();
    duringFrame();
    ImGui::Render();
    return n;
  }
  int frame(bool imguiReadsKeys) {
    return frame(imguiReadsKeys, [] {});
  }

  std::deque<InputEvent> queue;
  std::vector<std::string> handled;  // what the editor's handlers got, in order
};

TEST_F(ImGuiInputFeed, TapOfAKeyImGuiReadsIsPressedInItsOwnFrameAndHandledInOrder) {
  // Esc pressed and released before the frame (a 12 ms tap at 5 fps), then Enter the same.
  tap(queue, keys::ESCAPE);
  tap(queue, keys::ENTER);
  std::vector<std::string> pressed;
  auto look = [&] {
    if (ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_Escape), false)) pressed.push_back("ESCAPE");
    if (ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_Enter), false)) pressed.push_back("ENTER");
  };
  // Frame 1: Esc goes down (its release would hide the press from ImGui: it waits).
  EXPECT_EQ(frame(true, look), 1);
  EXPECT_EQ(pressed, std::vector<std::string>{"ESCAPE"});
  // Frame 2: Esc up, Enter down; frame 3: Enter up.
  EXPECT_EQ(frame(true, look), 2);
  EXPECT_EQ(frame(true, look), 1);
  EXPECT_TRUE(queue.empty());
  EXPECT_EQ(pressed, (std::vector<std::string>{"ESCAPE", "ENTER"}));
  EXPECT_EQ(handled, (std::vector<std::string>{"key_down:ESCAPE", "key_up:ESCAPE", "key_down:ENTER", "key_up:ENTER"}));
}

TEST_F(ImGuiInputFeed, TapsImGuiDoesNotNeedAreAllHandledInOneFrame) {
  // 25 taps of Right while ImGui has neither the keyboard nor a popup: one frame takes them
  // all (the step-forward command runs 25 times), in order.
  std::vector<std::string> expected;
  for (int i = 0; i < 25; ++i) {
    tap(queue, keys::RIGHT);
    expected.push_back("key_down:RIGHT");
    expected.push_back("key_up:RIGHT");
  }
  EXPECT_EQ(frame(false), 50);
  EXPECT_EQ(handled, expected);
  EXPECT_FALSE(ImGui::GetIO().KeysDown[keys::RIGHT]);  // ImGui's state ends released
}

TEST_F(ImGuiInputFeed, CtrlShortcutTapsReachImGuiOneAFrameWhileItHasTheKeyboard) {
  // Three Ctrl+Z taps while a text field has the keyboard: ImGui's own undo sees each press.
  for (int i = 0; i < 3; ++i) {
    queue.push_back(key(InputEventType::KeyDown, keys::LEFT_CONTROL, kModCtrl));
    tap(queue, keys::Z, kModCtrl);
    queue.push_back(key(InputEventType::KeyUp, keys::LEFT_CONTROL));
  }
  const size_t total = queue.size();
  int presses = 0, frames = 0;
  while (!queue.empty() && frames < 20) {
    frame(true, [&] {
      if (ImGui::GetIO().KeyCtrl && ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_Z), false)) ++presses;
    });
    ++frames;
  }
  EXPECT_EQ(presses, 3);
  EXPECT_EQ(handled.size(), total);
  EXPECT_EQ(handled.front(), "key_down:LEFT_CONTROL");
  EXPECT_EQ(handled[1], "key_down:Z");
  EXPECT_EQ(handled[2], "key_up:Z");
}

TEST_F(ImGuiInputFeed, TypedTextArrivesWholeInOneFrameInOrder) {
  // "hello" typed faster than the frame rate into a field that has the keyboard: each
  // letter's key down, character and key up; the repeated L does not wait for a frame.
  for (char c : std::string("hello")) {
    const int code = keys::A + (c - 'a');
    queue.push_back(key(InputEventType::KeyDown, code));
    InputEvent text;
    text.type = InputEventType::Text;
    text.text = std::string(1, c);
    queue.push_back(text);
    queue.push_back(key(InputEventType::KeyUp, code));
  }
  EXPECT_EQ(feedFrameInput(queue, ImGui::GetIO(), true, [&](const InputEvent& e) { handled.push_back(describe(e)); }), 15);
  std::string typed;  // what ImGui's next frame hands to the focused text field
  for (ImWchar ch : ImGui::GetIO().InputQueueCharacters) typed += static_cast<char>(ch);
  EXPECT_EQ(typed, "hello");
  EXPECT_EQ(handled[1], "text:h");
  EXPECT_EQ(handled[13], "text:o");
}

TEST_F(ImGuiInputFeed, AClickWithinOneFrameIsAClickForImGui) {
  InputEvent move;
  move.type = InputEventType::MouseMove;
  move.x = 100;
  move.y = 50;
  InputEvent down = move, up = move;
  down.type = InputEventType::ButtonDown;
  up.type = InputEventType::ButtonUp;
  queue = {move, down, up};
  bool clicked = false, released = false;
  EXPECT_EQ(frame(false, [&] { clicked = ImGui::IsMouseClicked(ImGuiMouseButton_Left); }), 2);
  EXPECT_TRUE(clicked);
  EXPECT_EQ(frame(false, [&] { released = ImGui::IsMouseReleased(ImGuiMouseButton_Left); }), 1);
  EXPECT_TRUE(released);
  EXPECT_EQ(ImGui::GetIO().MousePos.x, 100.0f);
}

TEST(ImGuiReadsKeyTaps, NamedKeysModifiersAndCtrlShortcutsOnly) {
  EXPECT_TRUE(imguiReadsKeyTaps(keys::ESCAPE, 0));
  EXPECT_TRUE(imguiReadsKeyTaps(keys::BACKSPACE, 0));
  EXPECT_TRUE(imguiReadsKeyTaps(keys::LEFT_SHIFT, 0));
  EXPECT_TRUE(imguiReadsKeyTaps(keys::Z, kModCtrl));
  EXPECT_FALSE(imguiReadsKeyTaps(keys::Z, 0));  // a plain z reaches a text field as a character
  EXPECT_FALSE(imguiReadsKeyTaps(keys::R, kModCtrl));
  EXPECT_FALSE(imguiReadsKeyTaps(keys::KP_1, 0));
}

}  // namespace
}  // namespace kinema
