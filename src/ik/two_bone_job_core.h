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
KINEMA_IK_INLINE glm::quat unitFromTo(const glm::vec3& a, const glm::vec3& b) {
  const float d = glm::dot(a, b);
  if (d < -0.999999f) return fromToRotation(a, b);
  const glm::vec3 c = glm::cross(a, b);
  const glm::quat q(1.0f + d, c.x, c.y, c.z);
  return q / sqrtFloat(glm::dot(q, q));
}

inline glm::vec3 anyPerpendicular(const glm::vec3& v) {
  const glm::vec3 a = std::abs(v.x) < 0.9f ? glm::vec3(1.0f, 0.0f, 0.0f) : glm::vec3(0.0f, 1.0f, 0.0f);
  return glm::cross(v, a);
}

inline bool nearlyUnit(const glm::quat& q) { return std::abs(glm::dot(q, q) - 1.0f) < 1e-3f; }

// The job in glm scalars: every case.
inline void runTwoBoneJobScalar(const TwoBoneIkJob& job) {
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
    u = toTarget / dist;
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
  glm::vec3 w = glm::cross(n, u) / sqrtFloat(nn);
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

#if defined(__SSE2__)
namespace twobone_simd {
// glm::dot of two 3-vectors held in SSE lanes, in glm's order: (x + y) + z.
KINEMA_IK_INLINE float dot3(__m128 a, __m128 b) {
  const __m128 t = _mm_mul_ps(a, b);
  return _mm_cvtss_f32(_mm_add_ss(_mm_add_ss(t, _mm_shuffle_ps(t, t, _MM_SHUFFLE(1, 1, 1, 1))),
                                  _mm_shuffle_ps(t, t, _MM_SHUFFLE(2, 2, 2, 2))));
}
KINEMA_IK_INLINE __m128 scale(__m128 v, float s) { return _mm_mul_ps(v, _mm_set1_ps(s)); }
KINEMA_IK_INLINE __m128 divide(__m128 v, float s) { return _mm_div_ps(v, _mm_set1_ps(s)); }
KINEMA_IK_INLINE glm::vec3 toVec3(__m128 v) {
  glm::vec3 r;
  simd::store3(r, v);
  return r;
}
// unitFromTo on unit 3-vectors in lanes: the half-way quaternion (1 + a.b, a x b) times
// 1 / sqrt of glm's quaternion dot ((w w + x x) + (y y + z z)).
KINEMA_IK_INLINE __m128 unitFromTo(__m128 a, __m128 b) {
  const float d = dot3(a, b);
  if (d < -0.999999f) return simd::load(fromToRotation(toVec3(a), toVec3(b)));
  // Lane 3 of a and b is +0 (callers make sure), so that of their cross product is +0,
  // and or-ing 1 + d into it sets w without touching x y z (an add would turn -0 into +0).
  const __m128 c = simd::cross(a, b);
  const __m128 q = _mm_or_ps(c, _mm_set_ps(1.0f + d, 0.0f, 0.0f, 0.0f));
  const __m128 sq = _mm_mul_ps(q, q);
  const __m128 pairs = _mm_add_ps(sq, _mm_shuffle_ps(sq, sq, _MM_SHUFFLE(0, 1, 2, 3)));
  const float n = _mm_cvtss_f32(_mm_add_ss(pairs, _mm_shuffle_ps(pairs, pairs, _MM_SHUFFLE(1, 1, 1, 1))));
  return divide(q, sqrtFloat(n));
}
}  // namespace twobone_simd

// runTwoBoneJobScalar's common case in SSE lanes (3-vectors as x y z 0, quaternions as
// x y z w), the same operations in the same order (glm's dot and cross orders, products
// and sums lane by lane): the same bits. The rare branches (soften, twist, weight, a
// target on the start joint, no bend plane, a zero bone) return false before writing
// anything, and the scalar job runs instead.
KINEMA_IK_INLINE bool runTwoBoneJobSse(const TwoBoneIkJob& job) {
  namespace ts = twobone_simd;
  if (job.soften > 0.0f || job.twistAngle != 0.0f || job.weight < 1.0f) return false;
  const __m128 start = simd::load3(job.startPosition), mid = simd::load3(job.midPosition);
  const __m128 end = simd::load3(job.endPosition);
  const __m128 ab = _mm_sub_ps(mid, start), bc = _mm_sub_ps(end, mid);
  const float l1 = sqrtFloat(ts::dot3(ab, ab)), l2 = sqrtFloat(ts::dot3(bc, bc));
  if (!(l1 > 1e-12f && l2 > 1e-12f)) return false;
  const float reach = l1 + l2;
  const __m128 toTarget = _mm_sub_ps(simd::load3(job.target), start);
  const float dist = sqrtFloat(ts::dot3(toTarget, toTarget));
  if (!(dist > 1e-12f)) return false;
  const float minReach = std::abs(l1 - l2);
  const float d = std::clamp(dist, minReach, reach);
  const __m128 u = ts::divide(toTarget, dist);
  const __m128 pole = simd::load3(job.pole);
  __m128 n = simd::cross(u, pole);
  float nn = ts::dot3(n, n);
  if (!(nn > 1e-10f * ts::dot3(pole, pole))) {
    n = simd::cross(u, ab);
    nn = ts::dot3(n, n);
    if (!(nn > 1e-10f * ts::dot3(ab, ab))) return false;
  }
  const __m128 w = ts::divide(simd::cross(n, u), sqrtFloat(nn));
  const float cosA = d > 1e-12f ? std::clamp((l1 * l1 + d * d - l2 * l2) / (2.0f * l1 * d), -1.0f, 1.0f) : 0.0f;
  const float sinA = sqrtFloat(std::max(0.0f, 1.0f - cosA * cosA));
  const __m128 midDir = _mm_add_ps(ts::scale(u, cosA), ts::scale(w, sinA));
  const float inv1 = 1.0f / l1, inv2 = 1.0f / l2;
  const __m128 dA = ts::unitFromTo(ts::scale(ab, inv1), midDir);
  const __m128 lower = ts::scale(_mm_sub_ps(ts::scale(u, d), ts::scale(midDir, l1)), inv2);
  // rotate(conj(dA), lower): its lane 3 is not 0; unitFromTo needs 0 there.
  const __m128 xyz = _mm_castsi128_ps(_mm_set_epi32(0, -1, -1, -1));
  const __m128 dB = ts::unitFromTo(ts::scale(bc, inv2), _mm_and_ps(simd::rotate(simd::conjugate(dA), lower), xyz));
  const __m128 rs = simd::load(job.startRotation), rm = simd::load(job.midRotation);
  if (job.reached) *job.reached = dist >= minReach && dist <= reach;
  if (job.startTurn) simd::store(*job.startTurn, dA);
  if (job.midTurn) simd::store(*job.midTurn, dB);
  simd::store(*job.startCorrection, simd::mul(simd::mul(simd::conjugate(rs), dA), rs));
  simd::store(*job.midCorrection, simd::mul(simd::mul(simd::conjugate(rm), dB), rm));
  return true;
}
#endif

KINEMA_IK_INLINE void runTwoBoneJob(const TwoBoneIkJob& job) {
#if defined(__SSE2__)
  if (runTwoBoneJobSse(job)) return;
#endif
  runTwoBoneJobScalar(job);
}

}  // namespace kinema::ik_detail
