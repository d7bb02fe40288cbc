#pragma once
#include <string>
#include <vector>

#include "core/mesh.h"
#include "core/skeleton.h"
#include "core/result.h"

namespace kinema {

// A leaf (`@`) the turtle left: the joint it hangs on and where it points (model space).
struct LSystemLeaf {
  int joint = -1;
  glm::vec3 position{0.0f};
  glm::quat orientation{1.0f, 0.0f, 0.0f, 0.0f};
};

// The turtle interpretation of a derived string as a skeleton (the seed's 16.6). The turtle
// starts at the origin heading +Y (up); `f` moves it `segmentLength` forward and adds a joint
// whose parent is the joint the turtle stood on, `+`/`-` turn it by +-angleDegrees about its
// own Z axis (the seed's world Z while it stays in the XY plane), `[`/`]` push and pop
// position, heading and joint, `@` records a leaf; every other symbol is ignored. Joint 0 is
// the root ("root") at the origin; the joint of the k-th `f` is "seg_k" (k from 1). Each joint's
// rest rotation is the turtle's heading when it was made, relative to its parent, so rotating
// a joint swings every segment that grows from it. Model space, metres; angles in degrees.
struct LSystemTurtleJob {
  std::string symbols;             // a derived string
  double angleDegrees = 60.0;      // finite
  float segmentLength = 1.0f;      // > 0, metres
  size_t maxJoints = 1u << 16;     // more segments than this is refused (the editor's limit)

  Skeleton skeleton;                // outputs: one joint per `f` plus the root
  std::vector<LSystemLeaf> leaves;

  std::string validate() const;     // finite angle, positive length, balanced [ ], joints <= maxJoints
  bool run(std::string& error);
};

// Tube geometry for a turtle's skeleton, rigidly skinned: the segment from joint P to its
// child C is a `sides`-sided open cylinder of `radius` (metres) weighted fully to P (the bone
// that turns it), each leaf a small double-sided diamond (`leafSize` long) on its joint.
// `skin` lists every joint in order with inverse bind = the inverse rest world matrix, so
// the rest pose shows the mesh where it was built.
struct LSystemTubeJob {
  const Skeleton* skeleton = nullptr;
  const std::vector<LSystemLeaf>* leaves = nullptr;  // may be null
  float radius = 0.1f;   // > 0
  int sides = 8;         // 3 .. 64
  float leafSize = 0.4f; // >= 0 (0: no leaf geometry)

  MeshPrimitive primitive;  // outputs
  Skin skin;

  std::string validate() const;
  bool run(std::string& error);
};

}  // namespace kinema
