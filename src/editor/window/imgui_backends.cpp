#include "editor/window/imgui_backends.h"

#include <imgui.h>

#include "imgui_impl_opengl3.h"

namespace kinema {
// The platform side (mouse, keys, display size, time) is the editor's own input layer
// (input_events.h, editor_window.cpp): ImGui's GLFW backend would read the live mouse
// each frame and override replayed --script events.
void imguiBackendsInit(GLFWwindow*) { ImGui_ImplOpenGL3_Init("#version 330 core"); }
void imguiBackendsNewFrame() { ImGui_ImplOpenGL3_NewFrame(); }
void imguiBackendsRenderDrawData(ImDrawData* data) { ImGui_ImplOpenGL3_RenderDrawData(data); }
void imguiBackendsShutdown() { ImGui_ImplOpenGL3_Shutdown(); }
void imguiBackendsReloadFonts() {
  ImGui_ImplOpenGL3_DestroyFontsTexture();
  ImGui_ImplOpenGL3_CreateFontsTexture();
}
}  // namespace kinema
