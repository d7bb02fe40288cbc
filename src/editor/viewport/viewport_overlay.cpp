#include "editor/viewport/viewport_overlay.h"

#include <algorithm>

#include "editor/model/active_ik_target.h"
#include "editor/viewport/capsule_shape.h"
#include "editor/viewport/lattice_cage.h"
#include "editor/viewport/limit_shapes.h"
#include "editor/viewport/overlay_builder.h"

namespace kinema {

void buildViewportOverlay(const EditorState& state, const ViewportView& view, const ViewportTools& tools,
                          OverlayDrawList& out) {
  out.clear();
  const Document& doc = state.doc;
  const ModalTool mode = state.tool.mode;
  RotateGizmo gizmo;
  if ((mode == ModalTool::None || mode == ModalTool::GizmoDrag) && tools.gizmo(state, view, gizmo)) {
    const GizmoPart hot = mode == ModalTool::GizmoDrag ? static_cast<GizmoPart>(state.tool.ring) : tools.hoveredGizmoPart();
    addRotateGizmo(out, gizmo, view, hot);
  }
  const std::vector<PoseIkTarget>& targets = doc.ikTargets();
  const int activeTarget = activeIkTarget(doc);
  for (int i = 0; i < static_cast<int>(targets.size()); ++i) {
    const int e = targets[i].target.effector;
    const glm::vec3 effector = e >= 0 && e < static_cast<int>(state.world().size()) ? glm::vec3(state.world()[e][3])
                                                                                  : targets[i].target.position;
    const bool hot = i == state.hoveredIkTarget || (mode == ModalTool::IkDrag && state.tool.ikTarget == i) ||
                     i == activeTarget;
    addIkTargetHandle(out, targets[i].target.position, effector, hot);
  }
  if (doc.temporaryIkTarget())
    addIkTargetHandle(out, doc.temporaryIkTarget()->target.position, doc.temporaryIkTarget()->target.position, true);
  if (state.view.showLimits) {
    const Skeleton& s = doc.skeleton();
    for (int j : doc.selection.joints()) {
      const JointLimit* limit = doc.rig().limitOf(j);
      if (!limit || j >= static_cast<int>(state.world().size())) continue;
      LimitShapeJob job;
      job.limit = *limit;
      job.jointPosition = glm::vec3(state.world()[j][3]);
      const int parent = s.parents[j];
      job.restFrameWorld = (parent >= 0 ? jointWorldRotation(doc, parent) : glm::quat(1, 0, 0, 0)) * s.rest[j].rotation;
      float size = 0.1f;
      for (int c = j + 1; c < s.size(); ++c)
        if (s.parents[c] == j) {
          job.restBoneDirection = s.rest[c].translation;
          size = glm::length(s.rest[c].translation);
          break;
        }
      job.size = size > 0 ? size : 0.1f;
      LimitShape shape;
      if (job.run(shape)) addLimitShape(out, shape);
    }
  }
  // Spring-bone collision capsules (issue 23), on top (most sit inside the body): where the
  // dynamic chains' tails cannot go. A capsule added to several chains is drawn once.
  std::vector<SpringCollider> drawn;
  for (const SpringBoneChain& chain : doc.scene().simulation.springChains)
    for (const SpringCollider& c : chain.colliders) {
      if (std::find(drawn.begin(), drawn.end(), c) != drawn.end()) continue;
      drawn.push_back(c);
      const bool onJoint = c.joint >= 0 && c.joint < static_cast<int>(state.world().size());
      const glm::mat4 m = onJoint ? state.world()[c.joint] : glm::mat4(1.0f);
      const float scale = glm::length(glm::vec3(m[0]));
      const CapsuleWire wire = capsuleWire(glm::vec3(m * glm::vec4(c.a, 1.0f)), glm::vec3(m * glm::vec4(c.b, 1.0f)), c.radius * scale);
      for (const std::vector<glm::vec3>& line : wire.polylines)
        out.addPolyline(line, false, glm::vec4(1.0f, 0.55f, 0.15f, 0.8f), 1.5f, OverlayDrawList::Layer::OnTop);
    }
  if (state.lattice.active)
    if (const Deformer* lattice = editedLattice(state))
      addLatticeCage(out, latticeWorldPoints(state), latticeEdges(lattice->lattice), state.lattice);
  // Screen shapes are drawn in the viewport's own pixels; the tools work in window pixels.
  if (mode == ModalTool::BoxSelect)
    addBoxSelectRectangle(out, state.tool.startMouse - view.origin, state.tool.mouse - view.origin);
  if (mode == ModalTool::Rotate && doc.selection.active() >= 0 && doc.selection.active() < static_cast<int>(state.world().size())) {
    glm::vec2 c;
    if (view.project(glm::vec3(state.world()[doc.selection.active()][3]), c))
      out.screenLines.push_back({c - view.origin, state.tool.mouse - view.origin, glm::vec4(0.9f, 0.9f, 0.9f, 0.7f), 1.0f});
  }
}

void colorSelection(const EditorState& state, SkeletonDrawList& list) {
  // X-ray bones are translucent so the body shows through; the selection stays opaque.
  const SkeletonStyle style = state.view.xrayBones ? SkeletonStyle::xRay() : SkeletonStyle();
  const glm::vec4 hover = glm::mix(style.bone, glm::vec4(1.0f), 0.5f);
  for (size_t b = 0; b < list.boneColors.size() && b < list.boneParents.size(); ++b) {
    const int p = list.boneParents[b];
    list.boneColors[b] = state.doc.selection.isSelected(p) ? style.selectedBone : p == state.hoveredJoint ? hover : style.bone;
  }
  // Sphere i is of joint list.joints[i]: joints that are not drawn (a glTF character's
  // helper nodes) have none, so the index alone is not the joint.
  for (size_t i = 0; i < list.jointColors.size() && i < list.joints.size(); ++i) {
    const int j = list.joints[i];
    list.jointColors[i] = state.doc.selection.isSelected(j) ? style.selectedJoint : j == state.hoveredJoint ? hover : style.joint;
  }
}

bool hiddenBonesSelection(const EditorState& state, const SkeletonDrawList& list, SkeletonDrawList& out) {
  out = SkeletonDrawList{};
  if (state.view.showBones || state.doc.selection.empty()) return false;
  std::vector<char> selected(static_cast<size_t>(state.doc.skeleton().size()), 0);
  for (int j : state.doc.selection.joints())
    if (j >= 0 && j < static_cast<int>(selected.size())) selected[j] = 1;
  out = keepJoints(list, selected);
  return !out.boneMatrices.empty() || !out.jointMatrices.empty();
}

}  // namespace kinema
