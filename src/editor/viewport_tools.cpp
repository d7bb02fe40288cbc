#include "editor/viewport_tools.h"

#include <GLFW/glfw3.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>

#include "core/forward_kinematics.h"
#include "editor/viewport_controller.h"
#include "ik/ik_solver.h"

namespace kinema {

namespace {

constexpr float kPi = 3.14159265358979f;
constexpr float kBoxThresholdPixels = 4.0f;

float distanceToSegment(glm::vec2 p, glm::vec2 a, glm::vec2 b) {
  const glm::vec2 ab = b - a;
  const float len2 = glm::dot(ab, ab);
  const float t = len2 > 0 ? std::clamp(glm::dot(p - a, ab) / len2, 0.0f, 1.0f) : 0.0f;
  return glm::length(p - (a + t * ab));
}

// World rotation of each joint from the pose's local rotations (exact, unlike reading it
// back from matrices that may carry scale).
glm::quat worldRotation(const Skeleton& s, const Pose& pose, int joint) {
  glm::quat q(1, 0, 0, 0);
  for (int j = joint; j >= 0; j = s.parents[j]) q = pose.local[j].rotation * q;
  return q;
}

// Turns `joint` by the world rotation `r` about its own position.
void rotateJointInWorld(const Skeleton& s, Pose& pose, int joint, const glm::quat& r) {
  const int parent = s.parents[joint];
  const glm::quat p = parent >= 0 ? worldRotation(s, pose, parent) : glm::quat(1, 0, 0, 0);
  pose.local[joint].rotation = glm::normalize(glm::inverse(p) * r * p * pose.local[joint].rotation);
}

bool hasSelectedAncestor(const EditorState& state, int joint) {
  for (int j = state.scene.skeleton.parents[joint]; j >= 0; j = state.scene.skeleton.parents[j])
    if (state.isSelected(j)) return true;
  return false;
}

// Screen angle of `p` around `c`, counter-clockwise as seen (screen y points down).
float screenAngle(glm::vec2 c, glm::vec2 p) { return std::atan2(-(p.y - c.y), p.x - c.x); }

float wrapAngle(float a) {
  while (a > kPi) a -= 2 * kPi;
  while (a < -kPi) a += 2 * kPi;
  return a;
}

int ancestorAt(const Skeleton& s, int joint, int steps) {
  int j = joint;
  for (int k = 0; k < steps && s.parents[j] >= 0; ++k) j = s.parents[j];
  return j;
}

}  // namespace

// ---------------------------------------------------------------- geometry

glm::mat4 orthographicProjection(const OrbitCamera& camera, float aspect) {
  const float h = camera.distance * std::tan(glm::radians(camera.fovYDeg) * 0.5f);
  return glm::ortho(-h * aspect, h * aspect, -h, h, -camera.farPlane, camera.farPlane);
}

ViewportGeometry viewportGeometry(const OrbitCamera& camera, bool orthographic, glm::vec2 size) {
  ViewportGeometry g;
  g.size = glm::max(size, glm::vec2(1.0f));
  const float aspect = g.size.x / g.size.y;
  g.view = camera.view();
  g.orthographic = orthographic;
  g.projection = orthographic ? orthographicProjection(camera, aspect) : camera.projection(aspect);
  g.viewProjection = g.projection * g.view;
  g.eye = camera.eye();
  g.forward = camera.forward();
  g.right = glm::vec3(g.view[0][0], g.view[1][0], g.view[2][0]);
  g.up = glm::vec3(g.view[0][1], g.view[1][1], g.view[2][1]);
  g.fovY = glm::radians(camera.fovYDeg);
  g.orthoHalfHeight = camera.distance * std::tan(g.fovY * 0.5f);
  return g;
}

bool ViewportGeometry::toScreen(const glm::vec3& world, glm::vec2& pixel) const {
  const glm::vec4 clip = viewProjection * glm::vec4(world, 1.0f);
  if (clip.w <= 1e-6f) return false;
  const glm::vec2 ndc = glm::vec2(clip) / clip.w;
  pixel = glm::vec2((ndc.x * 0.5f + 0.5f) * size.x, (0.5f - ndc.y * 0.5f) * size.y);
  return true;
}

float ViewportGeometry::unitsPerPixel(const glm::vec3& world) const {
  if (orthographic) return 2.0f * orthoHalfHeight / size.y;
  const float depth = std::max(glm::dot(world - eye, forward), 1e-4f);
  return 2.0f * depth * std::tan(fovY * 0.5f) / size.y;
}

glm::vec3 ViewportGeometry::screenDeltaToWorld(const glm::vec3& world, glm::vec2 pixels) const {
  return (right * pixels.x - up * pixels.y) * unitsPerPixel(world);
}

int pickJointOrBone(const EditorState& state, const ViewportGeometry& g, glm::vec2 cursor, float radius) {
  const std::vector<int>& parents = state.scene.skeleton.parents;
  const int n = static_cast<int>(state.world.size());
  std::vector<glm::vec2> screen(n);
  std::vector<char> visible(n);
  for (int i = 0; i < n; ++i) visible[i] = g.toScreen(glm::vec3(state.world[i][3]), screen[i]);
  // A joint point within 3/4 of the radius wins over any bone (bones end at joints).
  int best = -1;
  float bestDistance = radius * 0.75f;
  for (int i = 0; i < n; ++i) {
    if (!visible[i]) continue;
    const float d = glm::length(cursor - screen[i]);
    if (d < bestDistance) {
      bestDistance = d;
      best = i;
    }
  }
  if (best >= 0) return best;
  bestDistance = radius;
  for (int i = 0; i < n; ++i) {
    const int p = parents[i];
    if (p < 0 || !visible[i] || !visible[p]) continue;
    const float d = distanceToSegment(cursor, screen[p], screen[i]);
    if (d < bestDistance) {
      bestDistance = d;
      best = p;
    }
  }
  return best;
}

std::vector<int> jointsInBox(const EditorState& state, const ViewportGeometry& g, glm::vec2 a, glm::vec2 b) {
  const glm::vec2 lo = glm::min(a, b), hi = glm::max(a, b);
  std::vector<int> out;
  for (int i = 0; i < static_cast<int>(state.world.size()); ++i) {
    glm::vec2 p;
    if (g.toScreen(glm::vec3(state.world[i][3]), p) && p.x >= lo.x && p.x <= hi.x && p.y >= lo.y && p.y <= hi.y)
      out.push_back(i);
  }
  return out;
}

GizmoGeometry gizmoGeometry(const EditorState& state, const ViewportGeometry& g) {
  GizmoGeometry gizmo;
  const int j = state.activeJoint;
  if (j < 0 || j >= static_cast<int>(state.world.size()) || !state.view.showGizmo) return gizmo;
  gizmo.center = glm::vec3(state.world[j][3]);
  glm::vec2 c;
  if (!g.toScreen(gizmo.center, c)) return gizmo;
  gizmo.radiusWorld = gizmo.radiusPixels * g.unitsPerPixel(gizmo.center);
  const glm::quat r = state.view.localGizmo ? worldRotation(state.scene.skeleton, state.pose, j) : glm::quat(1, 0, 0, 0);
  for (int k = 0; k < 3; ++k) {
    glm::vec3 e(0.0f);
    e[k] = 1.0f;
    gizmo.axes[k] = r * e;
  }
  gizmo.valid = true;
  return gizmo;
}

int pickGizmoRing(const GizmoGeometry& gizmo, const ViewportGeometry& g, glm::vec2 cursor) {
  if (!gizmo.valid) return -1;
  glm::vec2 c;
  if (!g.toScreen(gizmo.center, c)) return -1;
  int best = -1;
  float bestDistance = 7.0f;
  for (int k = 0; k < 3; ++k) {
    const glm::vec3 a = gizmo.axes[k];
    const glm::vec3 u = glm::normalize(std::abs(a.x) < 0.9f ? glm::cross(a, glm::vec3(1, 0, 0)) : glm::cross(a, glm::vec3(0, 1, 0)));
    const glm::vec3 v = glm::cross(a, u);
    glm::vec2 prev(0.0f);
    bool havePrev = false;
    for (int s = 0; s <= 64; ++s) {
      const float t = 2 * kPi * s / 64;
      glm::vec2 p;
      const bool ok = g.toScreen(gizmo.center + gizmo.radiusWorld * (std::cos(t) * u + std::sin(t) * v), p);
      if (ok && havePrev) {
        const float d = distanceToSegment(cursor, prev, p);
        if (d < bestDistance) {
          bestDistance = d;
          best = k;
        }
      }
      prev = p;
      havePrev = ok;
    }
  }
  const float r = glm::length(cursor - c);
  if (std::abs(r - gizmo.radiusPixels * 1.25f) < bestDistance) best = 3;
  if (best < 0 && r < gizmo.radiusPixels * 0.9f) best = 4;
  return best;
}

// ---------------------------------------------------------------- edits

void pushUndo(EditorState& state, const Pose& before) {
  state.undoPoses.push_back(before);
  state.redoPoses.clear();
  state.undoDepth = static_cast<int>(state.undoPoses.size());
  state.dirty = true;
}

void undoEdit(EditorState& state) {
  if (state.undoPoses.empty()) return;
  state.redoPoses.push_back(state.pose);
  state.pose = state.undoPoses.back();
  state.undoPoses.pop_back();
  state.undoDepth = static_cast<int>(state.undoPoses.size());
  state.dirty = true;
}

void redoEdit(EditorState& state) {
  if (state.redoPoses.empty()) return;
  state.undoPoses.push_back(state.pose);
  state.pose = state.redoPoses.back();
  state.redoPoses.pop_back();
  state.undoDepth = static_cast<int>(state.undoPoses.size());
  state.dirty = true;
}

void clearSelectedRotations(EditorState& state) {
  if (state.selection.empty()) return;
  const Pose before = state.pose;
  for (int j : state.selection) state.pose.local[j].rotation = state.scene.skeleton.rest[j].rotation;
  pushUndo(state, before);
}

void copySelectedPose(EditorState& state) {
  state.clipboard.clear();
  for (int j : state.selection) state.clipboard.emplace_back(state.scene.skeleton.names[j], state.pose.local[j]);
  state.statusMessage = "copied " + std::to_string(state.clipboard.size()) + " joints";
}

namespace {
std::string mirrorName(const std::string& name) {
  auto swapSuffix = [&](const char* a, const char* b) -> std::string {
    const size_t n = std::string(a).size();
    if (name.size() > n && name.compare(name.size() - n, n, a) == 0) return name.substr(0, name.size() - n) + b;
    return "";
  };
  for (auto [a, b] : {std::pair{".L", ".R"}, {".R", ".L"}, {"_L", "_R"}, {"_R", "_L"}, {"Left", "Right"}, {"Right", "Left"}})
    if (std::string m = swapSuffix(a, b); !m.empty()) return m;
  for (auto [a, b] : {std::pair{"Left", "Right"}, {"Right", "Left"}})
    if (name.compare(0, std::string(a).size(), a) == 0) return b + name.substr(std::string(a).size());
  return name;
}
}  // namespace

void pastePose(EditorState& state, bool flipped) {
  if (state.clipboard.empty()) return;
  const Pose before = state.pose;
  int pasted = 0;
  for (const auto& [name, t] : state.clipboard) {
    const int j = state.scene.skeleton.find(flipped ? mirrorName(name) : name);
    if (j < 0) continue;
    Transform m = t;
    if (flipped) {  // mirror across the YZ plane: x -> -x
      m.rotation = glm::quat(t.rotation.w, t.rotation.x, -t.rotation.y, -t.rotation.z);
      m.translation.x = -t.translation.x;
    }
    state.pose.local[j].rotation = m.rotation;
    if (state.scene.skeleton.parents[j] < 0) state.pose.local[j].translation = m.translation;
    ++pasted;
  }
  if (pasted > 0) pushUndo(state, before);
}

void solveIkTargets(EditorState& state, const std::vector<IkTarget>& extra) {
  std::vector<IkTarget> targets = state.scene.ik.targets;
  targets.insert(targets.end(), extra.begin(), extra.end());
  state.ikStatus.assign(targets.size(), EditorIkStatus{});
  const Skeleton& s = state.scene.skeleton;
  for (size_t i = 0; i < targets.size(); ++i) {
    const IkTarget& t = targets[i];
    if (!t.validate(s).empty()) continue;
    // Two joints above the effector: the closed-form two-bone solver; longer chains: DLS.
    const bool twoBone = t.root >= 0 && s.parents[t.effector] >= 0 && s.parents[s.parents[t.effector]] == t.root;
    IkProblem problem;
    problem.skeleton = &s;
    problem.pose = &state.pose;
    problem.rig = &state.scene.ik;
    problem.targets = {t};
    IkSettings settings;
    settings.maxIterations = 50;
    const auto start = std::chrono::steady_clock::now();
    const IkResult r = solveIk(twoBone ? IkSolver::TwoBone : IkSolver::JacobianDls, problem, settings);
    const auto end = std::chrono::steady_clock::now();
    EditorIkStatus& st = state.ikStatus[i];
    st.iterations = r.iterations;
    st.error = r.error;
    st.converged = r.converged;
    st.milliseconds = std::chrono::duration<double, std::milli>(end - start).count();
  }
  computeWorld(s, state.pose, state.world);
}

void frameSelection(EditorState& state, float aspect, bool all) {
  Bounds b;
  if (!all)
    for (int j : state.selection) b.add(glm::vec3(state.world[j][3]));
  if (b.empty) b = jointBounds(state.world);
  if (b.empty) return;
  // One joint has no size: frame a sphere a tenth of the skeleton's around it.
  const float minRadius = 0.1f * std::max(jointBounds(state.world).radius(), 1e-3f);
  if (b.radius() < minRadius) {
    const glm::vec3 c = b.center();
    b.add(c + glm::vec3(minRadius * 0.7f));
    b.add(c - glm::vec3(minRadius * 0.7f));
  }
  state.camera.frame(b, aspect);
  state.camera.fitClipPlanes(jointBounds(state.world).radius());
}

void setViewPreset(EditorState& state, int preset, bool opposite) {
  switch (preset) {
    case 1: state.camera.azimuthDeg = opposite ? 180.0f : 0.0f; state.camera.elevationDeg = 0.0f; break;
    case 3: state.camera.azimuthDeg = opposite ? -90.0f : 90.0f; state.camera.elevationDeg = 0.0f; break;
    case 7: state.camera.azimuthDeg = 0.0f; state.camera.elevationDeg = opposite ? -89.9f : 89.9f; break;
    default: break;
  }
}

// ---------------------------------------------------------------- the tools

void ViewportTools::beginTool(EditorState& state, ModalTool tool) {
  state.tool = ToolState{};
  state.tool.mode = tool;
  state.tool.startMouse = mouse_;
  state.tool.mouse = mouse_;
  state.tool.startPose = state.pose;
  angle_ = 0.0f;
  lastAngle_ = 0.0f;
}

void ViewportTools::confirmTool(EditorState& state) {
  const ModalTool mode = state.tool.mode;
  if (mode == ModalTool::Rotate || mode == ModalTool::Grab || mode == ModalTool::GizmoDrag || mode == ModalTool::IkDrag) {
    bool changed = false;
    for (int j = 0; j < state.pose.size(); ++j) {
      const Transform& a = state.pose.local[j];
      const Transform& b = state.tool.startPose.local[j];
      if (a.rotation != b.rotation || a.translation != b.translation) changed = true;
    }
    if (changed) pushUndo(state, state.tool.startPose);
  }
  state.tool = ToolState{};
  autoIk_ = false;
}

void ViewportTools::cancelTool(EditorState& state) {
  if (state.tool.mode != ModalTool::BoxSelect && state.tool.mode != ModalTool::None) state.pose = state.tool.startPose;
  if (state.tool.mode == ModalTool::IkDrag && state.tool.ikTarget >= 0 &&
      state.tool.ikTarget < static_cast<int>(state.scene.ik.targets.size()))
    state.scene.ik.targets[state.tool.ikTarget].position = dragStart_;
  state.tool = ToolState{};
  autoIk_ = false;
}

glm::vec3 ViewportTools::constrainedAxis(const EditorState& state, int joint) const {
  glm::vec3 e(0.0f);
  e[static_cast<int>(state.tool.axis) - 1] = 1.0f;
  if (!state.tool.localAxes || joint < 0) return e;
  return worldRotation(state.scene.skeleton, state.pose, joint) * e;
}

void ViewportTools::applyRotate(EditorState& state, const ViewportGeometry& g) {
  glm::vec2 c;
  if (!g.toScreen(pivot_, c)) return;
  const float a = screenAngle(c, mouse_);
  angle_ += wrapAngle(a - lastAngle_);
  lastAngle_ = a;
  const bool typed = !state.tool.typed.empty();
  float angle = angle_;
  if (typed) {
    char* end = nullptr;
    const double deg = std::strtod(state.tool.typed.c_str(), &end);
    angle = std::isfinite(deg) ? static_cast<float>(glm::radians(deg)) : 0.0f;
  }
  state.pose = state.tool.startPose;
  const Skeleton& s = state.scene.skeleton;
  for (int j : state.selection) {
    if (hasSelectedAncestor(state, j)) continue;
    glm::vec3 axis = -g.forward;  // towards the viewer: a counter-clockwise drag turns counter-clockwise
    float sign = 1.0f;
    if (state.tool.axis != AxisConstraint::None) {
      axis = constrainedAxis(state, j);
      if (!typed) sign = glm::dot(axis, -g.forward) >= 0.0f ? 1.0f : -1.0f;
    }
    rotateJointInWorld(s, state.pose, j, glm::angleAxis(sign * angle, glm::normalize(axis)));
  }
  char line[96];
  std::snprintf(line, sizeof line, "Rotate %.1f deg %s%s", glm::degrees(angle),
                state.tool.axis == AxisConstraint::None ? "" : (state.tool.axis == AxisConstraint::X ? "X" : state.tool.axis == AxisConstraint::Y ? "Y" : "Z"),
                state.tool.localAxes ? " local" : "");
  state.statusMessage = line;
}

void ViewportTools::applyGrab(EditorState& state, const ViewportGeometry& g) {
  const glm::vec2 delta = mouse_ - state.tool.startMouse;
  glm::vec3 move = g.screenDeltaToWorld(dragStart_, delta);
  if (state.tool.axis != AxisConstraint::None) {
    const glm::vec3 axis = constrainedAxis(state, -1);
    // Follow the mouse along the axis's on-screen direction.
    const float upp = g.unitsPerPixel(dragStart_);
    glm::vec2 a, b;
    move = glm::vec3(0.0f);
    if (g.toScreen(dragStart_, a) && g.toScreen(dragStart_ + axis * upp * 100.0f, b) && glm::length(b - a) > 1e-3f) {
      const float len = glm::length(b - a);
      move = axis * glm::dot(delta, (b - a) / len) * (upp * 100.0f / len);
    }
  }
  state.pose = state.tool.startPose;
  state.pose.local[0].translation = state.tool.startPose.local[0].translation + move;
}

void ViewportTools::applyGizmo(EditorState& state, const ViewportGeometry& g) {
  const int j = state.activeJoint;
  if (j < 0) return;
  glm::vec2 c;
  if (!g.toScreen(pivot_, c)) return;
  state.pose = state.tool.startPose;
  glm::quat r(1, 0, 0, 0);
  if (state.tool.ring == 4) {  // trackball: drag right turns about the view's up axis
    const glm::vec2 d = mouse_ - state.tool.startMouse;
    const float len = glm::length(d);
    if (len < 1e-3f) return;
    r = glm::angleAxis(len * 0.01f, glm::normalize(g.up * d.x + g.right * d.y));
  } else {
    const float a = screenAngle(c, mouse_);
    angle_ += wrapAngle(a - lastAngle_);
    lastAngle_ = a;
    glm::vec3 axis = -g.forward;
    if (state.tool.ring < 3) {
      const GizmoGeometry gizmo = gizmoGeometry(state, g);
      axis = gizmo.axes[state.tool.ring];
    }
    const float sign = glm::dot(axis, -g.forward) >= 0.0f ? 1.0f : -1.0f;
    r = glm::angleAxis(sign * angle_, glm::normalize(axis));
  }
  rotateJointInWorld(state.scene.skeleton, state.pose, j, r);
}

void ViewportTools::applyIkDrag(EditorState& state, const ViewportGeometry& g) {
  const glm::vec2 delta = mouse_ - state.tool.startMouse;
  glm::vec3 move = g.screenDeltaToWorld(dragStart_, delta);
  if (state.tool.axis != AxisConstraint::None) {
    const glm::vec3 axis = constrainedAxis(state, -1);
    const float upp = g.unitsPerPixel(dragStart_);
    glm::vec2 a, b;
    move = glm::vec3(0.0f);
    if (g.toScreen(dragStart_, a) && g.toScreen(dragStart_ + axis * upp * 100.0f, b) && glm::length(b - a) > 1e-3f) {
      const float len = glm::length(b - a);
      move = axis * glm::dot(delta, (b - a) / len) * (upp * 100.0f / len);
    }
  }
  if (autoIk_) autoIkTarget_.position = dragStart_ + move;
  else if (state.tool.ikTarget >= 0 && state.tool.ikTarget < static_cast<int>(state.scene.ik.targets.size()))
    state.scene.ik.targets[state.tool.ikTarget].position = dragStart_ + move;
}

void ViewportTools::update(EditorState& state) {
  // The chain follows the target every frame of the drag.
  if (state.tool.mode == ModalTool::IkDrag) {
    if (autoIk_) solveIkTargets(state, {autoIkTarget_});
    else solveIkTargets(state);
  }
}

void ViewportTools::leftPress(EditorState& state, const ViewportGeometry& g) {
  const bool shift = mods_ & kModShift;
  // IK target handles first (small, explicit), then the gizmo's rings, then joints;
  // nothing: a box (drag) or clearing the selection (click).
  for (int i = 0; i < static_cast<int>(state.scene.ik.targets.size()); ++i) {
    glm::vec2 p;
    if (g.toScreen(state.scene.ik.targets[i].position, p) && glm::length(p - mouse_) < 9.0f) {
      beginTool(state, ModalTool::IkDrag);
      state.tool.ikTarget = i;
      dragStart_ = state.scene.ik.targets[i].position;
      return;
    }
  }
  const GizmoGeometry gizmo = gizmoGeometry(state, g);
  const int ring = state.selection.empty() ? -1 : pickGizmoRing(gizmo, g, mouse_);
  const int joint = pickJointOrBone(state, g, mouse_);
  if (ring >= 0 && ring < 4 && !shift) {
    beginTool(state, ModalTool::GizmoDrag);
    state.tool.ring = ring;
    pivot_ = gizmo.center;
    glm::vec2 c;
    if (g.toScreen(pivot_, c)) lastAngle_ = screenAngle(c, mouse_);
    return;
  }
  if (joint >= 0) {
    if (shift) toggleSelection(state, joint);
    else if (!state.isSelected(joint) || state.activeJoint != joint) setSelection(state, {joint});
    if (state.view.autoIk && !shift && state.scene.skeleton.parents[joint] >= 0) {
      beginTool(state, ModalTool::IkDrag);
      autoIk_ = true;
      autoIkTarget_ = IkTarget{};
      autoIkTarget_.effector = joint;
      autoIkTarget_.root = ancestorAt(state.scene.skeleton, joint, std::max(1, state.view.autoIkChainLength));
      dragStart_ = autoIkTarget_.position = glm::vec3(state.world[joint][3]);
    }
    return;
  }
  if (ring == 4 && !shift) {
    beginTool(state, ModalTool::GizmoDrag);
    state.tool.ring = 4;
    pivot_ = gizmo.center;
    return;
  }
  pressedOnEmpty_ = true;
  state.tool.startMouse = mouse_;
}

void ViewportTools::mouseMove(EditorState& state, const ViewportGeometry& g, glm::vec2 previous) {
  const glm::vec2 delta = mouse_ - previous;
  state.tool.mouse = mouse_;
  ViewportController controller;
  if (navigating_) {
    if (panning_) controller.pan(state.camera, delta, g.size.y);
    else controller.orbit(state.camera, delta);
    return;
  }
  switch (state.tool.mode) {
    case ModalTool::Rotate: applyRotate(state, g); return;
    case ModalTool::Grab: applyGrab(state, g); return;
    case ModalTool::GizmoDrag: applyGizmo(state, g); return;
    case ModalTool::IkDrag: applyIkDrag(state, g); return;
    default: break;
  }
  if (pressedOnEmpty_ && glm::length(mouse_ - state.tool.startMouse) > kBoxThresholdPixels) {
    const glm::vec2 start = state.tool.startMouse;
    beginTool(state, ModalTool::BoxSelect);
    state.tool.startMouse = start;
    pressedOnEmpty_ = false;
  }
  if (state.tool.mode == ModalTool::None) {
    state.hoveredJoint = pickJointOrBone(state, g, mouse_);
    state.hoveredIkTarget = -1;
    for (int i = 0; i < static_cast<int>(state.scene.ik.targets.size()); ++i) {
      glm::vec2 p;
      if (g.toScreen(state.scene.ik.targets[i].position, p) && glm::length(p - mouse_) < 9.0f) state.hoveredIkTarget = i;
    }
  }
}

void ViewportTools::key(EditorState& state, const ViewportGeometry& g, int key) {
  const bool ctrl = mods_ & kModCtrl, shift = mods_ & kModShift, alt = mods_ & kModAlt;
  const ModalTool mode = state.tool.mode;
  const bool modal = mode == ModalTool::Rotate || mode == ModalTool::Grab || mode == ModalTool::IkDrag;
  if (modal) {
    if (key == GLFW_KEY_X || key == GLFW_KEY_Y || key == GLFW_KEY_Z) {
      const AxisConstraint axis = key == GLFW_KEY_X ? AxisConstraint::X : key == GLFW_KEY_Y ? AxisConstraint::Y : AxisConstraint::Z;
      // Blender: the first press constrains to the global axis, the second to the local one, the third frees.
      if (state.tool.axis != axis) {
        state.tool.axis = axis;
        state.tool.localAxes = false;
      } else if (!state.tool.localAxes && mode == ModalTool::Rotate) {
        state.tool.localAxes = true;
      } else {
        state.tool.axis = AxisConstraint::None;
        state.tool.localAxes = false;
      }
    } else if (key == GLFW_KEY_ESCAPE) {
      cancelTool(state);
      return;
    } else if (key == GLFW_KEY_ENTER || key == GLFW_KEY_KP_ENTER) {
      confirmTool(state);
      return;
    } else if (mode == ModalTool::Rotate) {
      std::string& t = state.tool.typed;
      if (key >= GLFW_KEY_0 && key <= GLFW_KEY_9) t += char('0' + key - GLFW_KEY_0);
      else if (key >= GLFW_KEY_KP_0 && key <= GLFW_KEY_KP_9) t += char('0' + key - GLFW_KEY_KP_0);
      else if (key == GLFW_KEY_MINUS || key == GLFW_KEY_KP_SUBTRACT) t = (!t.empty() && t[0] == '-') ? t.substr(1) : "-" + t;
      else if (key == GLFW_KEY_PERIOD || key == GLFW_KEY_KP_DECIMAL) t += '.';
      else if (key == GLFW_KEY_BACKSPACE && !t.empty()) t.pop_back();
    }
    if (mode == ModalTool::Rotate) applyRotate(state, g);
    else if (mode == ModalTool::Grab) applyGrab(state, g);
    else applyIkDrag(state, g);
    return;
  }
  if (mode != ModalTool::None) {
    if (key == GLFW_KEY_ESCAPE) cancelTool(state);
    return;
  }
  const float aspect = g.size.x / g.size.y;
  if (ctrl) {
    if (key == GLFW_KEY_Z && shift) redoEdit(state);
    else if (key == GLFW_KEY_Z || (key == GLFW_KEY_Y && !shift)) key == GLFW_KEY_Z ? undoEdit(state) : redoEdit(state);
    else if (key == GLFW_KEY_S) (shift ? state.requests.saveAs : state.requests.save) = true;
    else if (key == GLFW_KEY_O) state.requests.open = true;
    else if (key == GLFW_KEY_N) state.requests.newFile = true;
    else if (key == GLFW_KEY_C) copySelectedPose(state);
    else if (key == GLFW_KEY_V) pastePose(state, shift);
    else if (key == GLFW_KEY_I) state.view.autoIk = !state.view.autoIk;
    else if (key == GLFW_KEY_Q) state.requests.quit = true;
    else if (key == GLFW_KEY_KP_1 || key == GLFW_KEY_KP_3 || key == GLFW_KEY_KP_7)
      setViewPreset(state, key == GLFW_KEY_KP_1 ? 1 : key == GLFW_KEY_KP_3 ? 3 : 7, true);
    return;
  }
  switch (key) {
    case GLFW_KEY_R:
      if (alt) {
        clearSelectedRotations(state);
      } else if (!state.selection.empty()) {
        beginTool(state, ModalTool::Rotate);
        pivot_ = glm::vec3(state.world[state.activeJoint >= 0 ? state.activeJoint : state.selection.back()][3]);
        glm::vec2 c;
        if (g.toScreen(pivot_, c)) lastAngle_ = screenAngle(c, mouse_);
      }
      break;
    case GLFW_KEY_G:
      if (state.pose.size() > 0) {
        beginTool(state, ModalTool::Grab);
        dragStart_ = glm::vec3(state.world[0][3]);
      }
      break;
    case GLFW_KEY_I:
      // Shift+I: an IK target on the active joint, two bones up (Blender's "Add IK").
      if (shift && state.activeJoint >= 0 && state.scene.skeleton.parents[state.activeJoint] >= 0) {
        IkTarget t;
        t.effector = state.activeJoint;
        t.root = ancestorAt(state.scene.skeleton, state.activeJoint, 2);
        t.position = glm::vec3(state.world[state.activeJoint][3]);
        state.scene.ik.targets.push_back(t);
        state.ikStatus.resize(state.scene.ik.targets.size());
        state.dirty = true;
      }
      break;
    case GLFW_KEY_A:
      if (alt) setSelection(state, {});
      else {
        std::vector<int> all(state.scene.skeleton.size());
        for (int i = 0; i < static_cast<int>(all.size()); ++i) all[i] = i;
        setSelection(state, all);
      }
      break;
    case GLFW_KEY_ESCAPE: setSelection(state, {}); break;
    case GLFW_KEY_F: frameSelection(state, aspect, false); break;
    case GLFW_KEY_HOME: frameSelection(state, aspect, true); break;
    case GLFW_KEY_KP_1: setViewPreset(state, 1, false); break;
    case GLFW_KEY_KP_3: setViewPreset(state, 3, false); break;
    case GLFW_KEY_KP_7: setViewPreset(state, 7, false); break;
    case GLFW_KEY_KP_5: state.orthographic = !state.orthographic; break;
    case GLFW_KEY_SPACE:
      if (state.hasMotion()) state.playing = !state.playing;
      break;
    default: break;
  }
}

void ViewportTools::handle(EditorState& state, const InputEvent& e, const ViewportGeometry& g, bool mouseCaptured,
                           bool keyboardCaptured) {
  const bool toolRunning = state.tool.mode != ModalTool::None;
  mods_ = heldMods_ | e.mods;
  switch (e.type) {
    case InputEventType::MouseMove: {
      const glm::vec2 previous = mouse_;
      mouse_ = glm::vec2(e.x, e.y);
      if (!mouseCaptured || toolRunning || navigating_) mouseMove(state, g, previous);
      else state.hoveredJoint = -1;
      break;
    }
    case InputEventType::ButtonDown: {
      if (e.button >= 0 && e.button < 8) buttons_[e.button] = true;
      const ModalTool mode = state.tool.mode;
      if (mode == ModalTool::Rotate || mode == ModalTool::Grab || (mode == ModalTool::IkDrag && !buttons_[0])) {
        if (e.button == 0) confirmTool(state);
        else if (e.button == 1) cancelTool(state);
        break;
      }
      if (mode != ModalTool::None) {
        if (e.button == 1) cancelTool(state);  // right click cancels a drag too
        break;
      }
      if (mouseCaptured) break;
      if (e.button == 2 || (e.button == 0 && (mods_ & kModAlt))) {
        navigating_ = true;
        panning_ = mods_ & kModShift;
      } else if (e.button == 0) {
        leftPress(state, g);
      }
      break;
    }
    case InputEventType::ButtonUp: {
      if (e.button >= 0 && e.button < 8) buttons_[e.button] = false;
      if (navigating_ && (e.button == 2 || e.button == 0)) {
        navigating_ = false;
        break;
      }
      if (e.button != 0) break;
      if (state.tool.mode == ModalTool::GizmoDrag || state.tool.mode == ModalTool::IkDrag) {
        confirmTool(state);
      } else if (state.tool.mode == ModalTool::BoxSelect) {
        const std::vector<int> inside = jointsInBox(state, g, state.tool.startMouse, mouse_);
        state.tool = ToolState{};
        if (mods_ & kModShift) {
          for (int j : inside)
            if (!state.isSelected(j)) toggleSelection(state, j);
        } else {
          setSelection(state, inside);
        }
      } else if (pressedOnEmpty_ && !(mods_ & kModShift)) {
        setSelection(state, {});  // a click on nothing deselects, as in Blender
      }
      pressedOnEmpty_ = false;
      break;
    }
    case InputEventType::Scroll:
      if (!mouseCaptured) ViewportController().zoom(state.camera, e.y);
      break;
    case InputEventType::KeyDown: {
      // Modifiers come from the keys held (scripts) or the event's bits (GLFW).
      if (e.key == GLFW_KEY_LEFT_SHIFT || e.key == GLFW_KEY_RIGHT_SHIFT) heldMods_ |= kModShift;
      else if (e.key == GLFW_KEY_LEFT_CONTROL || e.key == GLFW_KEY_RIGHT_CONTROL) heldMods_ |= kModCtrl;
      else if (e.key == GLFW_KEY_LEFT_ALT || e.key == GLFW_KEY_RIGHT_ALT) heldMods_ |= kModAlt;
      else if (!keyboardCaptured || toolRunning) key(state, g, e.key);
      break;
    }
    case InputEventType::KeyUp:
      if (e.key == GLFW_KEY_LEFT_SHIFT || e.key == GLFW_KEY_RIGHT_SHIFT) heldMods_ &= ~kModShift;
      else if (e.key == GLFW_KEY_LEFT_CONTROL || e.key == GLFW_KEY_RIGHT_CONTROL) heldMods_ &= ~kModCtrl;
      else if (e.key == GLFW_KEY_LEFT_ALT || e.key == GLFW_KEY_RIGHT_ALT) heldMods_ &= ~kModAlt;
      break;
    case InputEventType::Text: break;
  }
}

}  // namespace kinema
