#pragma once
// The editor's "Compare solvers" mode (issue 10), window-free: the comparison it shows, the
// layout of its views, the mapping between view pixels and figure units, hit-testing the
// target and the joints, mouse drags (target, start pose, orbit), the play clock and the
// steps its keys take (bound in commands/compare_commands.cpp). compare_panel.cpp draws it
// with ImGui; everything here is unit-tested.
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "core/math.h"
#include "ik/figure_projection.h"  // FigureProjection: the figures' own plane, for hit-tests
#include "editor/model/input_events.h"
#include "ik/solver_comparison.h"

namespace kinema {

struct CompareRect {
  float x = 0, y = 0, w = 1, h = 1;
  bool contains(glm::vec2 p) const { return p.x >= x && p.y >= y && p.x < x + w && p.y < y + h; }
};

// Where the mode's parts sit inside its area (window pixels, origin top left).
struct CompareLayout {
  CompareRect side;                // chain settings
  CompareRect toolbar;             // preset, step buttons, speed, 2D/3D
  std::vector<CompareRect> views;  // one per solver, side by side
  CompareRect plot;                // convergence plot under the views
  CompareRect numbers;             // per solver: iterations, error, times
};
constexpr float kCompareSideWidth = 250.0f;
constexpr float kCompareToolbarHeight = 58.0f;
// toolbarHeight / sideWidth: pixels at the UI scale in force (the panel derives them from the
// font, so two rows of widgets fit at any scale); the defaults are the sizes at 1x.
CompareLayout compareLayout(const CompareRect& area, int solverCount, float toolbarHeight = kCompareToolbarHeight,
                            float sideWidth = kCompareSideWidth);

// Figure units <-> view pixels: [min, max] fitted into the rect (less a margin), aspect kept,
// centred, Y up in figure units and down in pixels.
struct FigureViewMap {
  glm::vec2 center{0.0f};     // figure units at the rect's centre
  glm::vec2 pixelCenter{0.0f};
  float pixelsPerUnit = 1.0f;
  static FigureViewMap fit(glm::vec2 min, glm::vec2 max, const CompareRect& rect, float marginPixels = 12.0f);
  glm::vec2 toPixel(glm::vec2 figure) const;
  glm::vec2 toFigure(glm::vec2 pixel) const;
};

// The direction the 3D view looks along for an orbit (yaw about Y, pitch up), radians;
// (0, 0) is +Z, the planar view.
glm::vec3 orbitViewDirection(float yaw, float pitch);

// The handle under the mouse: the target (-1), a joint index (>= 0) or nothing (-2). The
// target wins ties so it can always be grabbed.
constexpr int kHitNothing = -2, kHitTarget = -1;
int hitCompareHandle(const std::vector<glm::vec2>& jointPixels, glm::vec2 targetPixel, glm::vec2 mouse,
                     float radiusPixels = 9.0f);

// Steps per second -> how many steps to take this frame (the fraction carries over).
struct PlayClock {
  double carry = 0.0;
  int advance(double dt, double stepsPerSecond);
};

// Joint positions of a planar chain's start pose (startAngles about Z), j0 .. jN.
std::vector<glm::vec3> teachingChainPositions(const TeachingChain& chain);
// The start angles that turn bone (joint - 1) to point at `point` (XY plane), the bones
// after it keeping their relative angles. joint in 1..N.
void aimTeachingBone(TeachingChain& chain, int joint, glm::vec3 point);

enum class CompareDrag { None, Target, Joint, Orbit };

struct CompareMode {
  bool active = false;
  std::string preset;             // the preset chosen last
  SolverComparison comparison;    // empty runs until a preset is opened
  std::string error;              // the last failure (shown in the toolbar)
  bool view3d = false;            // 3D: ball joints, the view orbits
  float yaw = 0.0f, pitch = 0.0f; // the 3D view's orbit (radians)
  bool playing = false;
  float stepsPerSecond = 4.0f;
  PlayClock clock;
  // This frame's layout and the figure bounds every view shares (set by the panel).
  CompareLayout layout;
  glm::vec2 figureMin{-1.0f}, figureMax{1.0f};
  // The drag in progress.
  CompareDrag drag = CompareDrag::None;
  int dragView = -1, dragJoint = -1;
  glm::vec2 lastMouse{0.0f};
  glm::vec2 mouse{0.0f};   // the last mouse position (scripted button events carry none)

  bool ready() const { return !comparison.runs.empty(); }
  glm::vec3 viewDirection() const { return view3d ? orbitViewDirection(yaw, pitch) : glm::vec3(0, 0, 1); }
  FigureViewMap viewMap(int view) const;
};

// Opens a preset (its chain and target; cursors at 0). "" or a one-line error.
std::string openComparePreset(CompareMode& m, const std::string& name);
// Solves `setup` again (a side-panel edit): "" or the error (then nothing changes).
std::string restartComparison(CompareMode& m, const TeachingCase& setup);
// 2D <-> 3D: the chain's joints become hinges about Z or ball joints; solved again.
std::string setCompareView3d(CompareMode& m, bool view3d);
// Space / the Play button; stops at the end. Returns the steps taken this frame.
int advanceComparePlay(CompareMode& m, double dt);

// Mouse in window pixels. Down in a view grabs the target or a joint (or orbits in 3D);
// moves drag it (target: setTarget; joint: the start pose, setChain); up ends the drag.
// Return true when the event was used.
bool compareMouseDown(CompareMode& m, glm::vec2 mouse);
bool compareMouseMove(CompareMode& m, glm::vec2 mouse);
bool compareMouseUp(CompareMode& m);
// What the mode's commands do (commands/compare_commands.cpp binds them to Right,
// Shift+Right, Space, End, R and Esc; the panel's buttons run the same commands). Each
// returns false, doing nothing, until a preset is open; leaving always works.
bool compareStepSubStep(CompareMode& m);    // one sub-step of every solver; stops playing
bool compareStepIteration(CompareMode& m);  // to the end of the next iteration
bool toggleComparePlay(CompareMode& m);     // play / pause at stepsPerSecond
bool compareRunToEnd(CompareMode& m);       // every solver to its last entry
bool compareReset(CompareMode& m);          // every cursor back to the start
void leaveCompareMode(CompareMode& m);
// The mouse events of the editor's queue while the mode is active (keys go to the commands);
// a press over a panel (mouseCaptured) is left to ImGui.
bool handleCompareEvent(CompareMode& m, const InputEvent& e, bool mouseCaptured);

// Where each view draws its joints and target (window pixels), for hit-tests and tests.
std::vector<glm::vec2> compareJointPixels(const CompareMode& m, int view);
glm::vec2 compareTargetPixel(const CompareMode& m, int view);

// The --dump-state "compare" object (docs/cli.md).
nlohmann::json compareModeJson(const CompareMode& m);

}  // namespace kinema
