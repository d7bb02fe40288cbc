// Cyclic coordinate descent (seed 002): from the joint nearest the effector back to the
// IK root, turn each joint so that joint->effector points along joint->target.
//
// Speed: while a sweep climbs from the effector to the root, each joint it reaches is an
// ancestor of every joint already turned, so that joint's world position and rotation are
// still those of the last FK; only the effector's position must be carried along. One
// sweep therefore costs O(chain) (one FK of the chain's slots at its end), not O(chain^2).
#include <algorithm>

#include "ik/ik_chain.h"

namespace kinema {

using ik_detail::Goal;
using ik_detail::IkChain;

namespace {

// The shortest rotation of `from` onto `to`, capped at maxAngle (the per-step damping).
glm::quat dampedFromTo(const glm::vec3& from, const glm::vec3& to, float fromSq, float toSq, float maxAngle) {
  glm::quat q = ik_detail::fastFromTo(from, to, fromSq, toSq);
  if (maxAngle < glm::pi<float>()) {
    glm::vec3 axis;
    float angle;
    toAxisAngle(q, axis, angle);
    if (angle > maxAngle) q = glm::angleAxis(maxAngle, axis);
  }
  return q;
}

// One sweep for goal g, effector to IK root. Reads world[] and rotation[] of the joints
// it visits (valid: see above), writes their local rotations and rotation[].
void sweep(IkChain& c, const Goal& g, const IkSettings& settings, int it) {
  IkTrace* trace = settings.trace;
  const bool damped = settings.maxStepAngle < glm::pi<float>();
  glm::vec3 effector = c.position(g.slot);
  for (int s = c.parentSlot[g.slot]; s >= 0; s = c.parentSlot[s]) {
    const glm::vec3 p = c.position(s);
    const glm::vec3 toEffector = effector - p, toTarget = g.position - p;
    const float ee = glm::dot(toEffector, toEffector), tt = glm::dot(toTarget, toTarget);
    // A target at the joint (or an effector on it) gives no direction: skip the joint.
    if (ee > 1e-20f && tt > 1e-20f) {
      const glm::quat delta = dampedFromTo(toEffector, toTarget, ee, tt, settings.maxStepAngle);
      const glm::quat& parentRot = c.parentRotation(s);
      glm::quat local = ik_detail::turnedLocal(parentRot, delta, c.rotation[s]);
      if (c.limit[s]) {
        local = applyJointLimit(*c.limit[s], c.skeleton->rest[c.joints[s]].rotation, local);
        const glm::quat newWorld = ik_detail::renormalize(parentRot * local);
        const glm::quat applied = ik_detail::renormalize(newWorld * glm::conjugate(c.rotation[s]));
        effector = p + applied * toEffector;
      } else if (damped) {
        effector = p + delta * toEffector;
      } else {
        // The full turn lays joint->effector along joint->target, length kept: no rotation
        // of the vector needed.
        effector = p + toTarget * std::sqrt(ee / tt);
      }
      // rotation[s] is not updated: the sweep never reads it again (it climbs to the
      // ancestors), and the FK after the sweep recomputes every slot.
      c.pose->local[c.joints[s]].rotation = local;
    }
    if (trace) {
      // Tracing only: refresh the sub-tree so the recorded positions are exact. The
      // sweep itself never reads them, so traced and untraced runs agree bit for bit.
      for (int k = s; k < s + c.subtreeSize[s]; ++k) c.forwardSlot(k);
      c.record(trace, it, IkStep::CcdJoint, c.joints[s]);
    }
    if (s == g.rootSlot) break;
  }
}

// sweep() in the common case, in registers: one target without orientation (its slots
// run root..effector, each the parent of the next), no limits, no damping, no trace. The
// same arithmetic as sweep() with fastFromTo and turnedLocal written out, operation for
// operation, so both give the same bits; GCC keeps these scalars in registers where the
// glm temporaries of the general loop went through the stack. Square roots are sqrtss
// (ik_detail::sqrtFloat: the same IEEE result as std::sqrt without its errno branch).
void plainSweep(IkChain& c, const Goal& g) {
  using ik_detail::sqrtFloat;
  const glm::vec3* pos = c.positions.data();
  const glm::quat* rot = c.rotation.data();
  const int* joints = c.joints.data();
  Transform* local = c.pose->local.data();
  const glm::quat& rootParent = c.fixedRotation[g.rootSlot];
  const float gx = g.position.x, gy = g.position.y, gz = g.position.z;
  float ex = pos[g.slot].x, ey = pos[g.slot].y, ez = pos[g.slot].z;
  for (int s = g.slot - 1; s >= g.rootSlot; --s) {
    const float px = pos[s].x, py = pos[s].y, pz = pos[s].z;
    const float ax = ex - px, ay = ey - py, az = ez - pz;  // joint -> effector
    const float bx = gx - px, by = gy - py, bz = gz - pz;  // joint -> target
    const float ee = ax * ax + ay * ay + az * az, tt = bx * bx + by * by + bz * bz;
    if (!(ee > 1e-20f && tt > 1e-20f)) continue;
    // The effector first: it is the chain from one joint to the next.
    const float k = sqrtFloat(ee / tt);
    ex = px + bx * k;
    ey = py + by * k;
    ez = pz + bz * k;
    const float ll = sqrtFloat(ee * tt), d = ax * bx + ay * by + az * bz;
    const float cx = ay * bz - by * az, cy = az * bx - bz * ax, cz = ax * by - bx * ay;
    const float n2 = 2.0f * ll * (ll + d);
#if defined(__SSE2__)
    __m128 delta;
    if (!(ll > 0.0f) || d < -0.999999f * ll || !(n2 > 1e-30f && n2 < 1e30f)) {
      delta = ik_detail::simd::load(ik_detail::fastFromTo(glm::vec3(ax, ay, az), glm::vec3(bx, by, bz), ee, tt));
    } else {
      delta = _mm_mul_ps(_mm_setr_ps(cx, cy, cz, ll + d), _mm_set1_ps(1.0f / sqrtFloat(n2)));
    }
    namespace simd = ik_detail::simd;
    const __m128 parentRot = simd::load(s > g.rootSlot ? rot[s - 1] : rootParent);
    simd::store(local[joints[s]].rotation,
                simd::renormalize(simd::mul(simd::mul(simd::conjugate(parentRot), delta), simd::load(rot[s]))));
#else
    glm::quat delta;
    if (!(ll > 0.0f) || d < -0.999999f * ll || !(n2 > 1e-30f && n2 < 1e30f)) {
      delta = ik_detail::fastFromTo(glm::vec3(ax, ay, az), glm::vec3(bx, by, bz), ee, tt);
    } else {
      const float kq = 1.0f / sqrtFloat(n2);
      delta = glm::quat((ll + d) * kq, cx * kq, cy * kq, cz * kq);
    }
    local[joints[s]].rotation = ik_detail::turnedLocal(s > g.rootSlot ? rot[s - 1] : rootParent, delta, rot[s]);
#endif
  }
}

}  // namespace

IkResult solveCcd(const IkProblem& problem, const IkSettings& settings) {
  IkChain& c = ik_detail::workspace();
  if (IkResult bad; !(bad.message = c.begin(problem, settings)).empty()) return bad;
  IkTrace* trace = settings.trace;
  const bool plain = !trace && !(settings.maxStepAngle < glm::pi<float>()) && c.goals.size() == 1 &&
                     !c.goals[0].hasOrientation && !c.hasLimits();
  int it = 0;
  float error = c.maxError();  // of the current pose: measured once per sweep
  while (!c.converged(error, settings) && it < settings.maxIterations) {
    ++it;
    for (const Goal& g : c.goals) {
      if (g.hasOrientation) {
        // The effector itself turns to the target orientation first.
        c.rotateJoint(g.slot, ik_detail::renormalize(g.orientation * glm::conjugate(c.rotation[g.slot])));
        c.record(trace, it, IkStep::CcdJoint, c.joints[g.slot]);
      }
      if (plain)
        plainSweep(c, g);
      else
        sweep(c, g, settings, it);
      // Bring every slot up to date before the next goal (or the error test) reads them.
      c.forwardKinematics();
    }
    error = c.maxError();
    if (c.stalled(error, settings)) break;
  }
  if (!c.converged(error, settings) && c.straightenIfUnreachable()) c.record(trace, it, IkStep::Straighten);
  return c.result(it, settings);
}

}  // namespace kinema
