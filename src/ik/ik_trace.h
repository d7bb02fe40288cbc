#pragma once
#include <vector>

#include "core/math.h"

namespace kinema {

// What a solver did, step by step, for teaching and `kinema ik --trace`. Solvers write
// only when IkSettings::trace is set, so tracing off costs one pointer test per step.
enum class IkStep { Start, CcdJoint, FabrikBackward, FabrikForward, JacobianStep, TwoBone, Straighten };
const char* toString(IkStep step);

struct IkTraceEntry {
  int iteration = 0;  // 0 = the start state, then 1, 2, ...
  IkStep step = IkStep::Start;
  int joint = -1;     // CcdJoint: the joint just rotated
  float error = 0.0f; // largest effector distance after this step
  std::vector<glm::vec3> positions;  // world positions of IkTrace::joints
};

struct IkTrace {
  std::vector<int> joints;  // the skeleton joints the solver moved, parents first
  std::vector<IkTraceEntry> entries;
  void clear() {
    joints.clear();
    entries.clear();
  }
};

}  // namespace kinema
