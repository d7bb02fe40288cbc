#pragma once
#include <vector>

#include "core/pose.h"
#include "core/skeleton.h"
#include "ik/ik_solver.h"
#include "ik/joint_limits.h"
#include "ik/pose_ik_target.h"

namespace kinema {

// One solved target's outcome.
struct IkTargetReport {
  int target = -1;  // index into the targets solved (IkPosingInput::targets), -1 for the auto-IK drag target
  int iterations = 0;
  float error = 0.0f;        // effector distance to the target after the solve
  double milliseconds = 0.0; // time spent solving it
  bool converged = false;
};

// IK posing: the rule every solve of the editor's targets follows (the document calls it
// after each edit and drag step; editor/model/ik_posing.h has the drags):
//  * the driven target (the one being edited or dragged; also the auto-IK temporary
//    target) and every active *pinned* target are solved, in a stable order: the
//    temporary one, the driven one, then pinned ones in list order, each with its own
//    solver, joint limits respected. When several are solved and that leaves one off
//    target (overlapping chains), they are solved once more all together by damped least
//    squares (up to kIkJointIterations steps), where a chain whose root lies inside
//    another target's chain extends up to that chain's root (the outer chain moves it anyway);
//  * every other active (unpinned) target then follows its effector (its position is set
//    to where the effector ended), so FK edits and other drags carry it along.
// So a pinned target keeps its effector where it is while other targets move.
constexpr int kIkJointIterations = 200;

struct IkPosingInput {
  const Skeleton* skeleton = nullptr;
  const std::vector<JointLimit>* limits = nullptr;  // may be empty
  std::vector<PoseIkTarget>* targets = nullptr;     // unpinned ones are moved to their effectors
  const PoseIkTarget* temporary = nullptr;          // auto-IK target, or null
  int driven = -1;                                  // index into *targets, or -1
  IkSettings settings;
};

// Solves as described above, editing `pose` in place; returns one report per solved
// target (driven / temporary first, then pinned ones). Invalid targets are skipped with
// converged = false.
std::vector<IkTargetReport> solveIkPosing(const IkPosingInput& input, Pose& pose);

}  // namespace kinema
