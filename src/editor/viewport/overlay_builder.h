#pragma once
#include "editor/viewport/limit_shapes.h"
#include "editor/viewport/rotate_gizmo.h"
#include "editor/viewport/viewport_view.h"
#include "render/overlay_draw_list.h"

namespace kinema {

// Blender's overlay colours (linear RGB, alpha for blending).
struct OverlayStyle {
  glm::vec4 axisX{0.96f, 0.21f, 0.32f, 1.0f};
  glm::vec4 axisY{0.54f, 0.86f, 0.0f, 1.0f};
  glm::vec4 axisZ{0.16f, 0.55f, 0.96f, 1.0f};
  glm::vec4 viewRing{0.9f, 0.9f, 0.9f, 1.0f};
  glm::vec4 trackball{1.0f, 1.0f, 1.0f, 0.12f};
  glm::vec4 highlight{1.0f, 1.0f, 0.55f, 1.0f};
  glm::vec4 ikTarget{0.95f, 0.75f, 0.15f, 1.0f};
  glm::vec4 ikTargetSelected{1.0f, 1.0f, 1.0f, 1.0f};
  glm::vec4 limit{0.35f, 0.85f, 0.85f, 1.0f};
  glm::vec4 boxFill{1.0f, 1.0f, 1.0f, 0.08f};
  glm::vec4 boxBorder{1.0f, 1.0f, 1.0f, 0.9f};
  float ringWidthPixels = 2.5f;
  float highlightWidthPixels = 4.0f;
};

// The rotate gizmo: three axis rings (world circles of gizmo.ringRadiusWorld), the view
// ring, and a translucent trackball disc; `hovered` is drawn in the highlight colour.
void addRotateGizmo(OverlayDrawList& list, const RotateGizmo& gizmo, const ViewportView& view, GizmoPart hovered,
                    const OverlayStyle& style = {});
// An IK target handle: a diamond at the target and a dashed line to the effector it pulls.
void addIkTargetHandle(OverlayDrawList& list, const glm::vec3& target, const glm::vec3& effector, bool selected,
                       const OverlayStyle& style = {}, float radiusPixels = 7.0f);
// A joint limit's rim, arcs and spokes (depth-tested, so the skeleton can hide them).
void addLimitShape(OverlayDrawList& list, const LimitShape& shape, const OverlayStyle& style = {});
// The box-select rectangle between two pixel corners.
void addBoxSelectRectangle(OverlayDrawList& list, glm::vec2 cornerA, glm::vec2 cornerB, const OverlayStyle& style = {});

}  // namespace kinema
