#pragma once
#include <vector>

#include "editor/model/editor_state.h"
#include "editor/model/input_events.h"
#include "editor/viewport/picking.h"
#include "evaluation/scene_deformation.h"
#include "editor/viewport/rotate_gizmo.h"
#include "editor/viewport/viewport_view.h"
#include "render/skeleton_draw_list.h"

namespace kinema {

// Blender pose-mode input on an EditorState, no window: the window (live GLFW events) and
// --script replay both reach handle() through commands/editor_input.h. The mouse (select,
// box select, gizmo and IK handle drags, navigation) and the keys of a running modal tool
// (X/Y/Z, typed degrees, Enter, Esc) are handled here; every other key is a command, and
// R / G start their tools through startRotate() / startGrab(). The maths is
// editor-viewport's (picking, gizmo, drags); every change goes through the Document (drags
// are one undo step each).
class ViewportTools {
 public:
  // `list`: the skeleton as drawn last frame (picking casts rays against its shapes).
  // `mouseCaptured`: ImGui wants the mouse (over a panel). A running tool takes every key
  // (even while ImGui has the keyboard: the tool started from the 3D view).
  void handle(EditorState& state, const InputEvent& event, const ViewportView& view, const SkeletonDrawList& list,
              bool mouseCaptured);
  glm::vec2 mouse() const { return mouse_; }
  // R: rotates the selection with the mouse from where it is now. False (nothing starts)
  // when a tool runs, nothing is selected or a drag is refused (the reason in the status).
  bool startRotate(EditorState& state, const ViewportView& view);
  // G: moves the root joint with the mouse. False as startRotate.
  bool startGrab(EditorState& state);
  // B: the next left press starts a box select wherever it is (over a bone too), as Blender's
  // B does; Esc or a right click disarms it.
  void armBoxSelect(EditorState& state);
  // G in lattice edit mode: moves the selected lattice points with the mouse
  // (model/lattice_editing.h; confirmed as one undo step). False as startRotate.
  bool startLatticeGrab(EditorState& state);
  // The rotate gizmo on the active joint, as drawn and hit-tested (valid = false: none).
  bool gizmo(const EditorState& state, const ViewportView& view, RotateGizmo& out) const;
  GizmoPart hoveredGizmoPart() const { return hoveredPart_; }

 private:
  void mouseMove(EditorState& state, const ViewportView& view, const SkeletonDrawList& list, glm::vec2 previous);
  void leftPress(EditorState& state, const ViewportView& view, const SkeletonDrawList& list);
  void modalKey(EditorState& state, const ViewportView& view, int key);
  bool beginModal(EditorState& state, ModalTool tool, const char* label);
  void confirm(EditorState& state);
  void cancel(EditorState& state);
  void applyRotate(EditorState& state, const ViewportView& view);
  // The joint under the mouse: shown bones and joints first, else the body (mesh_picking.h).
  SkeletonPick pickAt(const EditorState& state, const ViewportView& view, const SkeletonDrawList& list) const;
  // Properties > Deformers > Pick centre is waiting: a click on the body centres the soft pull there.
  void softPullPickPress(EditorState& state, const ViewportView& view);
  // deformed_ as the document shows now (the meshes deformed at the current pose).
  void refreshDeformed(const EditorState& state) const;
  void applyGizmo(EditorState& state, const ViewportView& view);
  void applyMove(EditorState& state, const ViewportView& view);  // Grab and IK drags
  void applyLatticeMove(EditorState& state, const ViewportView& view);
  void latticePress(EditorState& state, const ViewportView& view);
  glm::vec3 jointPosition(const EditorState& state, int joint) const;

  glm::vec2 mouse_{0.0f};
  int mods_ = 0;     // the current event's modifiers
  HeldInput held_;   // the modifier keys held
  bool navigating_ = false, panning_ = false;
  bool pressedOnEmpty_ = false;  // a left press on nothing: a click clears, a drag box-selects
  bool boxArmed_ = false;        // B pressed: the next left press is taken as on nothing
  GizmoPart hoveredPart_ = GizmoPart::None;
  // The running rotation: the joints it turns (no selected ancestor), their start local
  // rotations and parents' world rotations, the sweep around the active joint's pixel.
  std::vector<int> joints_;
  std::vector<glm::quat> startLocal_, parentWorld_, startWorld_;
  RotateGizmo gizmo_;
  RotateMode rotateMode_;
  SweepTracker sweep_;
  // The body deformed at the pose last picked on: hover picks on every mouse move, the pose
  // changes far less often. Valid while the pose revision and the document's change count
  // (skinning methods, binds) match.
  mutable std::vector<DeformedPrimitive> deformed_;
  mutable long long deformedPose_ = -1;  // Document::poseRevision the deformed meshes are of
  mutable long long deformedRevision_ = -1, deformedChange_ = -1;  // meshRevision, changeCount
  mutable const Scene* deformedScene_ = nullptr;
  glm::vec3 startTranslation_{0.0f};
};

// The joints' world rotations from the document's local rotations (exact, no matrix scale).
glm::quat jointWorldRotation(const Document& doc, int joint);

}  // namespace kinema
