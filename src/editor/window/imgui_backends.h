#pragma once
// Dear ImGui's OpenGL 3 backend (Debian's sources, compiled against glad), behind
// four calls so the rest of the editor never includes backend headers.
#include <vector>

struct GLFWwindow;
struct ImVec4;
struct ImDrawData;
struct ImDrawList;

namespace kinema {
void imguiBackendsInit(GLFWwindow* window);
void imguiBackendsNewFrame();
// Draws the frame's lists merged into one (mergeImGuiDrawLists): one buffer upload a frame.
// `clipTo`, when given: only the pixels inside these rectangles (display coordinates, x0 y0
// x1 y1, pairwise disjoint) are drawn (clipImGuiDrawList), for a partial redraw.
void imguiBackendsRenderDrawData(ImDrawData* data, const std::vector<ImVec4>* clipTo = nullptr);
void imguiBackendsShutdown();
// Uploads the font atlas again after it was rebuilt (a new UI scale): between frames.
void imguiBackendsReloadFonts();
// Every list of `in` appended into `out` (cleared first) in order, each command's vertex and
// index offsets moved by what came before, so `out` alone draws the same triangles with the
// same clip rectangles and textures (needs a backend with RendererHasVtxOffset).
void mergeImGuiDrawLists(const ImDrawData& in, ImDrawList& out);
// Each command of `list` repeated once per rectangle of `rects` that its clip rectangle
// meets, clipped to it, with only its triangles whose box meets that rectangle (in order, so
// each pixel of disjoint rectangles is drawn as before by the triangles that reach it, and
// nothing outside them); commands left with no triangle are dropped. Rewrites the indices.
void clipImGuiDrawList(ImDrawList& list, const std::vector<ImVec4>& rects);
}  // namespace kinema
