#include "editor/viewport_overlay.h"

#include <imgui.h>

#include <algorithm>
#include <cmath>

#include "render/skeleton_draw_list.h"

namespace kinema {

namespace {

ImU32 color(float r, float g, float b, float a = 1.0f) { return ImGui::GetColorU32(ImVec4(r, g, b, a)); }

void drawRing(ImDrawList* dl, const ViewportGeometry& g, const GizmoGeometry& gizmo, const glm::vec3& axis, ImU32 c,
              float thickness) {
  const glm::vec3 u = glm::normalize(std::abs(axis.x) < 0.9f ? glm::cross(axis, glm::vec3(1, 0, 0))
                                                             : glm::cross(axis, glm::vec3(0, 1, 0)));
  const glm::vec3 v = glm::cross(axis, u);
  glm::vec2 prev(0.0f);
  bool havePrev = false;
  for (int s = 0; s <= 64; ++s) {
    const float t = 6.2831853f * s / 64;
    const glm::vec3 p = gizmo.center + gizmo.radiusWorld * (std::cos(t) * u + std::sin(t) * v);
    glm::vec2 q;
    const bool ok = g.toScreen(p, q);
    // The half of the ring facing away from the viewer is drawn fainter, as in Blender.
    const bool front = glm::dot(p - gizmo.center, -g.forward) >= -1e-4f * gizmo.radiusWorld;
    if (ok && havePrev) dl->AddLine(ImVec2(prev.x, prev.y), ImVec2(q.x, q.y), front ? c : (c & 0x00FFFFFF) | 0x60000000, thickness);
    prev = q;
    havePrev = ok;
  }
}

}  // namespace

void drawViewportOverlay(const EditorState& state, const ViewportGeometry& g) {
  ImDrawList* dl = ImGui::GetBackgroundDrawList();
  // Hover: a ring around the joint under the mouse.
  if (state.hoveredJoint >= 0 && state.hoveredJoint < static_cast<int>(state.world.size())) {
    glm::vec2 p;
    if (g.toScreen(glm::vec3(state.world[state.hoveredJoint][3]), p))
      dl->AddCircle(ImVec2(p.x, p.y), 9.0f, color(1.0f, 1.0f, 1.0f, 0.8f), 24, 1.5f);
  }
  // The rotate gizmo on the active joint.
  const GizmoGeometry gizmo = gizmoGeometry(state, g);
  const ModalTool mode = state.tool.mode;
  if (gizmo.valid && (mode == ModalTool::None || mode == ModalTool::GizmoDrag)) {
    const ImU32 axisColors[3] = {color(0.90f, 0.25f, 0.25f), color(0.45f, 0.80f, 0.20f), color(0.25f, 0.50f, 0.95f)};
    for (int k = 0; k < 3; ++k) {
      const bool active = mode == ModalTool::GizmoDrag && state.tool.ring == k;
      drawRing(dl, g, gizmo, gizmo.axes[k], active ? color(1, 1, 1) : axisColors[k], active ? 3.0f : 2.0f);
    }
    glm::vec2 c;
    if (g.toScreen(gizmo.center, c)) {
      const bool viewRing = mode == ModalTool::GizmoDrag && state.tool.ring == 3;
      dl->AddCircle(ImVec2(c.x, c.y), gizmo.radiusPixels * 1.25f, viewRing ? color(1, 1, 1) : color(0.85f, 0.85f, 0.85f, 0.8f), 64,
                    viewRing ? 3.0f : 1.5f);
      dl->AddCircle(ImVec2(c.x, c.y), gizmo.radiusPixels, color(0.6f, 0.6f, 0.6f, 0.35f), 64, 1.0f);
    }
  }
  // R mode: a dashed line from the pivot to the mouse, as Blender draws.
  if (mode == ModalTool::Rotate && state.activeJoint >= 0) {
    glm::vec2 c;
    if (g.toScreen(glm::vec3(state.world[state.activeJoint][3]), c))
      dl->AddLine(ImVec2(c.x, c.y), ImVec2(state.tool.mouse.x, state.tool.mouse.y), color(0.9f, 0.9f, 0.9f, 0.7f), 1.0f);
  }
  // IK target handles: a yellow diamond, a line to the effector.
  for (int i = 0; i < static_cast<int>(state.scene.ik.targets.size()); ++i) {
    const IkTarget& t = state.scene.ik.targets[i];
    glm::vec2 p, e;
    if (!g.toScreen(t.position, p)) continue;
    const bool hot = i == state.hoveredIkTarget || (mode == ModalTool::IkDrag && state.tool.ikTarget == i);
    if (t.effector >= 0 && t.effector < static_cast<int>(state.world.size()) &&
        g.toScreen(glm::vec3(state.world[t.effector][3]), e))
      dl->AddLine(ImVec2(p.x, p.y), ImVec2(e.x, e.y), color(1.0f, 0.85f, 0.2f, 0.6f), 1.0f);
    const float r = hot ? 9.0f : 7.0f;
    dl->AddQuadFilled(ImVec2(p.x, p.y - r), ImVec2(p.x + r, p.y), ImVec2(p.x, p.y + r), ImVec2(p.x - r, p.y),
                      hot ? color(1.0f, 1.0f, 0.5f) : color(1.0f, 0.8f, 0.1f));
    dl->AddQuad(ImVec2(p.x, p.y - r), ImVec2(p.x + r, p.y), ImVec2(p.x, p.y + r), ImVec2(p.x - r, p.y), color(0, 0, 0, 0.8f));
  }
  if (mode == ModalTool::BoxSelect) {
    const ImVec2 a(state.tool.startMouse.x, state.tool.startMouse.y), b(state.tool.mouse.x, state.tool.mouse.y);
    dl->AddRectFilled(ImVec2(std::min(a.x, b.x), std::min(a.y, b.y)), ImVec2(std::max(a.x, b.x), std::max(a.y, b.y)),
                      color(1, 1, 1, 0.08f));
    dl->AddRect(ImVec2(std::min(a.x, b.x), std::min(a.y, b.y)), ImVec2(std::max(a.x, b.x), std::max(a.y, b.y)),
                color(1, 1, 1, 0.7f));
  }
}

void colorSelection(const EditorState& state, SkeletonDrawList& list) {
  // Same bone order as SkeletonDrawJob::run: one per joint with a parent, skipping
  // zero-length bones.
  const std::vector<int>& parents = state.scene.skeleton.parents;
  const float size = std::max(jointBounds(state.world).radius(), 1e-3f);
  const SkeletonStyle style;
  size_t bone = 0;
  for (size_t i = 0; i < parents.size() && i < state.world.size(); ++i) {
    const int p = parents[i];
    if (p < 0) continue;
    if (glm::length(glm::vec3(state.world[i][3]) - glm::vec3(state.world[p][3])) <= size * 1e-4f) continue;
    if (bone < list.boneColors.size()) list.boneColors[bone] = state.isSelected(p) ? style.selectedBone : style.bone;
    ++bone;
  }
  for (size_t i = 0; i < list.jointColors.size(); ++i)
    list.jointColors[i] = state.isSelected(static_cast<int>(i)) ? style.selectedJoint : style.joint;
}

}  // namespace kinema
