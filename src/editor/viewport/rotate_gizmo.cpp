#include "editor/viewport/rotate_gizmo.h"
#include "core/math.h"

#include <algorithm>
#include <limits>

namespace kinema {

namespace {

glm::vec3 unitAxis(int i) {
  glm::vec3 a(0.0f);
  a[i] = 1.0f;
  return a;
}

float distanceToSegment(glm::vec2 p, glm::vec2 a, glm::vec2 b) {
  const glm::vec2 ab = b - a;
  const float len2 = glm::dot(ab, ab);
  const float t = len2 > 0.0f ? std::clamp(glm::dot(p - a, ab) / len2, 0.0f, 1.0f) : 0.0f;
  return glm::length(p - (a + ab * t));
}
}  // namespace

glm::quat RotateGizmo::axesFor(GizmoOrientation orientation, const glm::quat& jointWorldRotation) {
  return orientation == GizmoOrientation::Local ? glm::normalize(jointWorldRotation) : glm::quat(1, 0, 0, 0);
}

glm::vec3 RotateGizmo::axis(int i) const { return glm::normalize(axesRotation * unitAxis(i)); }

float RotateGizmo::ringRadiusWorld(const ViewportView& view) const {
  return ringRadiusPixels * view.unitsPerPixelAt(pivot);
}

std::vector<glm::vec3> RotateGizmo::ringPoints(const ViewportView& view, int i, int segments) const {
  segments = std::max(segments, 3);
  glm::vec3 u, v;
  float radius;
  if (i >= 0 && i < 3) {
    // The ring about axis i lies in the plane of the two other axes of the frame.
    u = axis((i + 1) % 3);
    v = axis((i + 2) % 3);
    radius = ringRadiusWorld(view);
  } else {
    // Parallel to the image plane, so it projects to an exact circle of the pixel radius.
    u = view.right();
    v = view.up();
    radius = viewRingRadiusPixels * view.unitsPerPixelAt(pivot);
  }
  std::vector<glm::vec3> points;
  points.reserve(segments);
  for (int k = 0; k < segments; ++k) {
    const float a = 2.0f * kPi * static_cast<float>(k) / static_cast<float>(segments);
    points.push_back(pivot + (u * std::cos(a) + v * std::sin(a)) * radius);
  }
  return points;
}

float rotateGizmoRingPixels(const ViewportView& view, const std::vector<glm::mat4>& world, const std::vector<int>& parents,
                            int joint, float maxPixels, float tolerancePixels) {
  const int n = static_cast<int>(std::min(world.size(), parents.size()));
  glm::vec2 centre;
  if (joint < 0 || joint >= n || !view.project(glm::vec3(world[joint][3]), centre)) return maxPixels;
  auto carried = [&](int k) {  // k is the joint or one of its descendants
    for (int a = k; a >= 0 && a < n; a = parents[a])
      if (a == joint) return true;
    return false;
  };
  float radius = maxPixels;
  for (int k = 0; k < n; ++k) {
    if (k == parents[joint] || carried(k)) continue;
    glm::vec2 p;
    if (!view.project(glm::vec3(world[k][3]), p)) continue;
    const float d = glm::length(p - centre);
    if (d >= 1.0f) radius = std::min(radius, (0.5f * d - tolerancePixels) / kViewRingScale);
  }
  return std::max(radius, std::min(kMinGizmoRingPixels, maxPixels));
}

bool ringSegmentFacesViewer(const RotateGizmo& gizmo, const ViewportView& view, const glm::vec3& a,
                            const glm::vec3& b) {
  // Blender clips its dials by the plane through the centre normal to the VIEW AXIS, not to
  // the line from the eye to the centre: a ring parallel to the image plane is a full circle
  // on screen wherever it sits in a perspective view, so it must be whole. The plane sits a
  // little behind the centre (2% of the radius) so a nearly face-on ring is whole as well and
  // the drawn arc grows smoothly from half to whole as a ring turns towards the viewer.
  constexpr float kClipBias = 0.02f;
  const glm::vec3 mid = (a + b) * 0.5f - gizmo.pivot;
  return glm::dot(mid, -view.forward()) >= -kClipBias * glm::length(mid);
}

GizmoPart hitTestRotateGizmo(const RotateGizmo& gizmo, const ViewportView& view, glm::vec2 cursor) {
  glm::vec2 center;
  if (!view.project(gizmo.pivot, center)) return GizmoPart::None;
  const GizmoPart parts[4] = {GizmoPart::AxisX, GizmoPart::AxisY, GizmoPart::AxisZ, GizmoPart::ViewRing};
  GizmoPart best = GizmoPart::None;
  float bestDistance = gizmo.tolerancePixels;
  for (int i = 0; i < 4; ++i) {
    const std::vector<glm::vec3> ring = gizmo.ringPoints(view, i);
    for (size_t k = 0; k < ring.size(); ++k) {
      const glm::vec3& a = ring[k];
      const glm::vec3& b = ring[(k + 1) % ring.size()];
      // Axis rings: only the half facing the viewer is drawn (as in Blender), so only it grabs.
      if (i < 3 && !ringSegmentFacesViewer(gizmo, view, a, b)) continue;
      glm::vec2 pa, pb;
      if (!view.project(a, pa) || !view.project(b, pb)) continue;
      const float d = distanceToSegment(cursor, pa, pb);
      if (d <= bestDistance) {
        bestDistance = d;
        best = parts[i];
      }
    }
  }
  if (best != GizmoPart::None) return best;
  if (glm::length(cursor - center) < gizmo.ringRadiusPixels) return GizmoPart::Trackball;
  return GizmoPart::None;
}

float sweptAngle(glm::vec2 center, glm::vec2 from, glm::vec2 to) {
  // Flip y so that counter-clockwise on screen is the positive direction.
  const glm::vec2 a(from.x - center.x, center.y - from.y), b(to.x - center.x, center.y - to.y);
  if (glm::dot(a, a) == 0.0f || glm::dot(b, b) == 0.0f) return 0.0f;
  return std::atan2(a.x * b.y - a.y * b.x, glm::dot(a, b));
}

void SweepTracker::begin(glm::vec2 centerPixel, glm::vec2 cursor) {
  center = centerPixel;
  last = cursor;
  total = 0.0f;
}

float SweepTracker::update(glm::vec2 cursor) {
  total += sweptAngle(center, last, cursor);
  if (cursor != center) last = cursor;  // at the centre the direction is undefined; keep the old one
  return total;
}

float snapAngle(float radians, float stepDegrees) {
  if (!(stepDegrees > 0.0f)) return radians;
  const float step = glm::radians(stepDegrees);
  return std::round(radians / step) * step;
}

glm::quat axisTurnForSweep(const ViewportView& view, const glm::vec3& pivot, const glm::vec3& axis, float sweptRadians,
                           bool snap, float* angleOut) {
  const float len = glm::length(axis);
  if (!(len > 0.0f)) {
    if (angleOut) *angleOut = 0.0f;
    return glm::quat(1, 0, 0, 0);
  }
  const glm::vec3 a = axis / len;
  // A counter-clockwise sweep turns things counter-clockwise on screen: a positive angle about
  // an axis pointing at the viewer, a negative one about an axis pointing away.
  const float sign = glm::dot(a, view.towardViewer(pivot)) >= 0.0f ? 1.0f : -1.0f;
  float angle = sign * sweptRadians;
  if (snap) angle = snapAngle(angle);
  if (angleOut) *angleOut = angle;
  return glm::angleAxis(angle, a);
}

glm::quat ringDragRotation(const ViewportView& view, const glm::vec3& pivot, const glm::vec3& axis, glm::vec2 start,
                           glm::vec2 current, bool snap, float* angleOut) {
  glm::vec2 center;
  if (!view.project(pivot, center)) {
    if (angleOut) *angleOut = 0.0f;
    return glm::quat(1, 0, 0, 0);
  }
  return axisTurnForSweep(view, pivot, axis, sweptAngle(center, start, current), snap, angleOut);
}

glm::quat trackballRotation(const ViewportView& view, glm::vec2 start, glm::vec2 current, float radiansPerPixel,
                            bool snap) {
  const glm::vec2 d = current - start;
  const float pixels = glm::length(d);
  if (!(pixels > 0.0f)) return glm::quat(1, 0, 0, 0);
  // The drag in world space (screen y grows downwards); the front of the ball follows it, so
  // the axis is towardViewer x drag: (axis x towardViewer) = drag direction.
  const glm::vec3 drag = glm::normalize(view.right() * d.x - view.up() * d.y);
  const glm::vec3 axis = glm::normalize(glm::cross(-view.forward(), drag));
  float angle = pixels * radiansPerPixel;
  if (snap) angle = snapAngle(angle);
  return glm::angleAxis(angle, axis);
}

glm::quat gizmoDragRotation(const RotateGizmo& gizmo, const ViewportView& view, GizmoPart part, glm::vec2 start,
                            glm::vec2 current, bool snap) {
  switch (part) {
    case GizmoPart::AxisX: return ringDragRotation(view, gizmo.pivot, gizmo.axis(0), start, current, snap);
    case GizmoPart::AxisY: return ringDragRotation(view, gizmo.pivot, gizmo.axis(1), start, current, snap);
    case GizmoPart::AxisZ: return ringDragRotation(view, gizmo.pivot, gizmo.axis(2), start, current, snap);
    case GizmoPart::ViewRing:
      return ringDragRotation(view, gizmo.pivot, view.towardViewer(gizmo.pivot), start, current, snap);
    case GizmoPart::Trackball: return trackballRotation(view, start, current, 0.01f, snap);
    case GizmoPart::None: break;
  }
  return glm::quat(1, 0, 0, 0);
}

void RotateMode::pressAxis(int axisIndex) {
  if (axisIndex < 0 || axisIndex > 2) {
    axis = -1;
    local = false;
  } else if (axis != axisIndex) {
    axis = axisIndex;
    local = false;
  } else if (!local) {
    local = true;
  } else {
    axis = -1;
    local = false;
  }
}

glm::vec3 RotateMode::worldAxis(const ViewportView& view, const glm::vec3& pivot,
                                const glm::quat& jointWorldRotation) const {
  if (axis < 0 || axis > 2) return view.towardViewer(pivot);
  return local ? glm::normalize(jointWorldRotation * unitAxis(axis)) : unitAxis(axis);
}

glm::quat RotateMode::rotation(const ViewportView& view, const glm::vec3& pivot, const glm::quat& jointWorldRotation,
                               glm::vec2 start, glm::vec2 current, bool snap, float* angleOut) const {
  return ringDragRotation(view, pivot, worldAxis(view, pivot, jointWorldRotation), start, current, snap, angleOut);
}

glm::quat localRotationAfterWorldTurn(const glm::quat& parentWorldRotation, const glm::quat& startLocal,
                                      const glm::quat& worldDelta) {
  const glm::quat parent = glm::normalize(parentWorldRotation);
  return glm::normalize(glm::inverse(parent) * glm::normalize(worldDelta) * parent * startLocal);
}

}  // namespace kinema
