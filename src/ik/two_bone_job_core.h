#pragma once
// TwoBoneIkJob::runUnchecked's body, inline: the job's own run() calls it, and solveTwoBone
// (two_bone.cpp) runs it on a job that lives in its registers, so the compiler keeps the
// job's fields there instead of storing and reloading them. Internal to src/ik.
// The two-bone triangle (seed 002's law of cosines): with bone lengths l1, l2 and the
// start-target distance d, the start joint's angle A between its bone and start->target
// obeys l2^2 = l1^2 + d^2 - 2 l1 d cos A, so the mid joint goes to
// start + l1 (cos A u + sin A w), u the unit direction to the target and w the unit bend
// direction (pole side, perpendicular to u). sin A comes from cos A by one square root
// (A itself is never needed), and each bone is turned by a half-way quaternion.
#include <algorithm>
#include <cmath>

#include "core/rotation.h"
#include "ik/ik_chain.h"
#include "ik/two_bone_job.h"

namespace kinema::ik_detail {

// The rotation taking unit vector a onto unit vector b: the half-way quaternion
// (1 + a.b, a x b) normalised, one square root. Opposite vectors: any perpendicular axis.
inline glm::quat unitFromTo(const glm::vec3& a, const glm::vec3& b) {
  const float d = glm::dot(a, b);
  if (d < -0.999999f) return fromToRotation(a, b);
  const glm::vec3 c = glm::cross(a, b);
  const glm::quat q(1.0f + d, c.x, c.y, c.z);
  return q * (1.0f / sqrtFloat(glm::dot(q, q)));
}

inline glm::vec3 anyPerpendicular(const glm::vec3& v) {
  const glm::vec3 a = std::abs(v.x) < 0.9f ? glm::vec3(1.0f, 0.0f, 0.0f) : glm::vec3(0.0f, 1.0f, 0.0f);
  return glm::cross(v, a);
}

inline bool nearlyUnit(const glm::quat& q) { return std::abs(glm::dot(q, q) - 1.0f) < 1e-3f; }

[[gnu::always_inline]] inline void runTwoBoneJob(const TwoBoneIkJob& job) {
  const glm::vec3 ab = job.midPosition - job.startPosition, bc = job.endPosition - job.midPosition;
  const float l1 = sqrtFloat(glm::dot(ab, ab)), l2 = sqrtFloat(glm::dot(bc, bc));
  const float reach = l1 + l2;
  glm::vec3 toTarget = job.target - job.startPosition;
  float dist = sqrtFloat(glm::dot(toTarget, toTarget));
  bool softened = false;
  if (job.soften > 0.0f && reach > 0.0f) {
    // Soft IK: past reach - s the end approaches full extension exponentially.
    const float s = job.soften * reach, da = reach - s;
    if (dist > da && dist > 0.0f) {
      const float d = da + s * (1.0f - std::exp(-(dist - da) / s));
      toTarget *= d / dist;
      dist = d;
      softened = true;
    }
  }
  const float minReach = std::abs(l1 - l2);
  if (job.reached) *job.reached = !softened && dist >= minReach && dist <= reach;
  const float d = std::clamp(dist, minReach, reach);

  glm::vec3 u;
  if (dist > 1e-12f) {
    u = toTarget * (1.0f / dist);
  } else {  // target on the start joint: keep the current aim
    u = job.endPosition - job.startPosition;
    if (glm::dot(u, u) < 1e-20f) u = ab;
    if (glm::dot(u, u) < 1e-20f) u = glm::vec3(0.0f, 1.0f, 0.0f);
    u = glm::normalize(u);
  }
  // The bend direction w: the pole's part perpendicular to u, else the mid joint's, as
  // (u x v) x u. Cross products keep w perpendicular to u even when v nearly lies along u,
  // where subtracting v's part along u would leave mostly rounding error. n is the bend axis.
  glm::vec3 n = glm::cross(u, job.pole);
  float nn = glm::dot(n, n);
  if (!(nn > 1e-10f * glm::dot(job.pole, job.pole))) {  // no pole, or along the target line
    n = glm::cross(u, ab);
    nn = glm::dot(n, n);
    if (!(nn > 1e-10f * glm::dot(ab, ab))) {
      n = anyPerpendicular(u);
      nn = glm::dot(n, n);
    }
  }
  glm::vec3 w = glm::cross(n, u) * (1.0f / sqrtFloat(nn));
  if (job.twistAngle != 0.0f) w = std::cos(job.twistAngle) * w + std::sin(job.twistAngle) * glm::cross(u, w);

  // World rotations: dA turns the whole arm about the start joint, dB the lower bone
  // about the mid joint, both expressed before dA is applied.
  glm::quat dA(1.0f, 0.0f, 0.0f, 0.0f), dB(1.0f, 0.0f, 0.0f, 0.0f);
  if (l1 > 1e-12f && l2 > 1e-12f) {
    // d = 0 only when l1 = l2 (d >= |l1 - l2|): the arm folds flat, cos A -> 0.
    const float cosA = d > 1e-12f ? std::clamp((l1 * l1 + d * d - l2 * l2) / (2.0f * l1 * d), -1.0f, 1.0f) : 0.0f;
    const float sinA = sqrtFloat(std::max(0.0f, 1.0f - cosA * cosA));
    const glm::vec3 midDir = cosA * u + sinA * w;  // unit
    const float inv1 = 1.0f / l1, inv2 = 1.0f / l2;
    dA = unitFromTo(ab * inv1, midDir);
    // After dA the mid joint sits at start + l1 midDir; its bone must point at
    // start + d u, a vector of length l2. Taken back through dA, dB needs no new frame.
    const glm::vec3 lower = (d * u - l1 * midDir) * inv2;
    dB = unitFromTo(bc * inv2, ik_detail::rotate(glm::conjugate(dA), lower));
  } else {
    dA = fromToRotation(job.endPosition - job.startPosition, u);  // a zero-length bone: aim only
  }
  // A world turn D of a joint with world rotation R is the local correction R^-1 D R.
  glm::quat cA = ik_detail::mul(ik_detail::mul(glm::conjugate(job.startRotation), dA), job.startRotation);
  glm::quat cB = ik_detail::mul(ik_detail::mul(glm::conjugate(job.midRotation), dB), job.midRotation);
  if (job.weight < 1.0f) {
    const glm::quat identity(1.0f, 0.0f, 0.0f, 0.0f);
    cA = slerpShortest(identity, cA, job.weight);
    cB = slerpShortest(identity, cB, job.weight);
    dA = job.startRotation * cA * glm::conjugate(job.startRotation);
    dB = job.midRotation * cB * glm::conjugate(job.midRotation);
  }
  if (job.startTurn) *job.startTurn = dA;
  if (job.midTurn) *job.midTurn = dB;
  *job.startCorrection = cA;
  *job.midCorrection = cB;
}

}  // namespace kinema::ik_detail
