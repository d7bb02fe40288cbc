#include "render/overlay_renderer.h"

#include <cstddef>

#include "render/shader_sources.h"

namespace kinema {

namespace {
using Vertex = OverlayRenderer::Vertex;
using Layer = OverlayDrawList::Layer;

void quad(std::vector<Vertex>& out, const glm::vec4& a, const glm::vec4& b, const glm::vec4& c, const glm::vec4& d,
          const glm::vec4& color) {
  for (const glm::vec4* p : {&a, &b, &c, &a, &c, &d}) out.push_back({*p, color});
}

// Cuts the segment to the part in front of the near plane (z >= -w in clip space).
bool clipToNear(glm::vec4& a, glm::vec4& b) {
  const float da = a.z + a.w, db = b.z + b.w;
  if (da < 0.0f && db < 0.0f) return false;
  if (da < 0.0f) a = a + (b - a) * (da / (da - db));
  if (db < 0.0f) b = b + (a - b) * (db / (db - da));
  return a.w > 0.0f && b.w > 0.0f;
}

// A segment between two NDC points as a quad `width` pixels wide, lengthened by half the
// width at both ends so consecutive segments of a polyline join without notches.
void segment(std::vector<Vertex>& out, glm::vec3 a, glm::vec3 b, float width, glm::vec2 size, const glm::vec4& color) {
  const glm::vec2 toPixels = size * 0.5f;
  const glm::vec2 d = (glm::vec2(b) - glm::vec2(a)) * toPixels;
  const float length = glm::length(d);
  if (!(length > 1e-6f)) return;
  const glm::vec2 along = d / length * (width * 0.5f) / toPixels;
  const glm::vec2 across = glm::vec2(-d.y, d.x) / length * (width * 0.5f) / toPixels;
  const glm::vec2 a2 = glm::vec2(a) - along, b2 = glm::vec2(b) + along;
  quad(out, glm::vec4(a2 - across, a.z, 1.0f), glm::vec4(b2 - across, b.z, 1.0f), glm::vec4(b2 + across, b.z, 1.0f),
       glm::vec4(a2 + across, a.z, 1.0f), color);
}

void handleShape(std::vector<Vertex>& out, glm::vec3 ndc, float radius, OverlayDrawList::HandleShape shape,
                 glm::vec2 size, const glm::vec4& color) {
  const glm::vec2 perPixel = 2.0f / size;
  auto at = [&](float x, float y) { return glm::vec4(ndc.x + x * perPixel.x, ndc.y + y * perPixel.y, ndc.z, 1.0f); };
  const glm::vec4 c(ndc, 1.0f);
  switch (shape) {
    case OverlayDrawList::HandleShape::Square:
      quad(out, at(-radius, -radius), at(radius, -radius), at(radius, radius), at(-radius, radius), color);
      break;
    case OverlayDrawList::HandleShape::Diamond:
      quad(out, at(0, -radius), at(radius, 0), at(0, radius), at(-radius, 0), color);
      break;
    case OverlayDrawList::HandleShape::Disc: {
      const int n = 32;
      for (int k = 0; k < n; ++k) {
        const float a0 = 6.28318530718f * static_cast<float>(k) / n, a1 = 6.28318530718f * static_cast<float>(k + 1) / n;
        out.push_back({c, color});
        out.push_back({at(radius * std::cos(a0), radius * std::sin(a0)), color});
        out.push_back({at(radius * std::cos(a1), radius * std::sin(a1)), color});
      }
      break;
    }
  }
}

glm::vec3 pixelToNdc(glm::vec2 p, glm::vec2 size) {
  return glm::vec3(2.0f * p.x / size.x - 1.0f, 1.0f - 2.0f * p.y / size.y, 0.0f);
}
}  // namespace

OverlayRenderer::~OverlayRenderer() {
  if (vao_) glDeleteVertexArrays(1, &vao_);
  if (buffer_) glDeleteBuffers(1, &buffer_);
}

std::string OverlayRenderer::init() {
  std::string error = program_.build("overlay", shaders::overlay_vert, shaders::overlay_frag);
  if (!error.empty()) return error;
  glGenVertexArrays(1, &vao_);
  glGenBuffers(1, &buffer_);
  glBindVertexArray(vao_);
  glBindBuffer(GL_ARRAY_BUFFER, buffer_);
  glEnableVertexAttribArray(0);
  glVertexAttribPointer(0, 4, GL_FLOAT, GL_FALSE, sizeof(Vertex), reinterpret_cast<void*>(offsetof(Vertex, clip)));
  glEnableVertexAttribArray(1);
  glVertexAttribPointer(1, 4, GL_FLOAT, GL_FALSE, sizeof(Vertex), reinterpret_cast<void*>(offsetof(Vertex, color)));
  glBindVertexArray(0);
  return {};
}

void OverlayRenderer::appendTriangles(const OverlayDrawList& list, Layer layer, const glm::mat4& viewProjection,
                                      glm::vec2 size, std::vector<Vertex>& out) {
  // Translucent handles first (backdrops such as the trackball disc), then lines, then opaque
  // handles, so markers sit on the lines that lead to them.
  auto handles = [&](bool translucent) {
    for (const OverlayDrawList::Handle& h : list.handles) {
      if (h.layer != layer || (h.color.a < 1.0f) != translucent) continue;
      const glm::vec4 clip = viewProjection * glm::vec4(h.center, 1.0f);
      if (clip.w <= 0.0f || clip.z < -clip.w) continue;
      const glm::vec3 ndc = glm::vec3(clip) / clip.w;
      if (h.outline.a > 0.0f) handleShape(out, ndc, h.radiusPixels + 1.5f, h.shape, size, h.outline);
      handleShape(out, ndc, h.radiusPixels, h.shape, size, h.color);
    }
  };
  handles(true);
  for (const OverlayDrawList::Line& l : list.lines) {
    if (l.layer != layer) continue;
    glm::vec4 a = viewProjection * glm::vec4(l.a, 1.0f), b = viewProjection * glm::vec4(l.b, 1.0f);
    if (!clipToNear(a, b)) continue;
    segment(out, glm::vec3(a) / a.w, glm::vec3(b) / b.w, l.widthPixels, size, l.color);
  }
  handles(false);
}

void OverlayRenderer::appendScreenTriangles(const OverlayDrawList& list, glm::vec2 size, std::vector<Vertex>& out) {
  for (const OverlayDrawList::ScreenRect& r : list.screenRects) {
    const glm::vec3 lo = pixelToNdc(r.min, size), hi = pixelToNdc(r.max, size);
    quad(out, glm::vec4(lo.x, lo.y, 0, 1), glm::vec4(hi.x, lo.y, 0, 1), glm::vec4(hi.x, hi.y, 0, 1),
         glm::vec4(lo.x, hi.y, 0, 1), r.fill);
  }
  for (const OverlayDrawList::ScreenLine& l : list.screenLines)
    segment(out, pixelToNdc(l.a, size), pixelToNdc(l.b, size), l.widthPixels, size, l.color);
}

void OverlayRenderer::upload(const std::vector<Vertex>& vertices) {
  glBindBuffer(GL_ARRAY_BUFFER, buffer_);
  glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(vertices.size() * sizeof(Vertex)), vertices.data(),
               GL_STREAM_DRAW);
  glDrawArrays(GL_TRIANGLES, 0, static_cast<GLsizei>(vertices.size()));
}

