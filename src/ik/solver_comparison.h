#pragma once
// Teaching mode's model (issue 10): one chain and one target solved by several solvers side
// by side, replayed one sub-step (one CCD joint rotation, one FABRIK pass) or one iteration
// at a time from each solver's IkTrace. No GL: the editor's "Compare solvers" view and
// `kinema demo` both drive this and draw what it holds.
#include <string>
#include <vector>

#include "core/pose.h"
#include "ik/ik_rig.h"
#include "ik/ik_solver.h"

namespace kinema {

// A chain for the board: joint 0 at `base`, then one joint per bone end; the last joint is
// the effector. With all angles 0 every bone points along +X; startAngles turn each joint
// about Z so the chain starts bent as the seed figures draw it. A planar chain stays in the
// z = base.z plane because its target is put there (no hinge is needed for that).
struct TeachingChain {
  std::vector<float> boneLengths;   // root to effector, each > 0
  std::vector<float> startAngles;   // radians, one per bone, relative to the parent bone (about Z)
  glm::vec3 base{0.0f};
  bool planar = true;               // joints turn about Z only (hinges, the board); false: ball joints in 3D
  // Empty or one per joint of the skeleton (bones + 1). Hinge limits about Z give the
  // allowed angle relative to the parent bone (the board's angle, not relative to the start).
  std::vector<JointLimit> limits;

  std::string validate() const;
  float reach() const;  // sum of bone lengths
};

// The chain as a skeleton ("j0" .. "jN", "jN" the effector), its start pose and its rig
// (limits). The skeleton's rest pose IS the start pose (rest rotations = startAngles), so
// the .kinema `kinema demo` saves starts there under `kinema ik FILE --trace`; limits are
// converted to be relative to that rest pose.
struct TeachingSkeleton {
  Skeleton skeleton;
  Pose start;
  IkRig rig;
};
TeachingSkeleton makeTeachingSkeleton(const TeachingChain& chain);

// A case as the presets and the editor set it up.
struct TeachingCase {
  std::string name;         // preset id: "ccd-steps", "fabrik-steps", ... (kinema demo NAME)
  std::string title;        // one line for figures and the editor's preset menu
  std::string description;  // what the case shows, a sentence or two
  TeachingChain chain;
  glm::vec3 target{0.0f};
  std::vector<IkSolver> solvers{IkSolver::Ccd, IkSolver::Fabrik};  // two or three
  IkSettings settings;      // tolerance, iteration cap (trace is set by the comparison)

  std::string validate() const;
};

// The presets: the seeds' 3-bone CCD and FABRIK cases, the two-bone no-solution region and
// two-solution case, an unreachable target, a target near the root, a 20-joint chain and a
// chain with hinge limits.
const std::vector<TeachingCase>& teachingPresets();
const TeachingCase* findTeachingPreset(const std::string& name);  // nullptr when unknown

// The settings a case runs `solver` with (trace not set): the case's settings, with
// FABRIK's DLS finish as the case asks and jacobian-transpose's larger iteration cap.
IkSettings settingsFor(const TeachingCase& setup, IkSolver solver);
// The arguments after FILE that make `kinema ik FILE ... --json --trace` run exactly this
// solver on this case (the file being makeTeachingSkeleton's skeleton saved as .kinema).
std::vector<std::string> ikCommandArguments(const TeachingCase& setup, IkSolver solver);

// One solver's recorded run, replayed through `cursor`.
struct SolverRun {
  IkSolver solver = IkSolver::Ccd;
  IkTrace trace;            // entries[0] is the start state; every later entry is one sub-step
  IkResult result;
  double totalMilliseconds = 0.0;         // the untraced solve, timed (median of repeats)
  double millisecondsPerIteration = 0.0;  // totalMilliseconds / max(1, result.iterations)
  int cursor = 0;           // the trace entry shown (0 = start)

  const IkTraceEntry& current() const { return trace.entries[cursor]; }
  // The entry before the cursor (the ghost), nullptr at the start.
  const IkTraceEntry* previous() const { return cursor > 0 ? &trace.entries[cursor - 1] : nullptr; }
  bool finished() const { return cursor + 1 >= static_cast<int>(trace.entries.size()); }
  // Largest effector error after each completed iteration, index 0 = the start.
  std::vector<float> convergence() const;
  // The same, revealed up to the cursor (a step-by-step replay must not show what is to
  // come): only iterations the entries 0 .. cursor reach, the last one being the cursor's
  // iteration with the error at the cursor (that iteration may still be under way).
  std::vector<float> convergenceSoFar() const;
};

struct SolverComparison {
  TeachingCase setup;
  TeachingSkeleton chain;
  std::vector<SolverRun> runs;  // one per setup.solvers entry, same order
};

// Solves the case with every solver (tracing, then timing the untraced solve: median of
// `timingRepeats`); cursors at 0. Returns
// "" or a one-line error (an invalid case: nothing is run).
std::string startComparison(const TeachingCase& setup, SolverComparison& out, int timingRepeats = 5);
// One sub-step forward in every run that is not finished.
void stepSubStep(SolverComparison& c);
// Forward in every run to the end of the current iteration when the cursor is inside one,
// else to the end of the next (from the start: the end of iteration 1); a run with no such
// iteration goes to its end.
void stepIteration(SolverComparison& c);
void runToEnd(SolverComparison& c);
void resetCursors(SolverComparison& c);
// A new target or chain: everything is solved again and the cursors go back to the start.
std::string setTarget(SolverComparison& c, const glm::vec3& target);
std::string setChain(SolverComparison& c, const TeachingChain& chain);

}  // namespace kinema
