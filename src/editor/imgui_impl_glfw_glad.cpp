// Debian's ImGui GLFW backend, built beside the glad-based OpenGL backend.
#define GLFW_INCLUDE_NONE
#include "imgui_impl_glfw.cpp"
