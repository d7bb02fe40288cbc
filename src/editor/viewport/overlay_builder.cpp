#include "editor/viewport/overlay_builder.h"

#include <algorithm>

namespace kinema {

void addRotateGizmo(OverlayDrawList& list, const RotateGizmo& gizmo, const ViewportView& view, GizmoPart hovered,
                    const OverlayStyle& style) {
  using Layer = OverlayDrawList::Layer;
  glm::vec4 ball = style.trackball;
  if (hovered == GizmoPart::Trackball) ball.a = std::min(1.0f, ball.a * 2.0f) * 0.999f;  // stays translucent
  list.addHandle(gizmo.pivot, gizmo.ringRadiusPixels, ball, OverlayDrawList::HandleShape::Disc, Layer::OnTop);
  list.handles.back().outline.a = 0.0f;

  const GizmoPart parts[3] = {GizmoPart::AxisX, GizmoPart::AxisY, GizmoPart::AxisZ};
  const glm::vec4 colors[3] = {style.axisX, style.axisY, style.axisZ};
  for (int i = 0; i < 3; ++i) {
    const bool hot = hovered == parts[i];
    const glm::vec4 color = hot ? style.highlight : colors[i];
    const float width = hot ? style.highlightWidthPixels : style.ringWidthPixels;
    const std::vector<glm::vec3> ring = gizmo.ringPoints(view, i);
    for (size_t k = 0; k < ring.size(); ++k) {
      const glm::vec3& a = ring[k];
      const glm::vec3& b = ring[(k + 1) % ring.size()];
      // Only the half facing the viewer, as Blender clips its rings by the gizmo's sphere.
      if (!ringSegmentFacesViewer(gizmo, view, a, b)) continue;
      list.addLine(a, b, color, width, Layer::OnTop);
    }
  }
  const bool hot = hovered == GizmoPart::ViewRing;
  list.addPolyline(gizmo.ringPoints(view, 3), true, hot ? style.highlight : style.viewRing,
                   hot ? style.highlightWidthPixels : style.ringWidthPixels, Layer::OnTop);
}

void addIkTargetHandle(OverlayDrawList& list, const glm::vec3& target, const glm::vec3& effector, bool selected,
                       const OverlayStyle& style, float radiusPixels) {
  const glm::vec4 color = selected ? style.ikTargetSelected : style.ikTarget;
  list.addDashedLine(target, effector, 8, color, 1.5f, OverlayDrawList::Layer::OnTop);
  list.addHandle(target, radiusPixels, color, OverlayDrawList::HandleShape::Diamond, OverlayDrawList::Layer::OnTop);
}

void addLimitShape(OverlayDrawList& list, const LimitShape& shape, const OverlayStyle& style) {
  const glm::vec4 axisColors[3] = {style.axisX, style.axisY, style.axisZ};
  for (const LimitShape::Polyline& line : shape.rims) {
    const glm::vec4 color = line.axis >= 0 && line.axis < 3 ? axisColors[line.axis] : style.limit;
    list.addPolyline(line.points, line.closed, color, 2.0f, OverlayDrawList::Layer::Scene);
  }
  glm::vec4 spoke = style.limit;
  spoke.a *= 0.6f;
  for (size_t k = 0; k + 1 < shape.spokes.size(); k += 2)
    list.addLine(shape.spokes[k], shape.spokes[k + 1], spoke, 1.0f, OverlayDrawList::Layer::Scene);
}

void addBoxSelectRectangle(OverlayDrawList& list, glm::vec2 cornerA, glm::vec2 cornerB, const OverlayStyle& style) {
  list.addScreenRectangle(cornerA, cornerB, style.boxFill, style.boxBorder);
}

}  // namespace kinema
