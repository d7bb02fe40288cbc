// The two-bone triangle (seed 002's law of cosines): with bone lengths l1, l2 and the
// start-target distance d, the start joint's angle A between its bone and start->target
// obeys l2^2 = l1^2 + d^2 - 2 l1 d cos A, so the mid joint goes to
// start + l1 (cos A u + sin A w), u the unit direction to the target and w the unit bend
// direction (pole side, perpendicular to u). sin A comes from cos A by one square root
// (A itself is never needed), and each bone is turned by a half-way quaternion.
#include "ik/two_bone_job.h"

#include <algorithm>
#include <cmath>

#include "core/rotation.h"
#include "ik/ik_chain.h"

namespace kinema {

namespace {

// The rotation taking unit vector a onto unit vector b: the half-way quaternion
// (1 + a.b, a x b) normalised, one square root. Opposite vectors: any perpendicular axis.
glm::quat unitFromTo(const glm::vec3& a, const glm::vec3& b) {
  const float d = glm::dot(a, b);
  if (d < -0.999999f) return fromToRotation(a, b);
  const glm::vec3 c = glm::cross(a, b);
  const glm::quat q(1.0f + d, c.x, c.y, c.z);
  return q * (1.0f / std::sqrt(glm::dot(q, q)));
}

glm::vec3 anyPerpendicular(const glm::vec3& v) {
  const glm::vec3 a = std::abs(v.x) < 0.9f ? glm::vec3(1.0f, 0.0f, 0.0f) : glm::vec3(0.0f, 1.0f, 0.0f);
  return glm::cross(v, a);
}

bool nearlyUnit(const glm::quat& q) { return std::abs(glm::dot(q, q) - 1.0f) < 1e-3f; }

}  // namespace

std::string TwoBoneIkJob::validate() const {
  if (!startCorrection || !midCorrection) return "two-bone job: startCorrection and midCorrection must be set";
  if (!isFinite(startPosition) || !isFinite(midPosition) || !isFinite(endPosition))
    return "two-bone job: joint positions are not finite";
  if (!isFinite(target)) return "two-bone job: target is not finite";
  if (!isFinite(pole)) return "two-bone job: pole is not finite";
  if (!isFinite(startRotation) || !nearlyUnit(startRotation) || !isFinite(midRotation) || !nearlyUnit(midRotation))
    return "two-bone job: joint rotations must be unit quaternions";
  if (!std::isfinite(twistAngle)) return "two-bone job: twist angle is not finite";
  if (!(weight >= 0.0f && weight <= 1.0f)) return "two-bone job: weight must lie in [0, 1]";
  if (!(soften >= 0.0f && soften <= 1.0f)) return "two-bone job: soften must lie in [0, 1]";
  return "";
}

bool TwoBoneIkJob::run() const {
  if (!validate().empty()) return false;
  runUnchecked();
  return true;
}

void TwoBoneIkJob::runUnchecked() const {
  const glm::vec3 ab = midPosition - startPosition, bc = endPosition - midPosition;
  const float l1 = std::sqrt(glm::dot(ab, ab)), l2 = std::sqrt(glm::dot(bc, bc));
  const float reach = l1 + l2;
  glm::vec3 toTarget = target - startPosition;
  float dist = std::sqrt(glm::dot(toTarget, toTarget));
  bool softened = false;
  if (soften > 0.0f && reach > 0.0f) {
    // Soft IK: past reach - s the end approaches full extension exponentially.
    const float s = soften * reach, da = reach - s;
    if (dist > da && dist > 0.0f) {
      const float d = da + s * (1.0f - std::exp(-(dist - da) / s));
      toTarget *= d / dist;
      dist = d;
      softened = true;
    }
  }
  const float minReach = std::abs(l1 - l2);
  if (reached) *reached = !softened && dist >= minReach && dist <= reach;
  const float d = std::clamp(dist, minReach, reach);

  glm::vec3 u;
  if (dist > 1e-12f) {
    u = toTarget * (1.0f / dist);
  } else {  // target on the start joint: keep the current aim
    u = endPosition - startPosition;
    if (glm::dot(u, u) < 1e-20f) u = ab;
    if (glm::dot(u, u) < 1e-20f) u = glm::vec3(0.0f, 1.0f, 0.0f);
    u = glm::normalize(u);
  }
  // The bend direction w: the pole's part perpendicular to u, else the mid joint's, as
  // (u x v) x u. Cross products keep w perpendicular to u even when v nearly lies along u,
  // where subtracting v's part along u would leave mostly rounding error. n is the bend axis.
  glm::vec3 n = glm::cross(u, pole);
  float nn = glm::dot(n, n);
  if (!(nn > 1e-10f * glm::dot(pole, pole))) {  // no pole, or along the target line
    n = glm::cross(u, ab);
    nn = glm::dot(n, n);
    if (!(nn > 1e-10f * glm::dot(ab, ab))) {
      n = anyPerpendicular(u);
      nn = glm::dot(n, n);
    }
  }
  glm::vec3 w = glm::cross(n, u) * (1.0f / std::sqrt(nn));
  if (twistAngle != 0.0f) w = std::cos(twistAngle) * w + std::sin(twistAngle) * glm::cross(u, w);

  // World rotations: dA turns the whole arm about the start joint, dB the lower bone
  // about the mid joint, both expressed before dA is applied.
  glm::quat dA(1.0f, 0.0f, 0.0f, 0.0f), dB(1.0f, 0.0f, 0.0f, 0.0f);
  if (l1 > 1e-12f && l2 > 1e-12f) {
    // d = 0 only when l1 = l2 (d >= |l1 - l2|): the arm folds flat, cos A -> 0.
    const float cosA = d > 1e-12f ? std::clamp((l1 * l1 + d * d - l2 * l2) / (2.0f * l1 * d), -1.0f, 1.0f) : 0.0f;
    const float sinA = std::sqrt(std::max(0.0f, 1.0f - cosA * cosA));
    const glm::vec3 midDir = cosA * u + sinA * w;  // unit
    const float inv1 = 1.0f / l1, inv2 = 1.0f / l2;
    dA = unitFromTo(ab * inv1, midDir);
    // After dA the mid joint sits at start + l1 midDir; its bone must point at
    // start + d u, a vector of length l2. Taken back through dA, dB needs no new frame.
    const glm::vec3 lower = (d * u - l1 * midDir) * inv2;
    dB = unitFromTo(bc * inv2, ik_detail::rotate(glm::conjugate(dA), lower));
  } else {
    dA = fromToRotation(endPosition - startPosition, u);  // a zero-length bone: aim only
  }
  // A world turn D of a joint with world rotation R is the local correction R^-1 D R.
  glm::quat cA = ik_detail::mul(ik_detail::mul(glm::conjugate(startRotation), dA), startRotation);
  glm::quat cB = ik_detail::mul(ik_detail::mul(glm::conjugate(midRotation), dB), midRotation);
  if (weight < 1.0f) {
    const glm::quat identity(1.0f, 0.0f, 0.0f, 0.0f);
    cA = slerpShortest(identity, cA, weight);
    cB = slerpShortest(identity, cB, weight);
    dA = startRotation * cA * glm::conjugate(startRotation);
    dB = midRotation * cB * glm::conjugate(midRotation);
  }
  if (startTurn) *startTurn = dA;
  if (midTurn) *midTurn = dB;
  *startCorrection = cA;
  *midCorrection = cB;
}

}  // namespace kinema