void OverlayRenderer::draw(const OverlayDrawList& list, const glm::mat4& viewProjection, int width, int height) {
  if (list.empty() || width <= 0 || height <= 0 || !vao_) return;
  const glm::vec2 size(static_cast<float>(width), static_cast<float>(height));
  glUseProgram(program_.id());
  glBindVertexArray(vao_);
  glEnable(GL_BLEND);
  glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
  glDisable(GL_CULL_FACE);
  glDepthMask(GL_FALSE);  // overlays never hide each other through the depth buffer

  // Scene layer: hidden where the skeleton is in front (LEQUAL so lines on a surface show).
  scratch_.clear();
  appendTriangles(list, Layer::Scene, viewProjection, size, scratch_);
  if (!scratch_.empty()) {
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LEQUAL);
    upload(scratch_);
  }
  // On top of everything: screen rectangles first, then gizmos and handles.
  glDisable(GL_DEPTH_TEST);
  scratch_.clear();
  appendScreenTriangles(list, size, scratch_);
  appendTriangles(list, Layer::OnTop, viewProjection, size, scratch_);
  if (!scratch_.empty()) upload(scratch_);

  glDepthMask(GL_TRUE);
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LESS);
  glDisable(GL_BLEND);
  glBindVertexArray(0);
}

}  // namespace kinema
