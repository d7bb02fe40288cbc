// The window draws ImGui's frame as one merged draw list (window/imgui_backends.h), so the
// backend uploads its buffers once a frame. The merged list must draw exactly the triangles
// of the separate lists, in their order, each with its own clip rectangle and texture.
#include <gtest/gtest.h>
#include <imgui.h>

#include <cstring>
#include <string>
#include <vector>

#include "editor/imgui_test_context.h"
#include "editor/window/imgui_backends.h"

namespace kinema {
namespace KINEMA_UNITY_ID {

// One triangle as drawn: its three vertices (position, uv, colour), clip rectangle, texture.
struct DrawnTriangle {
  ImDrawVert v[3];
  ImVec4 clip;
  ImTextureID texture;
  bool operator==(const DrawnTriangle& o) const {
    return std::memcmp(v, o.v, sizeof v) == 0 && clip.x == o.clip.x && clip.y == o.clip.y && clip.z == o.clip.z &&
           clip.w == o.clip.w && texture == o.texture;
  }
};

// What a backend with RendererHasVtxOffset draws for `list`: command by command, index
// IdxOffset + k addresses vertex VtxOffset + index.
void drawn(const ImDrawList& list, std::vector<DrawnTriangle>& out) {
  for (const ImDrawCmd& cmd : list.CmdBuffer) {
    ASSERT_EQ(cmd.UserCallback, nullptr);
    ASSERT_EQ(cmd.ElemCount % 3, 0u);
    for (unsigned int k = 0; k < cmd.ElemCount; k += 3) {
      DrawnTriangle t;
      for (int c = 0; c < 3; ++c) {
        const unsigned int i = cmd.IdxOffset + k + static_cast<unsigned int>(c);
        ASSERT_LT(i, static_cast<unsigned int>(list.IdxBuffer.Size));
        const unsigned int vi = cmd.VtxOffset + list.IdxBuffer[static_cast<int>(i)];
        ASSERT_LT(vi, static_cast<unsigned int>(list.VtxBuffer.Size));
        t.v[c] = list.VtxBuffer[static_cast<int>(vi)];
      }
      t.clip = cmd.ClipRect;
      t.texture = cmd.TextureId;
      out.push_back(t);
    }
  }
}

TEST(ImGuiDrawMerge, TheMergedListDrawsEveryListsTrianglesInOrder) {
  const test::ImGuiTestContext imgui(reinterpret_cast<ImTextureID>(static_cast<intptr_t>(7)));
  ImGui::NewFrame();
  // Three windows with text, frames, a clipped child and an image of another texture, so
  // the lists hold several commands with different clip rectangles and textures.
  for (int n = 0; n < 3; ++n) {
    ImGui::SetNextWindowPos(ImVec2(20.0f + 200.0f * n, 30.0f));
    ImGui::SetNextWindowSize(ImVec2(180, 300));
    ImGui::Begin(("window " + std::to_string(n)).c_str());
    for (int k = 0; k < 20 + 10 * n; ++k) ImGui::Text("line %d of window %d", k, n);
    ImGui::BeginChild("child", ImVec2(120, 80), true);
    for (int k = 0; k < 12; ++k) ImGui::Button(("button " + std::to_string(k)).c_str());
    ImGui::EndChild();
    ImGui::Image(reinterpret_cast<ImTextureID>(static_cast<intptr_t>(100 + n)), ImVec2(32, 32));
    ImGui::End();
  }
  ImGui::Render();
  const ImDrawData* data = ImGui::GetDrawData();
  ASSERT_GE(data->CmdListsCount, 3);
  std::vector<DrawnTriangle> separate;
  size_t commands = 0;
  for (int n = 0; n < data->CmdListsCount; ++n) {
    drawn(*data->CmdLists[n], separate);
    commands += static_cast<size_t>(data->CmdLists[n]->CmdBuffer.Size);
  }
  ASSERT_GT(separate.size(), 100u);

  ImDrawList merged(nullptr);
  mergeImGuiDrawLists(*data, merged);
  EXPECT_EQ(merged.VtxBuffer.Size, data->TotalVtxCount);
  EXPECT_EQ(merged.IdxBuffer.Size, data->TotalIdxCount);
  EXPECT_EQ(static_cast<size_t>(merged.CmdBuffer.Size), commands);
  std::vector<DrawnTriangle> together;
  drawn(merged, together);
  ASSERT_EQ(together.size(), separate.size());
  for (size_t t = 0; t < separate.size(); ++t) ASSERT_TRUE(together[t] == separate[t]) << "triangle " << t;
  // Merging again into the same list starts afresh.
  mergeImGuiDrawLists(*data, merged);
  EXPECT_EQ(merged.VtxBuffer.Size, data->TotalVtxCount);
}

}  // namespace
}  // namespace kinema
