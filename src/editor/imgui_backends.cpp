#include "editor/imgui_backends.h"

#include <imgui.h>

#include "imgui_impl_glfw.h"
#include "imgui_impl_opengl3.h"

namespace kinema {
void imguiBackendsInit(GLFWwindow* window) {
  ImGui_ImplGlfw_InitForOpenGL(window, true);
  ImGui_ImplOpenGL3_Init("#version 330 core");
}
void imguiBackendsNewFrame() {
  ImGui_ImplOpenGL3_NewFrame();
  ImGui_ImplGlfw_NewFrame();
}
void imguiBackendsRenderDrawData(ImDrawData* data) { ImGui_ImplOpenGL3_RenderDrawData(data); }
void imguiBackendsShutdown() {
  ImGui_ImplOpenGL3_Shutdown();
  ImGui_ImplGlfw_Shutdown();
}
}  // namespace kinema
