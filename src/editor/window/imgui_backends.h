#pragma once
// Dear ImGui's OpenGL 3 backend (Debian's sources, compiled against glad), behind
// four calls so the rest of the editor never includes backend headers.
struct GLFWwindow;
struct ImDrawData;

namespace kinema {
void imguiBackendsInit(GLFWwindow* window);
void imguiBackendsNewFrame();
void imguiBackendsRenderDrawData(ImDrawData* data);
void imguiBackendsShutdown();
// Uploads the font atlas again after it was rebuilt (a new UI scale): between frames.
void imguiBackendsReloadFonts();
}  // namespace kinema
