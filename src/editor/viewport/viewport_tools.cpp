#include "editor/viewport/viewport_tools.h"

#include "editor/model/deformer_edits.h"

#include "editor/model/key_codes.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "editor/viewport/box_select.h"
#include "editor/viewport/lattice_cage.h"
#include "editor/model/edit_labels.h"
#include "editor/model/ik_posing.h"
#include "editor/viewport/mesh_picking.h"
#include "editor/viewport/picking.h"
#include "editor/model/pose_edits.h"
#include "editor/viewport/translate_drag.h"
#include "editor/viewport/viewport_controller.h"

namespace kinema {

namespace {

constexpr float kBoxThresholdPixels = 4.0f;
constexpr float kHandlePickPixels = 9.0f;
constexpr float kLatticePickPixels = 10.0f;

bool hasSelectedAncestor(const Document& doc, int joint) {
  for (int j = doc.skeleton().parents[joint]; j >= 0; j = doc.skeleton().parents[j])
    if (doc.selection.isSelected(j)) return true;
  return false;
}

int ikHandleUnder(const EditorState& state, const ViewportView& view, glm::vec2 mouse) {
  const std::vector<PoseIkTarget>& targets = state.doc.ikTargets();
  const float radius = kHandlePickPixels * std::max(state.preferences.lineScale, 1.0f);  // markers grow with it
  for (int i = 0; i < static_cast<int>(targets.size()); ++i) {
    glm::vec2 p;
    if (view.project(targets[i].target.position, p) && glm::length(p - mouse) < radius) return i;
  }
  return -1;
}

AxisConstraint axisOf(int index) {
  return index == 0 ? AxisConstraint::X : index == 1 ? AxisConstraint::Y : index == 2 ? AxisConstraint::Z : AxisConstraint::None;
}

}  // namespace

glm::quat jointWorldRotation(const Document& doc, int joint) {
  glm::quat q(1, 0, 0, 0);
  for (int j = joint; j >= 0; j = doc.skeleton().parents[j]) q = doc.pose().local[j].rotation * q;
  return q;
}

glm::vec3 ViewportTools::jointPosition(const EditorState& state, int joint) const {
  return joint >= 0 && joint < static_cast<int>(state.world().size()) ? glm::vec3(state.world()[joint][3]) : glm::vec3(0.0f);
}

bool ViewportTools::gizmo(const EditorState& state, const ViewportView& view, RotateGizmo& out) const {
  const int j = state.doc.selection.active();
  if (!state.view.showGizmo || state.lattice.active || j < 0 || j >= static_cast<int>(state.world().size())) return false;
  out = RotateGizmo{};
  out.pivot = jointPosition(state, j);
  out.ringRadiusPixels =
      rotateGizmoRingPixels(view, state.world(), state.doc.skeleton().parents, j, out.ringRadiusPixels, out.tolerancePixels);
  out.viewRingRadiusPixels = out.ringRadiusPixels * kViewRingScale;
  out.axesRotation = RotateGizmo::axesFor(state.view.localGizmo ? GizmoOrientation::Local : GizmoOrientation::Global,
                                          jointWorldRotation(state.doc, j));
  glm::vec2 p;
  return view.project(out.pivot, p);
}

bool ViewportTools::beginModal(EditorState& state, ModalTool tool, const char* label) {
  const std::string error = state.doc.beginDrag(label);
  if (!error.empty()) {
    state.statusMessage = error;
    return false;
  }
  state.tool = ToolState{};
  state.tool.mode = tool;
  state.tool.startMouse = state.tool.mouse = mouse_;
  return true;
}

void ViewportTools::confirm(EditorState& state) {
  if (state.tool.mode == ModalTool::LatticeGrab) {
    state.tool = ToolState{};
    state.statusMessage = confirmLatticeMove(state);
    return;
  }
  if (state.doc.dragging()) state.doc.commitDrag();
  state.tool = ToolState{};
  state.statusMessage.clear();
}

void ViewportTools::cancel(EditorState& state) {
  if (state.tool.mode == ModalTool::LatticeGrab) cancelLatticeMove(state);
  if (state.doc.dragging()) state.doc.cancelDrag();
  state.tool = ToolState{};
  state.statusMessage.clear();
}

void ViewportTools::softPullPickPress(EditorState& state, const ViewportView& view) {
  PanelState& panels = state.panels;
  const int instance = panels.softPullPickInstance, deformer = panels.softPullPickDeformer;
  const PickRay ray = view.rayThrough(mouse_);
  refreshDeformed(state);
  const MeshPick m = pickMeshJoint(state.doc.scene(), deformed_, ray);
  if (!m.hit()) {
    state.statusMessage = "Soft pull: click on the body (the pick is still waiting; Cancel pick in Properties ends it)";
    return;
  }
  const DeformerStack* stack = state.doc.scene().deformerStack(static_cast<size_t>(instance));
  panels.softPullPickInstance = panels.softPullPickDeformer = -1;
  if (!stack || deformer < 0 || deformer >= static_cast<int>(stack->deformers.size())) return;
  const SoftPull& pull = stack->deformers[deformer].pull;
  const std::string error = setSoftPullShape(state.doc, instance, deformer, ray.at(m.distance), pull.radius, pull.falloff);
  state.statusMessage = error.empty() ? "Soft pull centred where the body was clicked" : error;
}

void ViewportTools::refreshDeformed(const EditorState& state) const {
  const Scene& scene = state.doc.scene();
  if (deformedScene_ != &scene || deformedRevision_ != state.doc.meshRevision() ||
      deformedChange_ != state.doc.changeCount() || deformedPose_ != state.doc.poseRevision()) {
    deformed_.clear();
    SceneDeformationJob job;
    job.scene = &scene;
    job.world = &state.world();
    job.out = &deformed_;
    if (!job.run()) deformed_.clear();
    deformedScene_ = &scene;
    deformedRevision_ = state.doc.meshRevision();
    deformedChange_ = state.doc.changeCount();
    deformedPose_ = state.doc.poseRevision();
  }
}

SkeletonPick ViewportTools::pickAt(const EditorState& state, const ViewportView& view,
                                   const SkeletonDrawList& list) const {
  SkeletonPick pick = pickSkeletonAt(list, view, mouse_);
  // Shown bones (solid or x-ray) are picked through the body, as in Blender's pose mode with
  // x-ray; a click on the body away from any bone, or any click while the bones are hidden,
  // takes the joint weighing most at the hit vertex.
  if (pick.hit() && state.view.showBones) return pick;
  const Scene& scene = state.doc.scene();
  if (scene.meshInstances.empty()) return pick;
  refreshDeformed(state);
  const MeshPick m = pickMeshJoint(scene, deformed_, view.rayThrough(mouse_));
  if (m.hit()) {
    pick.joint = m.joint;
    pick.boneChild = -1;
    pick.distance = m.distance;
  }
  return pick;
}

void ViewportTools::applyRotate(EditorState& state, const ViewportView& view) {
  const bool snap = mods_ & kModCtrl;
  const float total = sweep_.update(mouse_);
  const bool typed = !state.tool.typed.empty() && state.tool.typed != "-";
  const double typedDegrees = typed ? std::strtod(state.tool.typed.c_str(), nullptr) : 0.0;
  float shown = 0.0f;
  std::vector<glm::quat> locals(joints_.size());
  for (size_t k = 0; k < joints_.size(); ++k) {
    const glm::vec3 pivot = jointPosition(state, joints_[k]);
    const glm::vec3 axis = rotateMode_.worldAxis(view, pivot, startWorld_[k]);
    glm::quat delta;
    if (typed) {
      // Typed degrees turn about the axis itself (counter-clockwise looking down it).
      shown = static_cast<float>(glm::radians(typedDegrees));
      delta = glm::angleAxis(shown, glm::normalize(axis));
    } else {
      delta = axisTurnForSweep(view, pivot, axis, total, snap, &shown);
    }
    locals[k] = localRotationAfterWorldTurn(parentWorld_[k], startLocal_[k], delta);
  }
  updateRotateDrag(state.doc, joints_, locals);  // honours X-mirror, as the gizmo's drag does
  state.tool.axis = axisOf(rotateMode_.axis);
  state.tool.localAxes = rotateMode_.local;
  char line[96];
  std::snprintf(line, sizeof line, "Rotate %.1f deg%s%s", glm::degrees(shown),
                rotateMode_.axis < 0 ? "" : (rotateMode_.axis == 0 ? " X" : rotateMode_.axis == 1 ? " Y" : " Z"),
                rotateMode_.local ? " local" : "");
  state.statusMessage = line;
}

void ViewportTools::applyGizmo(EditorState& state, const ViewportView& view) {
  const GizmoPart part = static_cast<GizmoPart>(state.tool.ring);
  const bool snap = mods_ & kModCtrl;
  glm::quat delta(1, 0, 0, 0);
  const float total = sweep_.update(mouse_);
  if (part == GizmoPart::AxisX || part == GizmoPart::AxisY || part == GizmoPart::AxisZ)
    delta = axisTurnForSweep(view, gizmo_.pivot, gizmo_.axis(static_cast<int>(part) - static_cast<int>(GizmoPart::AxisX)),
                             total, snap);
  else if (part == GizmoPart::ViewRing)
    delta = axisTurnForSweep(view, gizmo_.pivot, view.towardViewer(gizmo_.pivot), total, snap);
  else
    delta = gizmoDragRotation(gizmo_, view, part, state.tool.startMouse, mouse_, snap);
  if (joints_.empty()) return;
  const int j = joints_[0];
  updateRotateDrag(state.doc, j, localRotationAfterWorldTurn(parentWorld_[0], startLocal_[0], delta));
}

namespace {
// Where a G move puts its start point with the mouse at `mouse`: in the view plane, or along
// the constrained world axis.
glm::vec3 movedPoint(const EditorState& state, const ViewportView& view, glm::vec2 mouse) {
  if (state.tool.axis == AxisConstraint::None) return dragInViewPlane(view, state.tool.startPoint, state.tool.startMouse, mouse);
  glm::vec3 axis(0.0f);
  axis[static_cast<int>(state.tool.axis) - 1] = 1.0f;
  return dragAlongAxis(view, state.tool.startPoint, axis, state.tool.startMouse, mouse);
}
}  // namespace

void ViewportTools::applyMove(EditorState& state, const ViewportView& view) {
  const glm::vec3 p = movedPoint(state, view, mouse_);
  if (state.tool.mode == ModalTool::Grab) {
    updateTranslateDrag(state.doc, 0, startTranslation_ + (p - state.tool.startPoint));
  } else if (state.tool.ikTarget >= 0) {
    updateIkTargetDrag(state.doc, state.tool.ikTarget, p);
  } else {
    updateAutoIkDrag(state.doc, p);
  }
}

void ViewportTools::applyLatticeMove(EditorState& state, const ViewportView& view) {
  const glm::vec3 p = movedPoint(state, view, mouse_);
  setLatticeMoveOffset(state, p - state.tool.startPoint);
  const glm::vec3 d = state.lattice.offset;
  char line[128];
  std::snprintf(line, sizeof line, "Move lattice points D: %.3f %.3f %.3f m%s", d.x, d.y, d.z,
                state.tool.axis == AxisConstraint::X   ? " along X"
                : state.tool.axis == AxisConstraint::Y ? " along Y"
                : state.tool.axis == AxisConstraint::Z ? " along Z"
                                                       : "");
  state.statusMessage = line;
}

void ViewportTools::latticePress(EditorState& state, const ViewportView& view) {
  const int point = pickLatticePoint(latticeWorldPoints(state), view, mouse_,
                                     kLatticePickPixels * std::max(state.preferences.lineScale, 1.0f));
  if (point >= 0) {
    clickLatticePoint(state.lattice, point, mods_ & kModShift);
    return;
  }
  pressedOnEmpty_ = true;
  state.tool.startMouse = mouse_;
}

bool ViewportTools::startLatticeGrab(EditorState& state) {
  if (state.tool.mode != ModalTool::None) return false;
  if (const std::string error = beginLatticeMove(state); !error.empty()) {
    state.statusMessage = error;
    return false;
  }
  // The grab point: the selected points' centre, where the mouse's motion is measured.
  const std::vector<glm::vec3> points = latticeWorldPoints(state);
  glm::vec3 centre(0.0f);
  for (int p : state.lattice.selected) centre += points[p];
  centre /= static_cast<float>(state.lattice.selected.size());
  state.tool = ToolState{};
  state.tool.mode = ModalTool::LatticeGrab;
  state.tool.startMouse = state.tool.mouse = mouse_;
  state.tool.startPoint = centre;
  return true;
}

void ViewportTools::armBoxSelect(EditorState& state) {
  boxArmed_ = true;
  state.statusMessage = "Box select: drag a box (Esc or right click cancels)";
}

void ViewportTools::leftPress(EditorState& state, const ViewportView& view, const SkeletonDrawList& list) {
  if (boxArmed_) {  // B: a box from here, whatever is under the mouse
    boxArmed_ = false;
    pressedOnEmpty_ = true;
    state.tool.startMouse = mouse_;
    state.statusMessage.clear();
    return;
  }
  if (state.panels.softPullPickInstance >= 0) return softPullPickPress(state, view);
  if (state.lattice.active) return latticePress(state, view);
  Document& doc = state.doc;
  const bool shift = mods_ & kModShift;
  // IK target handles first (small, explicit), then the gizmo's rings, then joints and
  // bones; nothing: a box (drag) or clearing the selection (click).
  const int handle = ikHandleUnder(state, view, mouse_);
  if (handle >= 0 && !shift) {
    state.tool = ToolState{};
    const std::string error = beginIkTargetDrag(doc, handle);
    if (!error.empty()) {
      state.statusMessage = error;
      return;
    }
    state.tool.mode = ModalTool::IkDrag;
    state.tool.ikTarget = handle;
    state.tool.startMouse = state.tool.mouse = mouse_;
    state.tool.startPoint = doc.ikTargets()[handle].target.position;
    return;
  }
  GizmoPart part = GizmoPart::None;
  if (!shift && gizmo(state, view, gizmo_)) part = hitTestRotateGizmo(gizmo_, view, mouse_);
  const SkeletonPick pick = pickAt(state, view, list);
  if (part == GizmoPart::Trackball && pick.hit() && pick.joint != doc.selection.active()) part = GizmoPart::None;
  if (part != GizmoPart::None) {
    const int j = doc.selection.active();
    state.tool = ToolState{};
    const std::string error = beginRotateDrag(doc, j);
    if (!error.empty()) {
      state.statusMessage = error;
      return;
    }
    state.tool.mode = ModalTool::GizmoDrag;
    state.tool.ring = static_cast<int>(part);
    state.tool.startMouse = state.tool.mouse = mouse_;
    joints_ = {j};
    startLocal_ = {doc.pose().local[j].rotation};
    const int parent = doc.skeleton().parents[j];
    parentWorld_ = {parent >= 0 ? jointWorldRotation(doc, parent) : glm::quat(1, 0, 0, 0)};
    glm::vec2 c;
    view.project(gizmo_.pivot, c);
    sweep_.begin(c, mouse_);
    return;
  }
  if (pick.hit()) {
    if (shift) doc.selection.shiftClick(pick.joint);
    else doc.selection.click(pick.joint);
    if (state.view.autoIk && !shift && doc.skeleton().parents[pick.joint] >= 0) {
      state.tool = ToolState{};
      const std::string error = beginAutoIkDrag(doc, pick.joint, std::max(1, state.view.autoIkChainLength));
      if (!error.empty()) {
        state.statusMessage = error;
        return;
      }
      state.tool.mode = ModalTool::IkDrag;
      state.tool.ikTarget = -1;
      state.tool.startMouse = state.tool.mouse = mouse_;
      state.tool.startPoint = jointPosition(state, pick.joint);
    }
    return;
  }
  pressedOnEmpty_ = true;
  state.tool.startMouse = mouse_;
}

void ViewportTools::mouseMove(EditorState& state, const ViewportView& view, const SkeletonDrawList& list,
                              glm::vec2 previous) {
  const glm::vec2 delta = mouse_ - previous;
  state.tool.mouse = mouse_;
  if (navigating_) {
    ViewportController controller;
    if (panning_) controller.pan(state.camera, delta, view.size.y);
    else controller.orbit(state.camera, delta);
    return;
  }
  switch (state.tool.mode) {
    case ModalTool::Rotate: applyRotate(state, view); return;
    case ModalTool::GizmoDrag: applyGizmo(state, view); return;
    case ModalTool::Grab:
    case ModalTool::IkDrag: applyMove(state, view); return;
    case ModalTool::LatticeGrab: applyLatticeMove(state, view); return;
    default: break;
  }
  if (pressedOnEmpty_ && glm::length(mouse_ - state.tool.startMouse) > kBoxThresholdPixels) {
    const glm::vec2 start = state.tool.startMouse;
    state.tool = ToolState{};
    state.tool.mode = ModalTool::BoxSelect;
    state.tool.startMouse = start;
    state.tool.mouse = mouse_;
    pressedOnEmpty_ = false;
  }
  if (state.tool.mode == ModalTool::None && state.lattice.active) {
    state.hoveredIkTarget = -1;
    state.hoveredJoint = -1;
    hoveredPart_ = GizmoPart::None;
    state.lattice.hovered = pickLatticePoint(latticeWorldPoints(state), view, mouse_,
                                             kLatticePickPixels * std::max(state.preferences.lineScale, 1.0f));
  } else if (state.tool.mode == ModalTool::None) {
    state.hoveredIkTarget = ikHandleUnder(state, view, mouse_);
    hoveredPart_ = gizmo(state, view, gizmo_) ? hitTestRotateGizmo(gizmo_, view, mouse_) : GizmoPart::None;
    state.hoveredJoint = pickAt(state, view, list).joint;
  }
}

bool ViewportTools::startRotate(EditorState& state, const ViewportView& view) {
  Document& doc = state.doc;
  if (state.tool.mode != ModalTool::None || doc.selection.empty()) return false;
  std::vector<int> turned;  // the selected joints without a selected ancestor: those R turns
  for (int j : doc.selection.joints())
    if (!hasSelectedAncestor(doc, j)) turned.push_back(j);
  if (!beginModal(state, ModalTool::Rotate, ("Rotate " + jointsPhrase(doc.skeleton(), turned)).c_str())) return false;
  joints_.clear();
  startLocal_.clear();
  parentWorld_.clear();
  startWorld_.clear();
  for (int j : doc.selection.joints()) {
    if (hasSelectedAncestor(doc, j)) continue;
    const int parent = doc.skeleton().parents[j];
    joints_.push_back(j);
    startLocal_.push_back(doc.pose().local[j].rotation);
    parentWorld_.push_back(parent >= 0 ? jointWorldRotation(doc, parent) : glm::quat(1, 0, 0, 0));
    startWorld_.push_back(jointWorldRotation(doc, j));
  }
  rotateMode_ = RotateMode{};
  const int active = doc.selection.active() >= 0 ? doc.selection.active() : doc.selection.joints().back();
  glm::vec2 c(0.0f);
  view.project(jointPosition(state, active), c);
  sweep_.begin(c, mouse_);
  return true;
}

bool ViewportTools::startGrab(EditorState& state) {
  Document& doc = state.doc;
  if (state.tool.mode != ModalTool::None || doc.skeleton().size() == 0) return false;
  state.tool = ToolState{};
  if (const std::string error = beginTranslateDrag(doc, 0); !error.empty()) {
    state.statusMessage = error;
    return false;
  }
  state.tool.mode = ModalTool::Grab;
  state.tool.startMouse = state.tool.mouse = mouse_;
  state.tool.startPoint = jointPosition(state, 0);
  startTranslation_ = doc.pose().local[0].translation;
  return true;
}

// The keys a running tool takes (every other key is a command: commands/editor_input.h).
void ViewportTools::modalKey(EditorState& state, const ViewportView& view, int key) {
  const ModalTool mode = state.tool.mode;
  if (mode == ModalTool::Rotate || mode == ModalTool::Grab || mode == ModalTool::IkDrag || mode == ModalTool::LatticeGrab) {
    if (key == keys::ESCAPE) return cancel(state);
    if (key == keys::ENTER || key == keys::KP_ENTER) return confirm(state);
    if (key == keys::X || key == keys::Y || key == keys::Z) {
      const int axis = key - keys::X;
      if (mode == ModalTool::Rotate) {
        rotateMode_.pressAxis(axis);  // global -> local -> free, as in Blender
      } else {
        state.tool.axis = state.tool.axis == axisOf(axis) ? AxisConstraint::None : axisOf(axis);
      }
    } else if (mode == ModalTool::Rotate) {
      std::string& t = state.tool.typed;
      if (key >= keys::Num0 && key <= keys::Num9) t += char('0' + key - keys::Num0);
      else if (key >= keys::KP_0 && key <= keys::KP_9) t += char('0' + key - keys::KP_0);
      else if (key == keys::MINUS || key == keys::KP_SUBTRACT) t = (!t.empty() && t[0] == '-') ? t.substr(1) : "-" + t;
      else if (key == keys::PERIOD || key == keys::KP_DECIMAL) t += '.';
      else if (key == keys::BACKSPACE && !t.empty()) t.pop_back();
    }
    if (mode == ModalTool::Rotate) applyRotate(state, view);
    else if (mode == ModalTool::LatticeGrab) applyLatticeMove(state, view);
    else applyMove(state, view);
    return;
  }
  if (mode != ModalTool::None && key == keys::ESCAPE) cancel(state);
}

void ViewportTools::handle(EditorState& state, const InputEvent& e, const ViewportView& view,
                           const SkeletonDrawList& list, bool mouseCaptured) {
  const bool toolRunning = state.tool.mode != ModalTool::None;
  mods_ = held_.track(e);
  switch (e.type) {
    case InputEventType::MouseMove: {
      const glm::vec2 previous = mouse_;
      mouse_ = glm::vec2(e.x, e.y);
      if (!mouseCaptured || toolRunning || navigating_) mouseMove(state, view, list, previous);
      else state.hoveredJoint = -1;
      break;
    }
    case InputEventType::ButtonDown: {
      const ModalTool mode = state.tool.mode;
      if (mode == ModalTool::Rotate || mode == ModalTool::Grab || mode == ModalTool::LatticeGrab) {
        if (e.button == 0) confirm(state);
        else if (e.button == 1) cancel(state);
        break;
      }
      if (mode != ModalTool::None) {
        if (e.button == 1) cancel(state);  // right click cancels a drag too
        break;
      }
      if (boxArmed_ && e.button == 1) {  // a right click disarms B
        boxArmed_ = false;
        state.statusMessage.clear();
        break;
      }
      if (mouseCaptured) break;
      if (e.button == 2 || (e.button == 0 && (mods_ & kModAlt))) {
        navigating_ = true;
        panning_ = mods_ & kModShift;
      } else if (e.button == 0) {
        leftPress(state, view, list);
      }
      break;
    }
    case InputEventType::ButtonUp: {
      if (navigating_ && (e.button == 2 || e.button == 0)) {
        navigating_ = false;
        break;
      }
      if (e.button != 0) break;
      if (state.tool.mode == ModalTool::GizmoDrag || state.tool.mode == ModalTool::IkDrag) {
        confirm(state);
      } else if (state.tool.mode == ModalTool::BoxSelect && state.lattice.active) {
        const std::vector<int> inside =
            boxSelectLatticePointsOnScreen(latticeWorldPoints(state), view, state.tool.startMouse, mouse_);
        state.tool = ToolState{};
        boxSelectLatticePoints(state.lattice, inside, (mods_ & kModShift)  ? BoxSelectMode::Extend
                                                      : (mods_ & kModCtrl) ? BoxSelectMode::Subtract
                                                                           : BoxSelectMode::Replace);
      } else if (state.tool.mode == ModalTool::BoxSelect) {
        const std::vector<int> inside = boxSelectJoints(state.world(), view, state.tool.startMouse, mouse_);
        state.tool = ToolState{};
        state.doc.selection.box(inside, (mods_ & kModShift)  ? BoxSelectMode::Extend
                                        : (mods_ & kModCtrl) ? BoxSelectMode::Subtract
                                                             : BoxSelectMode::Replace);
      } else if (pressedOnEmpty_ && !(mods_ & kModShift) && state.lattice.active) {
        selectNoLatticePoints(state.lattice);  // a click on nothing deselects the points
      } else if (pressedOnEmpty_ && !(mods_ & kModShift)) {
        state.doc.selection.clear();  // a click on nothing deselects, as in Blender
      }
      pressedOnEmpty_ = false;
      break;
    }
    case InputEventType::Scroll:
      if (!mouseCaptured) ViewportController().zoom(state.camera, e.y);
      break;
    case InputEventType::KeyDown:
      // Only a running tool takes keys here; the rest are commands (commands/editor_input.h).
      if (toolRunning && !isModifierKey(e.key)) modalKey(state, view, e.key);
      if (boxArmed_ && e.key == keys::ESCAPE) {  // Esc disarms B
        boxArmed_ = false;
        state.statusMessage.clear();
      }
      break;
    case InputEventType::KeyUp:
    case InputEventType::Text:
    case InputEventType::Command: break;
  }
}

}  // namespace kinema
