#pragma once
#include <string>
#include <vector>

#include "core/pose.h"

namespace kinema {

// Forward kinematics as an ozz-style job: explicit inputs and outputs, no hidden state.
// world[i] = world[parents[i]] * local[i] (roots: root * local[i]), in one forward loop,
// which is correct because parents[i] < i.
struct LocalToWorldJob {
  const int* parents = nullptr;     // count entries, parents[i] < i
  const Transform* local = nullptr; // count entries
  glm::mat4* world = nullptr;       // count entries, written
  int count = 0;
  glm::mat4 root{1.0f};             // placement of the whole skeleton
  // -1 updates every joint. Otherwise only this joint and its descendants are
  // written, and world[] must already hold valid transforms for the other joints.
  int subtreeRoot = -1;

  // Empty when the inputs are usable; otherwise what is wrong with them.
  std::string validate() const;
  // Runs the job; returns false (and writes nothing) when validate() fails.
  bool run() const;
};

// Convenience wrappers over LocalToWorldJob for whole skeletons.
std::vector<glm::mat4> computeWorld(const Skeleton& skeleton, const Pose& pose);
void computeWorld(const Skeleton& skeleton, const Pose& pose, std::vector<glm::mat4>& world);
// The vertical (Y) extent of the joints at the rest pose, file units: how tall a character
// stands. 0 for a skeleton of fewer than two joints or a flat one.
float restJointHeight(const Skeleton& skeleton);
// Recomputes world[] for `joint` and everything below it (IK changes one sub-tree).
void updateSubtree(const Skeleton& skeleton, const Pose& pose, int joint,
                   std::vector<glm::mat4>& world);

// world = parent * local for affine matrices (bottom rows 0,0,0,1), 36 multiplies.
inline glm::mat4 multiplyAffine(const glm::mat4& a, const glm::mat4& b) {
  glm::mat4 r;
  for (int c = 0; c < 3; ++c) r[c] = a[0] * b[c].x + a[1] * b[c].y + a[2] * b[c].z;
  r[3] = a[0] * b[3].x + a[1] * b[3].y + a[2] * b[3].z + a[3];
  return r;
}

}  // namespace kinema
