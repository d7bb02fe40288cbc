// Debian's ImGui OpenGL 3 backend, built against glad: the archive's own copy brings a
// loader that fails under OSMesa and would bypass the project's single loader.
#include <glad/gl.h>
#define IMGUI_IMPL_OPENGL_LOADER_CUSTOM
#include "imgui_impl_opengl3.cpp"
