// Cyclic coordinate descent (seed 002): from the joint nearest the effector back to the
// IK root, turn each joint so that joint->effector points along joint->target.
#include <algorithm>

#include "ik/ik_chain.h"

namespace kinema {

using ik_detail::Goal;
using ik_detail::IkChain;

namespace {

// The shortest rotation of `from` onto `to`, capped at maxAngle (the per-step damping).
glm::quat dampedFromTo(const glm::vec3& from, const glm::vec3& to, float maxAngle) {
  glm::quat q = fromToRotation(from, to);
  if (maxAngle < glm::pi<float>()) {
    glm::vec3 axis;
    float angle;
    toAxisAngle(q, axis, angle);
    if (angle > maxAngle) q = glm::angleAxis(maxAngle, axis);
  }
  return q;
}

}  // namespace

IkResult solveCcd(const IkProblem& problem, const IkSettings& settings) {
  IkResult bad;
  bad.message = problem.validate();
  if (!bad.message.empty()) return bad;
  IkChain c;
  c.build(problem);
  IkTrace* trace = settings.trace;
  c.record(trace, 0, IkStep::Start);
  int it = 0;
  while (!c.converged(settings) && it < settings.maxIterations) {
    ++it;
    for (const Goal& g : c.goals) {
      if (g.hasOrientation) {
        // The effector itself turns to the target orientation first.
        c.rotateJoint(g.slot, safeNormalize(g.orientation * glm::conjugate(c.rotation[g.slot])));
        c.record(trace, it, IkStep::CcdJoint, c.joints[g.slot]);
      }
      for (int s = c.parentSlot[g.slot]; s >= 0; s = c.parentSlot[s]) {
        const glm::vec3 p = c.position(s);
        const glm::vec3 toEffector = c.position(g.slot) - p, toTarget = g.position - p;
        // A target at the joint (or an effector on it) gives no direction: skip the joint.
        if (glm::dot(toEffector, toEffector) > 1e-20f && glm::dot(toTarget, toTarget) > 1e-20f)
          c.rotateJoint(s, dampedFromTo(toEffector, toTarget, settings.maxStepAngle));
        c.record(trace, it, IkStep::CcdJoint, c.joints[s]);
        if (s == g.rootSlot) break;
      }
    }
    // Rigid updates accumulate rounding; one FK pass per sweep keeps positions exact.
    c.forwardKinematics();
    if (c.stalled(c.maxError(), settings)) break;
  }
  if (!c.converged(settings) && c.straightenIfUnreachable()) c.record(trace, it, IkStep::Straighten);
  return c.result(it, settings);
}

}  // namespace kinema
