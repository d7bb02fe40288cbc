#pragma once
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "anim/playback_sampling_job.h"
#include "core/pose.h"
#include "editor/model/document.h"
#include "io/input_limits.h"
#include "editor/model/bottom_panels.h"
#include "editor/model/motion_control.h"
#include "editor/model/motion_path.h"
#include "editor/model/onion_skin.h"
#include "editor/model/compare_mode.h"
#include "editor/model/curve_editor.h"
#include "editor/model/dope_sheet.h"
#include "editor/model/foot_contact_edits.h"
#include "editor/model/motion_cleanup_edit.h"
#include "editor/model/particle_edits.h"
#include "editor/model/simulation_edits.h"
#include "editor/model/crowd_edits.h"
#include "editor/model/item_rects.h"
#include "editor/model/lattice_editing.h"
#include "editor/model/property_keying.h"
#include "editor/model/editor_layout.h"
#include "editor/model/message_log.h"
#include "editor/model/user_preferences.h"
#include "editor/model/viewport_quality.h"
#include "editor/model/window_redraw.h"
#include "editor/model/panel_state.h"
#include "scene/scene.h"
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
  LatticeGrab, // G in lattice edit mode: move the selected lattice points (lattice_editing.h)
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
  int ring = -1;            // GizmoDrag: the GizmoPart (rotate_gizmo.h) as an int
  int ikTarget = -1;        // IkDrag: the target's index in doc.ikTargets(); -1 = auto-IK
  std::string typed;        // numbers typed during R (degrees)
  glm::vec3 startPoint{0.0f};  // Grab / IkDrag: where the dragged point was at the start
};

// The editor shown in the area between the 3D view and the timeline (Blender's bottom area).
enum class AnimationEditorKind { None, DopeSheet, CurveEditor };

// Display switches of the viewport (panels and menus toggle them).
struct ViewOptions {
  bool showGrid = true;
  bool xrayBones = false;   // bones drawn over everything
  bool showBones = true;    // off: the body alone (bones none / on / x-ray, Alt+Z cycles)
  bool showWeights = false; // the active joint's skin weights as heat colours on the meshes
  bool showLimits = true;   // joint-limit cones and arcs of the selection
  bool showGizmo = true;
  bool localGizmo = false;  // the gizmo's rings turn with the joint (else world axes)
  bool autoIk = false;      // dragging a joint moves it by IK up the chain
  int autoIkChainLength = 2;
};

// Everything the editor shows and edits, owned by the caller (no globals). Panels read and
// write it; the window turns input into edits of it and evaluateEditorPose() poses the
// document at the playhead; world() is the one evaluation of that pose everybody reads.
struct EditorState {
  Document doc;        // the scene being edited: pose, IK targets, selection, history, path, dirty
  PanelState panels;   // the panels' own state: dialogs, buffers, clipboard, autosave (editor_panels.h)

  // --- Playback (files with motion): the playhead (timeline.h) ---
  // The clip the timeline plays, when the scene has clips: the views' copy of the
  // document's active clip (Document::activeClip), which it follows (timeline.h
  // followDocumentClip) as of the document's clipListRevision followedClipList.
  int clip = 0;
  long long followedClipList = -1;
  double time = 0.0;       // seconds; frames are the clip's grid (Clip::secondsPerFrame)
  bool playing = false;
  bool loop = true;        // playback wraps at the clip's end (sampling itself always clamps)
  bool sampleClip = false; // the timeline moved: the next evaluate poses the document at `time`

  // --- Viewport ---
  OrbitCamera camera;      // camera.orthographic: numpad 5
  glm::vec4 viewportRect{0.0f};  // the 3D view in window pixels (x, y, width, height), set each frame
  ViewportRenderInfo viewportRender;  // how the window drew the last frame's 3D view (viewport_quality.h)
  WindowRedrawInfo windowRedraw;      // how the window drew its last frame (window_redraw.h)
  ViewOptions view;
  ToolState tool;
  int hoveredJoint = -1;   // under the mouse (drawn highlighted)
  int hoveredIkTarget = -1;
  AnimationEditorKind animationEditor = AnimationEditorKind::None;
  HoveredProperty hoveredProperty;  // the keyable Properties field under the mouse (I keys it)
  LatticeEditState lattice;  // lattice edit mode (Tab): the edited lattice, its point selection, a running G
  CompareMode compare;     // Teach > Compare Solvers: replaces the 3D view and the side panels while active
  CurveEditorState curveEditor;  // the curve editor's view, channel toggles and key selection
  DopeSheetState dopeSheet;  // the dope sheet's selection, view, clipboard and mouse gesture
  std::string statusMessage;  // one line for the status bar (errors included)
  InputLimits inputLimits;    // what File > Open lets a file ask for (kinema edit --allow-outside-paths)
  ItemRects items;  // where the named widgets were drawn (scripts click them by name; item_rects.h)
  // Onion skin, motion path, motion control (View menu; onion_skin.h, motion_path.h, motion_control.h).
  OnionSkinSettings onionSkin;
  MotionPathSettings motionPath;
  MotionControlSettings motionControl;
  bool onionSkinWindowOpen = false;  // View > Onion Skin && Motion Path...
  // Look and layout (Edit > Preferences): the UI scale, theme, 3D line scale, splitters and
  // window placement. Its loop and keys fields are only the file's copy: in a session the
  // settings are `loop` and doc.autoKey.preferences (currentPreferences / applyPreferences).
  UserPreferences preferences;
  EditorLayout layout;      // this frame's panel rectangles (window pixels), set by the window
  MessageLog log;           // every message in full (View > Log)
  bool preferencesWindowOpen = false, logWindowOpen = false;
  // Foot contacts (the strip over the timeline, contact_lanes.h) and Animation > Clean Up
  // Motion… (motion_cleanup_edit.h): the chosen contact, the bar being dragged, the window's
  // settings, the range Add Foot Contact covers, and the last clean-up's figures.
  FootContactSelection contactSelection;
  FootContactDrag contactDrag;
  // A press on an empty lane: a new contact starts from contactNewFrame once the mouse moves.
  bool contactNewArmed = false;
  Foot contactNewFoot = Foot::Left;
  long long contactNewFrame = 0;
  bool cleanUpWindowOpen = false;
  CleanUpOptions cleanUp;
  Foot newContactFoot = Foot::Left;
  int newContactFirst = 0, newContactLast = 10;  // frames
  std::optional<CleanUpResult> lastCleanUp;
  // Simulate menu (issue 23): the chains played live, the Simulation window, the last bake,
  // and Teach > Stiff Springs (the time-step window: step as a fraction of explicit Euler's limit).
  LiveSprings liveSprings;
  bool simulationWindowOpen = false;
  std::optional<SimulationBake> lastBake;
  CrowdEditorState crowds;  // Simulate > crowds (issue 24): the Crowd panel, the live flock
  bool stiffSpringsWindowOpen = false;
  // Opens where explicit Euler blows up and the other three hold (1.5x its limit, zeta 0.3:
  // still under symplectic Euler's and Verlet's 2 / omega_max).
  float stiffSpringsStep = 1.5f;   // dt / (2 zeta / omega_max)
  float stiffSpringsZeta = 0.3f;
  // Particle systems (issue 24; particle_edits.h): played live in the viewport, the Particles
  // window and the system it shows.
  LiveParticles liveParticles;
  bool particlesWindowOpen = false;
  int particleSystem = 0;

