#pragma once
// An ImGui context for tests that build frames without a window or a GL backend: an 800x600
// display, the font atlas built (its texture id set to `font`), and a renderer that draws
// with vertex offsets, as the editor's backend does. Destroyed with the object.
#include <imgui.h>

namespace kinema::test {

struct ImGuiTestContext {
  explicit ImGuiTestContext(ImTextureID font) {
    ImGui::CreateContext();
    ImGuiIO& io = ImGui::GetIO();
    io.IniFilename = nullptr;
    io.DisplaySize = ImVec2(800, 600);
    io.DeltaTime = 1.0f / 60.0f;
    unsigned char* pixels = nullptr;
    int w = 0, h = 0;
    io.Fonts->GetTexDataAsRGBA32(&pixels, &w, &h);
    io.Fonts->SetTexID(font);
    io.BackendFlags |= ImGuiBackendFlags_RendererHasVtxOffset;
  }
  ~ImGuiTestContext() { ImGui::DestroyContext(); }
  ImGuiTestContext(const ImGuiTestContext&) = delete;
  ImGuiTestContext& operator=(const ImGuiTestContext&) = delete;
};

}  // namespace kinema::test
