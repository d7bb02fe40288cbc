#pragma once
#include "ik/ik_solver.h"
#include "ik/ik_target.h"

namespace kinema {

// An IK target as the editor keeps it: the solver's IkTarget (effector, root, position,
// orientation, pole, weight) plus the per-target editor settings.
struct PoseIkTarget {
  IkTarget target;
  // > 0: the chain is this many bones up from the effector (Blender's chain length) and
  // overrides target.root; 0: target.root decides (-1 = topmost ancestor / grandparent).
  int chainLength = 0;
  IkSolver solver = IkSolver::JacobianDls;
  bool active = true;   // solved at all
  // Pinned: holds its effector where the target is while other targets or joints move.
  // Unpinned: follows its effector when something else moves it (see ik_posing.h).
  bool pinned = false;

  // The IkTarget handed to the solver, with chainLength resolved into `root`.
  IkTarget resolved(const Skeleton& skeleton) const;
  // Empty when usable with this skeleton; otherwise one line.
  std::string validate(const Skeleton& skeleton) const;
};

// Exact (bitwise for floats) equality, for the history's change detection.
bool sameBits(const PoseIkTarget& a, const PoseIkTarget& b);

}  // namespace kinema
