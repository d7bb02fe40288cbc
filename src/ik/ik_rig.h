#pragma once
#include <string>
#include <vector>

#include "core/skeleton.h"
#include "ik/ik_target.h"
#include "ik/joint_limits.h"
#include "ik/ik_solver_kind.h"

namespace kinema {

// The IK data that travels with a skeleton (and in .kinema files under "ik"): joint
// limits and saved targets. Kept apart from core::Skeleton so core has no IK types.
struct IkRig {
  // Empty (no limits) or one entry per skeleton joint.
  std::vector<JointLimit> limits;
  std::vector<IkTarget> targets;
  // How the editor drives each saved target: empty, or one entry per target.
  std::vector<IkTargetOptions> targetOptions;

  bool empty() const { return limits.empty() && targets.empty(); }
  // The limit of `joint`, or nullptr when it has none.
  const JointLimit* limitOf(int joint) const {
    if (joint < 0 || joint >= static_cast<int>(limits.size()) || !limits[joint].active()) return nullptr;
    return &limits[joint];
  }
  void setLimit(int jointCount, int joint, const JointLimit& limit) {
    if (static_cast<int>(limits.size()) < jointCount) limits.resize(jointCount);
    limits[joint] = limit;
  }
  // Empty when the rig fits the skeleton; otherwise one sentence naming the problem.
  std::string validate(const Skeleton& skeleton) const;
};

}  // namespace kinema
