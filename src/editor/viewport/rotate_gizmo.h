#pragma once
#include <vector>

#include "editor/viewport/viewport_view.h"

namespace kinema {

// Blender's rotate gizmo: three axis rings (X red, Y green, Z blue), an outer ring in the
// view plane, and a free trackball inside. Sizes are in pixels so it looks the same at any
// zoom; rings are world circles of the radius that spans `ringRadiusPixels` at the pivot.
enum class GizmoPart { None, AxisX, AxisY, AxisZ, ViewRing, Trackball };
enum class GizmoOrientation { Global, Local };

struct RotateGizmo {
  glm::vec3 pivot{0.0f};                // world position of the joint
  glm::quat axesRotation{1, 0, 0, 0};   // world rotation of the ring frame (identity = global)
  float ringRadiusPixels = 80.0f;
  float viewRingRadiusPixels = 96.0f;
  float tolerancePixels = 6.0f;         // how close to a ring the cursor must be to grab it

  // The frame for an orientation: global = world axes; local = the joint's world rotation.
  static glm::quat axesFor(GizmoOrientation orientation, const glm::quat& jointWorldRotation);
  glm::vec3 axis(int i) const;          // world axis of ring i (0 = X, 1 = Y, 2 = Z), unit
  float ringRadiusWorld(const ViewportView& view) const;
  // Points of ring i (0..2) in world space, or of the view ring (i = 3), `segments` of them.
  std::vector<glm::vec3> ringPoints(const ViewportView& view, int i, int segments = 64) const;
};

// The axis rings' radius (pixels) for the gizmo on `joint`: Blender's fixed size (`maxPixels`,
// 80) at most, but at a whole-body zoom small enough that no ring covers a neighbouring limb
// (a click on the other foot must select it, not grab a ring): the view ring (kViewRingScale
// wider) and its grab tolerance stay within half the on-screen distance to the nearest joint
// the rotation does not carry along (any but the joint, its parent and its descendants;
// joints within a pixel of the pivot or behind the eye are skipped). Never under
// kMinGizmoRingPixels, so it stays grabbable. `world`: joint world transforms; `parents`: -1
// for roots.
constexpr float kMinGizmoRingPixels = 12.0f;
constexpr float kViewRingScale = 1.2f;  // the view ring's radius over the axis rings' (Blender's 96 / 80)
float rotateGizmoRingPixels(const ViewportView& view, const std::vector<glm::mat4>& world, const std::vector<int>& parents,
                            int joint, float maxPixels = 80.0f, float tolerancePixels = 6.0f);

// Whether the axis-ring segment a-b is on the half facing the viewer (Blender draws and grabs
// only that half): judged against the view axis, so a ring whose axis is the view axis is a
// whole circle also off-centre in perspective; nearly face-on rings (within ~1 degree) too.
bool ringSegmentFacesViewer(const RotateGizmo& gizmo, const ViewportView& view, const glm::vec3& a,
                            const glm::vec3& b);

// Which part the cursor is over: the nearest ring within the tolerance; else the trackball
// when inside the axis rings' radius; else None.
GizmoPart hitTestRotateGizmo(const RotateGizmo& gizmo, const ViewportView& view, glm::vec2 cursor);

// The angle (radians) the cursor swept around `center` going from `from` to `to`, in pixels
// with y down; positive = counter-clockwise as the viewer sees it. In (-pi, pi].
float sweptAngle(glm::vec2 center, glm::vec2 from, glm::vec2 to);
// Accumulates the swept angle over a drag frame by frame, so turns past 180 degrees (and
// several full turns) add up instead of wrapping.
struct SweepTracker {
  glm::vec2 center{0.0f}, last{0.0f};
  float total = 0.0f;  // radians, counter-clockwise as the viewer sees it
  void begin(glm::vec2 centerPixel, glm::vec2 cursor);
  float update(glm::vec2 cursor);  // returns the new total
};
// Rounds to multiples of `stepDegrees` (Ctrl snapping, 5 degrees in Blender).
float snapAngle(float radians, float stepDegrees = 5.0f);

// World rotation for an axis-ring (or R-mode axis) drag: the cursor's sweep around the
// pivot's screen position, signed so the joint follows the cursor whether the axis points
// towards or away from the viewer. `angleOut` (optional) receives the signed angle about `axis`.
glm::quat ringDragRotation(const ViewportView& view, const glm::vec3& pivot, const glm::vec3& axis, glm::vec2 start,
                           glm::vec2 current, bool snap, float* angleOut = nullptr);
// The same from an accumulated sweep (SweepTracker::total) instead of two cursor positions.
glm::quat axisTurnForSweep(const ViewportView& view, const glm::vec3& pivot, const glm::vec3& axis, float sweptRadians,
                           bool snap, float* angleOut = nullptr);
// Trackball: about the view-plane axis perpendicular to the drag, `radiansPerPixel` * length.
glm::quat trackballRotation(const ViewportView& view, glm::vec2 start, glm::vec2 current,
                            float radiansPerPixel = 0.01f, bool snap = false);
// The gizmo drag for `part` (axis rings, view ring = about the view axis, trackball).
glm::quat gizmoDragRotation(const RotateGizmo& gizmo, const ViewportView& view, GizmoPart part, glm::vec2 start,
                            glm::vec2 current, bool snap);

// Blender's R: free (about the view axis), or constrained to X/Y/Z. Pressing an axis key
// cycles global -> local -> free for that axis; another axis starts at global. rotation()
// measures start -> current directly (within half a turn); for longer drags feed a
// SweepTracker each mouse move and use axisTurnForSweep(view, pivot, worldAxis(...), total, ...).
struct RotateMode {
  int axis = -1;          // -1 = view axis, 0/1/2 = X/Y/Z
  bool local = false;
  void pressAxis(int axisIndex);
  // The world axis of the constraint (`jointWorldRotation` gives the local axes).
  glm::vec3 worldAxis(const ViewportView& view, const glm::vec3& pivot, const glm::quat& jointWorldRotation) const;
  // World rotation for the cursor moving from `start` to `current` around the pivot on screen.
  glm::quat rotation(const ViewportView& view, const glm::vec3& pivot, const glm::quat& jointWorldRotation,
                     glm::vec2 start, glm::vec2 current, bool snap, float* angleOut = nullptr) const;
};

// The joint's new LOCAL rotation after turning its world rotation by `worldDelta`:
// inverse(parentWorldRotation) * worldDelta * parentWorldRotation * startLocal. The caller
// applies it to the pose (roots: parentWorldRotation = identity).
glm::quat localRotationAfterWorldTurn(const glm::quat& parentWorldRotation, const glm::quat& startLocal,
                                      const glm::quat& worldDelta);

}  // namespace kinema
