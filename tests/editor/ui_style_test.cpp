// The editor's look (issue 39, item 9): menus, popups and floating windows are opaque in
// every theme, so panel text behind them does not read through. ImGui's own themes draw
// window and popup backgrounds at 94 % opacity.
#include <gtest/gtest.h>
#include <imgui.h>

#include "editor/window/ui_style.h"

namespace kinema {
namespace KINEMA_UNITY_ID {

TEST(UiStyle, MenusPopupsAndWindowsAreOpaqueInEveryTheme) {
  ImGui::CreateContext();
  for (const UiTheme theme : {UiTheme::Dark, UiTheme::Light, UiTheme::Classic}) {
    UiStyle style;
    style.update(1.0f, 1.0f, theme, "");  // the built-in font: no file needed
    const ImGuiStyle& s = ImGui::GetStyle();
    EXPECT_EQ(s.Colors[ImGuiCol_WindowBg].w, 1.0f) << toString(theme);
    EXPECT_EQ(s.Colors[ImGuiCol_PopupBg].w, 1.0f) << toString(theme);
    EXPECT_EQ(s.Colors[ImGuiCol_MenuBarBg].w, 1.0f) << toString(theme);
  }
  ImGui::DestroyContext();
}

}  // namespace
}  // namespace kinema
