#include "render/overlay_draw_list.h"

#include <algorithm>

namespace kinema {

void OverlayDrawList::addLine(const glm::vec3& a, const glm::vec3& b, const glm::vec4& color, float widthPixels,
                              Layer layer) {
  lines.push_back({a, b, color, widthPixels, layer});
}

void OverlayDrawList::addPolyline(const std::vector<glm::vec3>& points, bool closed, const glm::vec4& color,
                                  float widthPixels, Layer layer) {
  if (points.size() < 2) return;
  for (size_t k = 0; k + 1 < points.size(); ++k) addLine(points[k], points[k + 1], color, widthPixels, layer);
  if (closed && points.size() > 2) addLine(points.back(), points.front(), color, widthPixels, layer);
}

void OverlayDrawList::addDashedLine(const glm::vec3& a, const glm::vec3& b, int dashes, const glm::vec4& color,
                                    float widthPixels, Layer layer) {
  dashes = std::max(dashes, 1);
  // 2 * dashes - 1 equal pieces: dash, gap, dash, ..., dash (both ends are drawn).
  const float pieces = static_cast<float>(2 * dashes - 1);
  for (int k = 0; k < dashes; ++k) {
    const float t0 = static_cast<float>(2 * k) / pieces, t1 = static_cast<float>(2 * k + 1) / pieces;
    addLine(a + (b - a) * t0, a + (b - a) * t1, color, widthPixels, layer);
  }
}

void OverlayDrawList::addHandle(const glm::vec3& center, float radiusPixels, const glm::vec4& color, HandleShape shape,
                                Layer layer) {
  Handle h;
  h.center = center;
  h.radiusPixels = radiusPixels;
  h.color = color;
  h.shape = shape;
  h.layer = layer;
  handles.push_back(h);
}

void OverlayDrawList::addScreenRectangle(glm::vec2 cornerA, glm::vec2 cornerB, const glm::vec4& fill,
                                         const glm::vec4& border) {
  const glm::vec2 lo = glm::min(cornerA, cornerB), hi = glm::max(cornerA, cornerB);
  screenRects.push_back({lo, hi, fill});
  // Blender's dashed outline: 4 pixels on, 4 off, along each edge.
  const glm::vec2 corners[4] = {lo, {hi.x, lo.y}, hi, {lo.x, hi.y}};
  for (int e = 0; e < 4; ++e) {
    const glm::vec2 a = corners[e], b = corners[(e + 1) % 4];
    const float length = glm::length(b - a);
    if (length <= 0.0f) continue;
    const glm::vec2 dir = (b - a) / length;
    for (float s = 0.0f; s < length; s += 8.0f) screenLines.push_back({a + dir * s, a + dir * std::min(s + 4.0f, length), border, 1.0f});
  }
}

void OverlayDrawList::scaleWidths(float k) {
  for (Line& l : lines) l.widthPixels *= k;
  for (Handle& h : handles)
    if (h.radiusPixels <= kMarkerPixels) h.radiusPixels *= k;  // markers; larger discs are areas (a gizmo's)
  for (ScreenLine& l : screenLines) l.widthPixels *= k;
}

}  // namespace kinema
