#pragma once
// Dear ImGui's OpenGL 3 backend (Debian's sources, compiled against glad), behind
// four calls so the rest of the editor never includes backend headers.
struct GLFWwindow;
struct ImDrawData;
struct ImDrawList;

namespace kinema {
void imguiBackendsInit(GLFWwindow* window);
void imguiBackendsNewFrame();
// Draws the frame's lists merged into one (mergeImGuiDrawLists): one buffer upload a frame.
void imguiBackendsRenderDrawData(ImDrawData* data);
void imguiBackendsShutdown();
// Uploads the font atlas again after it was rebuilt (a new UI scale): between frames.
void imguiBackendsReloadFonts();
// Every list of `in` appended into `out` (cleared first) in order, each command's vertex and
// index offsets moved by what came before, so `out` alone draws the same triangles with the
// same clip rectangles and textures (needs a backend with RendererHasVtxOffset).
void mergeImGuiDrawLists(const ImDrawData& in, ImDrawList& out);
}  // namespace kinema
