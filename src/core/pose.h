#pragma once
#include <string>
#include <vector>

#include "core/skeleton.h"

namespace kinema {

// Local transforms, one per joint of a skeleton, in the skeleton's joint order.
struct Pose {
  std::vector<Transform> local;

  static Pose rest(const Skeleton& skeleton) { return Pose{skeleton.rest}; }
  int size() const { return static_cast<int>(local.size()); }

  // Empty when the pose fits the skeleton (one finite transform per joint).
  std::string validate(const Skeleton& skeleton) const;
};

}  // namespace kinema
