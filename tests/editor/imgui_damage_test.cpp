// Changed-only redraws of the panels (issue 20): imguiDamage finds where a frame's ImGui
// draw lists differ from the previous frame's, and clipImGuiDrawList limits drawing to those
// rectangles. Widget rectangles come from ImGui itself (GetItemRectMin/Max), not from the
// code under test.
#include <gtest/gtest.h>
#include <imgui.h>

#include <string>
#include <vector>

#include "editor/imgui_test_context.h"
#include "editor/window/imgui_backends.h"
#include "editor/window/imgui_damage.h"

namespace kinema {
namespace KINEMA_UNITY_ID {

const ImTextureID kFont = reinterpret_cast<ImTextureID>(static_cast<intptr_t>(7));

struct ImGuiFrames {
  test::ImGuiTestContext context{kFont};
  // A panel of 12 lines, line `changed` (and `alsoChanged`) showing `value`; a second window
  // when `extra`. Returns the rectangles of lines 0, `changed` and 11 as drawn (and of
  // `alsoChanged` and of the line halfway between the two, when given).
  std::vector<PixelRect> frame(int changed, float value, bool extra = false, int alsoChanged = -1) {
    ImGui::NewFrame();
    ImGui::SetNextWindowPos(ImVec2(20, 30));
    ImGui::SetNextWindowSize(ImVec2(300, 400));
    ImGui::Begin("Properties");
    std::vector<PixelRect> lines;
    for (int k = 0; k < 12; ++k) {
      ImGui::Text("rotation %d: %.3f", k, k == changed || k == alsoChanged ? value : 0.0f);
      if (k == 0 || k == changed || k == 11 || (alsoChanged >= 0 && (k == alsoChanged || k == (changed + alsoChanged) / 2))) {
        const ImVec2 a = ImGui::GetItemRectMin(), b = ImGui::GetItemRectMax();
        lines.push_back(PixelRect{int(a.x), int(a.y), int(b.x), int(b.y)});
      }
    }
    ImGui::End();
    if (extra) {
      ImGui::SetNextWindowPos(ImVec2(400, 30));
      ImGui::Begin("Another");
      ImGui::Text("new");
      ImGui::End();
    }
    ImGui::Render();
    return lines;
  }
};

PixelRect unionOf(const std::vector<PixelRect>& rects) {
  PixelRect u;
  for (const PixelRect& r : rects) u = u.united(r);
  return u;
}

TEST(ImGuiDamage, AChangedValueDamagesItsLineAloneAndTheSameFrameNothing) {
  ImGuiFrames imgui;
  ImGuiDrawSnapshot last;
  imgui.frame(5, 1.0f);
  const PixelRect display{0, 0, 800, 600};
  EXPECT_EQ(unionOf(imguiDamage(*ImGui::GetDrawData(), kFont, last)), display) << "nothing kept: everything";
  // A new window settles in its first frames (it sizes itself); then frames repeat exactly.
  for (int settle = 0; settle < 2; ++settle) {
    imgui.frame(5, 1.0f);
    imguiDamage(*ImGui::GetDrawData(), kFont, last);
  }
  imgui.frame(5, 1.0f);
  EXPECT_TRUE(imguiDamage(*ImGui::GetDrawData(), kFont, last).empty());
  const std::vector<PixelRect> lines = imgui.frame(5, 2.5f);
  const std::vector<PixelRect> damage = imguiDamage(*ImGui::GetDrawData(), kFont, last);
  ASSERT_EQ(damage.size(), 1u);
  // The digits that changed lie inside the line; the damage is inside it and nowhere else.
  EXPECT_TRUE(lines[1].grown(1).contains(damage[0])) << damage[0].x0 << "," << damage[0].y0 << " " << damage[0].x1 << ","
                                                     << damage[0].y1;
  EXPECT_FALSE(damage[0].intersects(lines[0]));
  EXPECT_FALSE(damage[0].intersects(lines[2]));
  EXPECT_GT(damage[0].area(), 0);
}

// Two values far apart in one window (a moved playhead and the frame number it shows, on a
// timeline) damage two small rectangles, not the box around both.
TEST(ImGuiDamage, TwoChangesFarApartInAWindowDamageTwoRectangles) {
  ImGuiFrames imgui;
  ImGuiDrawSnapshot last;
  for (int settle = 0; settle < 3; ++settle) {
    imgui.frame(2, 1.0f, false, 10);
    imguiDamage(*ImGui::GetDrawData(), kFont, last);
  }
  // Lines 0, 2, 6 (between), 10, 11 in their order of drawing.
  const std::vector<PixelRect> lines = imgui.frame(2, 2.5f, false, 10);
  ASSERT_EQ(lines.size(), 5u);
  const std::vector<PixelRect> damage = imguiDamage(*ImGui::GetDrawData(), kFont, last);
  ASSERT_EQ(damage.size(), 2u);
  const PixelRect& first = damage[0].y0 < damage[1].y0 ? damage[0] : damage[1];
  const PixelRect& second = damage[0].y0 < damage[1].y0 ? damage[1] : damage[0];
  EXPECT_TRUE(lines[1].grown(1).contains(first));
  EXPECT_TRUE(lines[3].grown(1).contains(second));
  EXPECT_FALSE(first.intersects(lines[2]) || second.intersects(lines[2])) << "the line between did not change";
}

TEST(ImGuiDamage, ANewWindowOrADifferentDisplayDamagesEverything) {
  ImGuiFrames imgui;
  ImGuiDrawSnapshot last;
  imgui.frame(5, 1.0f);
  imguiDamage(*ImGui::GetDrawData(), kFont, last);
  // The new window is drawn from its second frame (ImGui sizes it first): by then, everything.
  std::vector<PixelRect> damage;
  for (int n = 0; n < 3; ++n) {
    imgui.frame(5, 1.0f, true);
    for (const PixelRect& r : imguiDamage(*ImGui::GetDrawData(), kFont, last)) damage.push_back(r);
  }
  EXPECT_EQ(unionOf(damage), (PixelRect{0, 0, 800, 600}));
  ImGui::GetIO().DisplaySize = ImVec2(640, 480);
  imgui.frame(5, 1.0f, true);
  EXPECT_EQ(unionOf(imguiDamage(*ImGui::GetDrawData(), kFont, last)), (PixelRect{0, 0, 640, 480}));
  // Another font texture (the atlas rebuilt at a new UI scale): everything.
  imgui.frame(5, 1.0f, true);
  EXPECT_EQ(unionOf(imguiDamage(*ImGui::GetDrawData(), reinterpret_cast<ImTextureID>(static_cast<intptr_t>(8)), last)),
            (PixelRect{0, 0, 640, 480}));
}

// A picture from another texture (a kept 3D view, a plot) may change without its triangles
// changing: a window that draws one counts as changed every frame, even drawn exactly alike.
TEST(ImGuiDamage, AnImageCountsAsChangedEvenWhenDrawnAlike) {
  test::ImGuiTestContext context{kFont};
  ImGuiDrawSnapshot last;
  const ImTextureID picture = reinterpret_cast<ImTextureID>(static_cast<intptr_t>(9));
  PixelRect image, text;
  auto frame = [&] {
    ImGui::NewFrame();
    ImGui::SetNextWindowPos(ImVec2(20, 30));
    ImGui::SetNextWindowSize(ImVec2(300, 300));
    ImGui::Begin("Plot");
    ImGui::Text("a caption");
    text = PixelRect{int(ImGui::GetItemRectMin().x), int(ImGui::GetItemRectMin().y), int(ImGui::GetItemRectMax().x),
                     int(ImGui::GetItemRectMax().y)};
    ImGui::Image(picture, ImVec2(100, 80));
    image = PixelRect{int(ImGui::GetItemRectMin().x), int(ImGui::GetItemRectMin().y), int(ImGui::GetItemRectMax().x),
                      int(ImGui::GetItemRectMax().y)};
    ImGui::End();
    ImGui::Render();
    return imguiDamage(*ImGui::GetDrawData(), kFont, last);
  };
  for (int settle = 0; settle < 3; ++settle) frame();
  const std::vector<PixelRect> damage = frame();
  ASSERT_FALSE(damage.empty());
  EXPECT_TRUE(unionOf(damage).contains(image.grown(-1)));
  EXPECT_FALSE(unionOf(damage).intersects(text)) << "the caption, a font draw, is alike";
}

TEST(ImGuiDamage, ClippingKeepsTheTrianglesThatMeetEachRectangleInsideItAndDropsTheRest) {
  // Command a: two triangles, one at (0..10, 0..10), one at (60..70, 60..70), clipped to
  // (0, 0, 100, 100); command b: one triangle at (250..260, 250..260), clipped to
  // (200, 200, 300, 300).
  ImDrawList list(nullptr);
  auto vertex = [&](float x, float y) {
    ImDrawVert v{};
    v.pos = ImVec2(x, y);
    list.VtxBuffer.push_back(v);
  };
  for (float o : {0.0f, 60.0f, 250.0f}) vertex(o, o), vertex(o + 10, o), vertex(o, o + 10);
  for (ImDrawIdx i = 0; i < 9; ++i) list.IdxBuffer.push_back(i);
  ImDrawCmd a, b;
  a.ClipRect = ImVec4(0, 0, 100, 100);
  a.ElemCount = 6;
  b.ClipRect = ImVec4(200, 200, 300, 300);
  b.IdxOffset = 6;
  b.ElemCount = 3;
  list.CmdBuffer.push_back(a);
  list.CmdBuffer.push_back(b);
  // The first rectangle meets a's second triangle only, the second a's first only; b meets none.
  const std::vector<ImVec4> rects{ImVec4(50, 50, 120, 70), ImVec4(5, 5, 20, 500)};
  clipImGuiDrawList(list, rects);
  ASSERT_EQ(list.CmdBuffer.Size, 2);
  const ImDrawCmd& first = list.CmdBuffer[0];
  const ImDrawCmd& second = list.CmdBuffer[1];
  EXPECT_EQ(first.ClipRect.x, 50);
  EXPECT_EQ(first.ClipRect.z, 100);
  EXPECT_EQ(first.ClipRect.w, 70);
  ASSERT_EQ(first.ElemCount, 3u);
  EXPECT_EQ(list.IdxBuffer[static_cast<int>(first.IdxOffset)], 3);  // a's second triangle
  EXPECT_EQ(second.ClipRect.y, 5);
  EXPECT_EQ(second.ClipRect.w, 100);
  ASSERT_EQ(second.ElemCount, 3u);
  EXPECT_EQ(list.IdxBuffer[static_cast<int>(second.IdxOffset)], 0);  // a's first triangle
  EXPECT_EQ(list.IdxBuffer.Size, 6);
}

}  // namespace
}  // namespace kinema