  bool wasPlaying = false;  // playback stopped since the last evaluate: the document takes the frame
  // The document's pose revision right after the last poseAtPlayhead: equal while the pose
  // shows the clip at the playhead, so undoing a clip edit (a modifier) shows the clip again.
  long long animatedPoseRevision = -1;
  // The playhead and document state the pose was last sampled at while playing: a second
  // evaluate of the same frame samples nothing.
  struct SampledAt {
    int clip = -1;
    double time = 0.0;
    long long poseRevision = -1, changeCount = -1;
    bool operator==(const SampledAt& o) const {
      return clip == o.clip && time == o.time && poseRevision == o.poseRevision && changeCount == o.changeCount;
    }
  } sampledAt;

  // The played clip in its sampling form (anim/playback_clip.h), used while the clip plays
  // (poseAtPlayhead): built on the first played frame and again after any change of the
  // document, which changeCount and clipListRevision (unique to a document) tell.
  struct PlaybackSampler {
    PlaybackClip clip;
    PlaybackContext context;
    int clipIndex = -1, joints = -1;
    long long clipListRevision = -1, changeCount = -1;
  } playbackSampler;

  // World transforms of the document's pose (model space, one per joint): the document's
  // cached evaluation (Document::worldTransforms), recomputed only after the pose changed.
  // Every panel, tool and renderer reads this one.
  const std::vector<glm::mat4>& world() const { return doc.worldTransforms(); }

  bool hasMotion() const { return clip >= 0 && clip < static_cast<int>(doc.scene().clips.size()); }
  double duration() const;       // the clip's length in seconds, 0 without motion
  // The panels under the 3D view this frame (layout: panel_layout.h).
  // The timeline is there whenever a skeleton is, so a pose can be keyed (timeline.h).
  bool timelineShown() const { return hasMotion() || doc.skeleton().size() > 0; }
  BottomPanels bottomPanels() const {
    BottomPanels b;
    b.timeline = timelineShown();
    b.animationEditor = animationEditor != AnimationEditorKind::None;
    b.contactLanes = hasMotion() && (cleanUpWindowOpen || !doc.scene().clips[clip].contacts.empty());
    return b;
  }
  // Whether window pixel p is over the animation editor (right under the 3D view, when
  // shown): keys pressed there go to that editor, not to the viewport (Blender).
  bool animationEditorContains(glm::vec2 p) const {
    // Before the window's first layout: the stored height (at UI scale 1).
    const float h = layout.animationEditor.h > 0.0f ? layout.animationEditor.h : preferences.panels.animationEditorHeight;
    return animationEditor != AnimationEditorKind::None && p.x >= viewportRect.x &&
           p.x < viewportRect.x + viewportRect.z && p.y >= viewportRect.y + viewportRect.w &&
           p.y < viewportRect.y + viewportRect.w + h;
  }
};

// While the clip plays, and when the timeline moved (sampleClip) or playback stopped, the
// document's pose becomes the clip's at state.time (poseAtPlayhead: not an undo step, not a
// change to save); the playhead is copied into the document. A second call in the same
// frame samples nothing and, the pose unchanged, costs no forward kinematics (world()).
void evaluateEditorPose(EditorState& state);
// Advances playback by dt seconds (wrapping or stopping at the end).
void advancePlayback(EditorState& state, double dt);
// The preferences as the file keeps them: state.preferences with the session's loop switch
// and new-key defaults; applyPreferences sets all of them (at start).
UserPreferences currentPreferences(const EditorState& state);
void applyPreferences(EditorState& state, const UserPreferences& p);
}  // namespace kinema
