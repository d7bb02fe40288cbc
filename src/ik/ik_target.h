#pragma once
#include <string>

#include "core/math.h"
#include "core/skeleton.h"

namespace kinema {

// One IK goal: bring `effector` to `position` (and optionally to `orientation`, a world
// rotation), moving only the joints from `root` down to the effector.
struct IkTarget {
  int effector = -1;
  // The chain's first joint: it may rotate but its position never moves. -1 = the
  // effector's topmost ancestor (for the two-bone solver: its grandparent).
  int root = -1;
  glm::vec3 position{0.0f};
  bool hasOrientation = false;
  glm::quat orientation{1.0f, 0.0f, 0.0f, 0.0f};
  float weight = 1.0f;  // relative importance when targets compete (> 0)
  // Two-bone only: the middle joint (-1 = the effector's parent) and the bend-plane hint
  // (a world point the middle joint bends towards; ignored when hasPole is false).
  int mid = -1;
  bool hasPole = false;
  glm::vec3 pole{0.0f};

  // Empty when usable with this skeleton; otherwise one sentence naming the problem.
  std::string validate(const Skeleton& skeleton) const;
};

// The effective IK root of a target (resolving -1 as described above).
int ikRootOf(const Skeleton& skeleton, const IkTarget& target, bool twoBone = false);

}  // namespace kinema
