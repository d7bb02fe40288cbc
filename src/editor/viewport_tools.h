#pragma once
#include <vector>

#include "core/math.h"
#include "editor/editor_state.h"
#include "editor/input_events.h"

namespace kinema {

// The camera's matrices for one viewport size, with world <-> pixel helpers (pixels have
// their origin top left, as mouse events do).
struct ViewportGeometry {
  glm::vec2 size{1.0f};
  glm::mat4 view{1.0f}, projection{1.0f}, viewProjection{1.0f};
  glm::vec3 eye{0.0f}, forward{0.0f, 0.0f, -1.0f}, right{1.0f, 0.0f, 0.0f}, up{0.0f, 1.0f, 0.0f};
  bool orthographic = false;
  float fovY = 0.6f, orthoHalfHeight = 1.0f;

  // False when the point is behind the eye.
  bool toScreen(const glm::vec3& world, glm::vec2& pixel) const;
  // World units per pixel in the view plane through `world`.
  float unitsPerPixel(const glm::vec3& world) const;
  // The world displacement, parallel to the view plane, that moves `world` by `pixels` on screen.
  glm::vec3 screenDeltaToWorld(const glm::vec3& world, glm::vec2 pixels) const;
};
ViewportGeometry viewportGeometry(const OrbitCamera& camera, bool orthographic, glm::vec2 size);
// The orthographic projection the viewport uses: same framing as the perspective view at
// the target's distance.
glm::mat4 orthographicProjection(const OrbitCamera& camera, float aspect);

// The joint under the cursor: the nearest joint point or bone (a bone picks its head joint,
// as Blender does) within `radius` pixels, or -1.
int pickJointOrBone(const EditorState& state, const ViewportGeometry& g, glm::vec2 cursor, float radius = 10.0f);
// Joints whose screen positions lie in the box spanned by a and b.
std::vector<int> jointsInBox(const EditorState& state, const ViewportGeometry& g, glm::vec2 a, glm::vec2 b);

// The rotate gizmo on the active joint: rings 0..2 turn about X/Y/Z (world, or the joint's
// own axes with view.localGizmo), ring 3 (the outer circle) about the view axis; dragging
// inside the rings is a free trackball (ring 4).
struct GizmoGeometry {
  glm::vec3 center{0.0f};
  glm::vec3 axes[3];
  float radiusWorld = 1.0f;
  float radiusPixels = 70.0f;
  bool valid = false;
};
GizmoGeometry gizmoGeometry(const EditorState& state, const ViewportGeometry& g);
// The ring under the cursor (0..3, 4 = trackball inside), or -1.
int pickGizmoRing(const GizmoGeometry& gizmo, const ViewportGeometry& g, glm::vec2 cursor);

// Blender-style pose-mode input on an EditorState, no window: the window (live GLFW events)
// and --script replay both call handle(); update() runs once per frame (IK during drags).
class ViewportTools {
 public:
  // `mouseCaptured`/`keyboardCaptured`: ImGui wants the event (over a panel, typing).
  void handle(EditorState& state, const InputEvent& event, const ViewportGeometry& g, bool mouseCaptured,
              bool keyboardCaptured);
  void update(EditorState& state);
  glm::vec2 mouse() const { return mouse_; }
  int mods() const { return mods_; }

 private:
  void mouseMove(EditorState& state, const ViewportGeometry& g, glm::vec2 previous);
  void leftPress(EditorState& state, const ViewportGeometry& g);
  void key(EditorState& state, const ViewportGeometry& g, int key);
  void beginTool(EditorState& state, ModalTool tool);
  void confirmTool(EditorState& state);
  void cancelTool(EditorState& state);
  void applyRotate(EditorState& state, const ViewportGeometry& g);
  void applyGrab(EditorState& state, const ViewportGeometry& g);
  void applyGizmo(EditorState& state, const ViewportGeometry& g);
  void applyIkDrag(EditorState& state, const ViewportGeometry& g);
  glm::vec3 constrainedAxis(const EditorState& state, int joint) const;

  glm::vec2 mouse_{0.0f};
  int mods_ = 0, heldMods_ = 0;  // effective modifiers of the current event; held modifier keys
  bool buttons_[8] = {};
  bool navigating_ = false, panning_ = false;
  bool pressedOnEmpty_ = false;  // a left press on nothing: a click clears, a drag box-selects
  glm::vec3 pivot_{0.0f};        // world point the running tool turns about / moves
  glm::vec3 dragStart_{0.0f};    // IK target / root position when the drag began
  IkTarget autoIkTarget_;        // the temporary target of an auto-IK drag
  bool autoIk_ = false;
  float angle_ = 0.0f, lastAngle_ = 0.0f;  // R / ring drags: the angle swept so far (radians)
};

// Edits with the placeholder history: call before changing state.pose for an undo step.
void pushUndo(EditorState& state, const Pose& before);
void undoEdit(EditorState& state);
void redoEdit(EditorState& state);
// Alt+R: the selected joints' rotations back to the rest pose's.
void clearSelectedRotations(EditorState& state);
void copySelectedPose(EditorState& state);
// Pastes the clipboard onto joints of the same name (flipped: onto the .L/.R mirror joint,
// mirrored across the YZ plane).
void pastePose(EditorState& state, bool flipped);
// Solves every IK target of the document on state.pose and records the status per target.
void solveIkTargets(EditorState& state, const std::vector<IkTarget>& extra = {});
// Frames the selection (F) or everything (Home) from the current direction.
void frameSelection(EditorState& state, float aspect, bool all);
// Numpad views: 1 front, 3 right, 7 top; opposite = Ctrl (back, left, bottom).
void setViewPreset(EditorState& state, int preset, bool opposite);

}  // namespace kinema
