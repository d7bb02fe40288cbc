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
#if defined(__SSE2__)
  // 3-vectors in SSE lanes x y z, lane 3 kept +0 (masked on load), so that the cross
  // product's lane 3 is +0 and the half-way quaternion's w can be or-ed in. Dots in the
  // scalar order ((x x + y y) + z z), the rest lane by lane: the same bits.
  namespace simd = ik_detail::simd;
  const __m128 xyz = _mm_castsi128_ps(_mm_set_epi32(0, -1, -1, -1));
  auto dot3 = [](__m128 a, __m128 b) {
    const __m128 t = _mm_mul_ps(a, b);
    return _mm_cvtss_f32(_mm_add_ss(_mm_add_ss(t, _mm_shuffle_ps(t, t, _MM_SHUFFLE(1, 1, 1, 1))),
                                    _mm_shuffle_ps(t, t, _MM_SHUFFLE(2, 2, 2, 2))));
  };
  const __m128 target = simd::load3(g.position);
  __m128 effector = simd::load3(pos[g.slot]);
  for (int s = g.slot - 1; s >= g.rootSlot; --s) {
    // pos[s + 1] follows pos[s]: a 4-float load stays inside the array.
    const __m128 p = _mm_and_ps(_mm_loadu_ps(&pos[s].x), xyz);
    const __m128 a = _mm_sub_ps(effector, p), b = _mm_sub_ps(target, p);  // joint -> effector, -> target
    const float ee = dot3(a, a), tt = dot3(b, b);
    // A target at the joint (or an effector on it) gives no direction: skip the joint.
    if (!(ee > 1e-20f && tt > 1e-20f)) continue;
    // The effector first: it is the chain from one joint to the next. The full turn lays
    // joint->effector along joint->target, length kept.
    effector = _mm_add_ps(p, _mm_mul_ps(b, _mm_set1_ps(sqrtFloat(ee / tt))));
    const float ll = sqrtFloat(ee * tt), d = dot3(a, b);
    const float n2 = 2.0f * ll * (ll + d);
    __m128 delta;
    if (!(ll > 0.0f) || d < -0.999999f * ll || !(n2 > 1e-30f && n2 < 1e30f)) {
      glm::vec3 from, to;
      simd::store3(from, a);
      simd::store3(to, b);
      delta = simd::load(ik_detail::fastFromTo(from, to, ee, tt));
    } else {
      const __m128 half = _mm_or_ps(simd::cross(a, b), _mm_set_ps(ll + d, 0.0f, 0.0f, 0.0f));
      delta = _mm_mul_ps(half, _mm_set1_ps(1.0f / sqrtFloat(n2)));
    }
    const __m128 parentRot = simd::load(s > g.rootSlot ? rot[s - 1] : rootParent);
    simd::store(local[joints[s]].rotation,
                simd::renormalize(simd::mul(simd::mul(simd::conjugate(parentRot), delta), simd::load(rot[s]))));
  }
#else
  const float gx = g.position.x, gy = g.position.y, gz = g.position.z;
  float ex = pos[g.slot].x, ey = pos[g.slot].y, ez = pos[g.slot].z;
  for (int s = g.slot - 1; s >= g.rootSlot; --s) {
    const float px = pos[s].x, py = pos[s].y, pz = pos[s].z;
    const float ax = ex - px, ay = ey - py, az = ez - pz;  // joint -> effector
    const float bx = gx - px, by = gy - py, bz = gz - pz;  // joint -> target
    const float ee = ax * ax + ay * ay + az * az, tt = bx * bx + by * by + bz * bz;
    if (!(ee > 1e-20f && tt > 1e-20f)) continue;
    const float k = sqrtFloat(ee / tt);
    ex = px + bx * k;
    ey = py + by * k;
    ez = pz + bz * k;
    const float ll = sqrtFloat(ee * tt), d = ax * bx + ay * by + az * bz;
    const float cx = ay * bz - by * az, cy = az * bx - bz * ax, cz = ax * by - bx * ay;
    const float n2 = 2.0f * ll * (ll + d);
    glm::quat delta;
    if (!(ll > 0.0f) || d < -0.999999f * ll || !(n2 > 1e-30f && n2 < 1e30f)) {
      delta = ik_detail::fastFromTo(glm::vec3(ax, ay, az), glm::vec3(bx, by, bz), ee, tt);
    } else {
      const float kq = 1.0f / sqrtFloat(n2);
      delta = glm::quat((ll + d) * kq, cx * kq, cy * kq, cz * kq);
    }
    local[joints[s]].rotation = ik_detail::turnedLocal(s > g.rootSlot ? rot[s - 1] : rootParent, delta, rot[s]);
  }
#endif
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
