#pragma once
#include <string>
#include <vector>

#include "core/transform.h"

namespace kinema {

// A joint tree (or forest) stored as flat arrays, ozz-style: parents[i] < i for every
// joint, roots have parent -1, so forward kinematics is a single forward loop.
struct Skeleton {
  std::vector<std::string> names;
  std::vector<int> parents;
  std::vector<Transform> rest;  // rest (bind) local transforms

  int size() const { return static_cast<int>(parents.size()); }
  bool empty() const { return parents.empty(); }

  // Appends a joint and returns its index; `parent` must already exist (or be -1).
  int addJoint(const std::string& name, int parent, const Transform& restLocal);

  // Index of the joint with this name, or -1.
  int find(const std::string& name) const;

  // Empty when the skeleton is well formed; otherwise one sentence naming the first
  // problem: array sizes differ, an empty or duplicate name, a parent index out of
  // range, a joint that is its own ancestor (cycle), a parent listed after its child,
  // or a non-finite number in a rest transform.
  std::string validate() const;

  // True when `joint` is `ancestor` or lies below it.
  bool isInSubtree(int joint, int ancestor) const;
};

}  // namespace kinema
