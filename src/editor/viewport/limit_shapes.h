#pragma once
#include <vector>

#include "core/math.h"
#include "ik/joint_limits.h"

namespace kinema {

// World-space geometry that shows a joint's limit (src/ik/joint_limits.h) around the joint:
// Cone: the swing cone as a rim (closed loop) + spokes from the joint, and a twist arc about
// the cone's axis. Hinge: an arc of the directions the bone can take about the hinge axis,
// with spokes at both ends. Euler: one arc per axis (each range about its own axis, ignoring
// the order's coupling; it is a guide, not the exact allowed set).
struct LimitShape {
  struct Polyline {
    std::vector<glm::vec3> points;
    bool closed = false;
    int axis = -1;  // Euler arcs: 0/1/2 (for colouring X/Y/Z); otherwise -1
  };
  std::vector<Polyline> rims;    // cone rim / hinge, Euler and twist arcs
  std::vector<glm::vec3> spokes; // pairs: from the joint to the rim / arc ends
};

// Inputs, ozz-job style.
struct LimitShapeJob {
  JointLimit limit;
  glm::vec3 jointPosition{0.0f};
  // World rotation of the joint's REST frame: parentWorldRotation * restRotation (limits are
  // expressed there).
  glm::quat restFrameWorld{1, 0, 0, 0};
  // The bone's direction in the rest frame (towards the first child); hinge and Euler arcs
  // sweep it. Need not be unit; a zero vector picks any perpendicular to the axis.
  glm::vec3 restBoneDirection{0.0f, 1.0f, 0.0f};
  float size = 1.0f;      // world length of the spokes (e.g. the bone's length)
  int segments = 32;      // per full circle

  std::string validate() const;
  // Fills `out` (empty for JointLimitType::None); false when validate() fails.
  bool run(LimitShape& out) const;
};

}  // namespace kinema
