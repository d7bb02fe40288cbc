#include "editor/window/imgui_backends.h"

#include <imgui.h>

#include <algorithm>
#include <cstring>

#include "imgui_impl_opengl3.h"

namespace kinema {

namespace {
// The frame's draw lists copied into one: the backend then fills its vertex and index
// buffers once a frame. Given one list per window it re-fills the same buffers for each,
// while the draws of the previous window still read them, and a software rasteriser
// (llvmpipe) must finish everything queued so far before each re-fill: a dozen stalls a frame.
struct MergedDrawData {
  ImDrawList list{nullptr};
  ImDrawList* lists[1] = {&list};
  ImDrawData data;
};
MergedDrawData& merged() {
  static MergedDrawData m;
  return m;
}
}  // namespace

void mergeImGuiDrawLists(const ImDrawData& in, ImDrawList& out) {
  out.VtxBuffer.resize(0);
  out.IdxBuffer.resize(0);
  out.CmdBuffer.resize(0);
  out.VtxBuffer.reserve(in.TotalVtxCount);
  out.IdxBuffer.reserve(in.TotalIdxCount);
  for (int n = 0; n < in.CmdListsCount; ++n) {
    const ImDrawList& list = *in.CmdLists[n];
    // Indices stay relative to each command's VtxOffset (16-bit indices address 64k
    // vertices past it), so the lists' vertices and indices are appended unchanged and
    // only the offsets move.
    const unsigned int vtxBase = static_cast<unsigned int>(out.VtxBuffer.Size);
    const unsigned int idxBase = static_cast<unsigned int>(out.IdxBuffer.Size);
    const int vtx = out.VtxBuffer.Size, idx = out.IdxBuffer.Size;
    out.VtxBuffer.resize(vtx + list.VtxBuffer.Size);
    if (list.VtxBuffer.Size > 0)
      std::memcpy(out.VtxBuffer.Data + vtx, list.VtxBuffer.Data, sizeof(ImDrawVert) * static_cast<size_t>(list.VtxBuffer.Size));
    out.IdxBuffer.resize(idx + list.IdxBuffer.Size);
    if (list.IdxBuffer.Size > 0)
      std::memcpy(out.IdxBuffer.Data + idx, list.IdxBuffer.Data, sizeof(ImDrawIdx) * static_cast<size_t>(list.IdxBuffer.Size));
    for (const ImDrawCmd& cmd : list.CmdBuffer) {
      ImDrawCmd c = cmd;
      c.VtxOffset += vtxBase;
      c.IdxOffset += idxBase;
      out.CmdBuffer.push_back(c);
    }
  }
}

// The platform side (mouse, keys, display size, time) is the editor's own input layer
// (input_events.h, editor_window.cpp): ImGui's GLFW backend would read the live mouse
// each frame and override replayed --script events.
void imguiBackendsInit(GLFWwindow*) { ImGui_ImplOpenGL3_Init("#version 330 core"); }
void imguiBackendsNewFrame() { ImGui_ImplOpenGL3_NewFrame(); }
void imguiBackendsRenderDrawData(ImDrawData* data, const std::vector<ImVec4>* clipTo) {
  // The backend draws with glDrawElementsBaseVertex (it sets RendererHasVtxOffset), so one
  // list of any length draws like the separate ones.
  const bool vtxOffset = ImGui::GetIO().BackendFlags & ImGuiBackendFlags_RendererHasVtxOffset;
  if (!data || !vtxOffset || (data->CmdListsCount < 2 && !clipTo)) {
    ImGui_ImplOpenGL3_RenderDrawData(data);
    return;
  }
  MergedDrawData& m = merged();
  mergeImGuiDrawLists(*data, m.list);
  if (clipTo) clipImGuiDrawList(m.list, *clipTo);
  m.data = *data;
  m.data.CmdLists = m.lists;
  m.data.CmdListsCount = 1;
  ImGui_ImplOpenGL3_RenderDrawData(&m.data);
}

void clipImGuiDrawList(ImDrawList& list, const std::vector<ImVec4>& rects) {
  // Triangles whose box misses a rectangle give it no pixel: left out, so a software
  // rasteriser does not shade and set up the whole panel's text to fill a few words of it.
  ImVector<ImDrawCmd> clipped;
  ImVector<ImDrawIdx> indices;
  clipped.reserve(list.CmdBuffer.Size);
  indices.reserve(list.IdxBuffer.Size);
  const ImDrawVert* vertices = list.VtxBuffer.Data;
  const unsigned int vertexCount = static_cast<unsigned int>(list.VtxBuffer.Size);
  for (const ImDrawCmd& cmd : list.CmdBuffer)
    for (const ImVec4& r : rects) {
      ImDrawCmd c = cmd;
      c.ClipRect = ImVec4(std::max(cmd.ClipRect.x, r.x), std::max(cmd.ClipRect.y, r.y), std::min(cmd.ClipRect.z, r.z),
                          std::min(cmd.ClipRect.w, r.w));
      if (c.UserCallback) {
        clipped.push_back(c);
        continue;
      }
      if (!(c.ClipRect.z > c.ClipRect.x && c.ClipRect.w > c.ClipRect.y)) continue;
      c.IdxOffset = static_cast<unsigned int>(indices.Size);
      const unsigned int end = std::min(cmd.IdxOffset + cmd.ElemCount, static_cast<unsigned int>(list.IdxBuffer.Size));
      for (unsigned int k = cmd.IdxOffset; k + 2 < end; k += 3) {
        const ImDrawIdx* t = list.IdxBuffer.Data + k;
        float x0 = 1e30f, y0 = 1e30f, x1 = -1e30f, y1 = -1e30f;
        bool known = true;
        for (int i = 0; i < 3; ++i) {
          const unsigned int v = cmd.VtxOffset + t[i];
          if (v >= vertexCount) {
            known = false;  // kept as it was: the backend draws what the list says
            break;
          }
          x0 = std::min(x0, vertices[v].pos.x), x1 = std::max(x1, vertices[v].pos.x);
          y0 = std::min(y0, vertices[v].pos.y), y1 = std::max(y1, vertices[v].pos.y);
        }
        if (known && (x1 < c.ClipRect.x || x0 > c.ClipRect.z || y1 < c.ClipRect.y || y0 > c.ClipRect.w)) continue;
        indices.push_back(t[0]), indices.push_back(t[1]), indices.push_back(t[2]);
      }
      c.ElemCount = static_cast<unsigned int>(indices.Size) - c.IdxOffset;
      if (c.ElemCount > 0) clipped.push_back(c);
    }
  list.CmdBuffer.swap(clipped);
  list.IdxBuffer.swap(indices);
}

void imguiBackendsShutdown() { ImGui_ImplOpenGL3_Shutdown(); }
void imguiBackendsReloadFonts() {
  ImGui_ImplOpenGL3_DestroyFontsTexture();
  ImGui_ImplOpenGL3_CreateFontsTexture();
}
}  // namespace kinema
