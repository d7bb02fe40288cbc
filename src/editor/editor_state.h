#pragma once
#include <string>
#include <utility>
#include <vector>

#include "core/pose.h"
#include "editor/document.h"
#include "editor/panel_state.h"
#include "io/scene.h"
#include "render/camera.h"

namespace kinema {

// The modal tool the viewport is in (Blender pose mode). Only one runs at a time; input
// goes to it until it is confirmed or cancelled.
enum class ModalTool {
  None,
  Rotate,      // R: rotate the selection with the mouse
  Grab,        // G: move the root joint
  BoxSelect,   // left drag on empty space
  IkDrag,      // dragging an IK target handle (or a joint with auto-IK)
  GizmoDrag,   // dragging a ring of the rotate gizmo
  Navigate,    // orbit / pan with the mouse
};

// An axis a modal tool is constrained to (X/Y/Z pressed during R, G or an IK drag).
enum class AxisConstraint { None, X, Y, Z };

const char* modalToolName(ModalTool tool);  // "none", "rotate", ... (for --dump-state)

// What the running tool needs between frames. Cleared when the tool ends.
struct ToolState {
  ModalTool mode = ModalTool::None;
  AxisConstraint axis = AxisConstraint::None;
  bool localAxes = false;   // the constraint axis is the joint's own (press the axis key twice)
  glm::vec2 startMouse{0}, mouse{0};  // window pixels, origin top left
  int ring = -1;            // GizmoDrag: 0..2 = X/Y/Z ring, 3 = trackball
  int ikTarget = -1;        // IkDrag: the target's index in ikTargets
  std::string typed;        // numbers typed during R (degrees)
  Pose startPose;           // restored on cancel; the "before" of the undo step
};

// Display switches of the viewport (panels and menus toggle them).
struct ViewOptions {
  bool showGrid = true;
  bool xrayBones = false;   // bones drawn over everything
  bool showLimits = true;   // joint-limit cones and arcs of the selection
  bool showGizmo = true;
  bool localGizmo = false;  // the gizmo's rings turn with the joint (else world axes)
  bool autoIk = false;      // dragging a joint moves it by IK up the chain
  int autoIkChainLength = 2;
};

// One IK target of the document plus how its last solve went (the status bar shows these).
struct EditorIkStatus {
  int iterations = 0;
  float error = 0.0f;       // distance effector - target after the solve
  double milliseconds = 0.0;
  bool converged = false;
};

// Requests the panels raise; the window acts on them between frames (dialogs, files,
// camera moves) and clears them.
struct EditorRequests {
  bool newFile = false, open = false, save = false, saveAs = false, exportFile = false, quit = false;
  std::string path;          // open / save-as / export target chosen in a dialog
  bool frameSelected = false, frameAll = false;
  int viewPreset = 0;        // 0 none, 1 front, 3 side (right), 7 top; negative = the opposite
  bool toggleOrtho = false;
  bool undo = false, redo = false;
  bool copyPose = false, pastePose = false, pasteFlipped = false;
  bool clearRotation = false, resetPose = false;
};

// Everything the editor shows and edits, owned by the caller (no globals). Panels read and
// write it; the window turns input into edits of it and evaluateEditorPose() into world
// transforms.
struct EditorState {
  // --- The document (placeholder fields until editor-model's Document lands) ---
  Scene scene;                    // skeleton, clips, IK rig (scene.ik.targets are the IK targets)
  Pose pose;                      // the pose being edited (local transforms)
  std::string path;               // file the document was opened from / saved to, "" = new
  bool dirty = false;             // edited since the last save
  std::vector<int> selection;     // selected joints, in selection order
  int activeJoint = -1;           // the last one clicked (gizmo, properties); -1 = none
  int undoDepth = 0;              // steps that Ctrl+Z can undo
  // Placeholder history (whole poses) until editor-model's command history lands.
  std::vector<Pose> undoPoses, redoPoses;
  std::vector<std::pair<std::string, Transform>> clipboard;  // copied joints by name

  Document doc;        // editor-model's document; the panels edit it (the placeholders above go)
  PanelState panels;   // the panels' own state: dialogs, buffers, clipboard, autosave (editor_panels.h)

  // --- Playback (files with motion) ---
  int clip = 0;            // the clip the timeline plays, when the scene has clips
  double time = 0.0;       // seconds
  bool playing = false;
  bool loop = true;        // playback wraps at the clip's end (sampling itself always clamps)
  bool sampleClip = true;  // the next evaluate samples the clip into the pose (time moved)

  // --- Viewport ---
  OrbitCamera camera;
  bool orthographic = false;
  ViewOptions view;
  ToolState tool;
  int hoveredJoint = -1;   // under the mouse (drawn highlighted)
  int hoveredIkTarget = -1;
  std::vector<EditorIkStatus> ikStatus;  // one per scene.ik.targets entry
  EditorRequests requests;
  std::string statusMessage;  // one line for the status bar (errors included)

  // Derived each frame from the fields above.
  std::vector<glm::mat4> world;

  bool hasMotion() const { return clip >= 0 && clip < static_cast<int>(scene.clips.size()); }
  double duration() const;       // the clip's length in seconds, 0 without motion
  double frameTime() const;      // the clip's frame time, or 1/30 s
  long long frameCount() const;  // frames on the clip's grid, at least 1
  bool isSelected(int joint) const;
  // Display name for the title bar: the file's name or "untitled".
  std::string documentName() const;
};

// Samples the current clip at state.time into state.pose (when the time moved or playback
// runs) and runs FK into state.world.
void evaluateEditorPose(EditorState& state);
// Advances playback by dt seconds (wrapping or stopping at the end).
void advancePlayback(EditorState& state, double dt);
// Sets the selection to exactly `joints` (active = the last one), or clears it.
void setSelection(EditorState& state, const std::vector<int>& joints);
// Shift-click: adds the joint (making it active) or removes it when it was selected.
void toggleSelection(EditorState& state, int joint);

}  // namespace kinema
