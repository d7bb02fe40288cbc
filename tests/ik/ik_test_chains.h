#pragma once
// Chains and random poses shared by the IK tests.
#include <cmath>
#include <random>
#include <vector>

#include "core/forward_kinematics.h"
#include "core/rotation.h"
#include "core/skeleton.h"

namespace kinema::test {

// n joints in a line along +Y, bone lengths varying 0.5..1.5 (so joints are not all alike).
inline Skeleton makeChain(int n, std::mt19937* rng = nullptr) {
  Skeleton s;
  std::uniform_real_distribution<float> len(0.5f, 1.5f);
  for (int i = 0; i < n; ++i)
    s.addJoint("j" + std::to_string(i), i - 1,
               Transform::fromTranslation(glm::vec3(0.0f, i == 0 ? 0.0f : (rng ? len(*rng) : 1.0f), 0.0f)));
  return s;
}

// Root at the origin, bones along +X of lengths l1, l2; every joint turns about Z.
inline Skeleton planarArm(float l1, float l2) {
  Skeleton s;
  s.addJoint("shoulder", -1, Transform::identity());
  s.addJoint("elbow", 0, Transform::fromTranslation({l1, 0.0f, 0.0f}));
  s.addJoint("hand", 1, Transform::fromTranslation({l2, 0.0f, 0.0f}));
  return s;
}

// Hips -> spine -> chest, then two arms of three joints: two hands, one shared spine.
inline Skeleton twoArms() {
  Skeleton s;
  s.addJoint("hips", -1, Transform::identity());
  s.addJoint("spine", 0, Transform::fromTranslation({0, 1, 0}));
  s.addJoint("chest", 1, Transform::fromTranslation({0, 1, 0}));
  int p = 2;
  for (int i = 0; i < 3; ++i) p = s.addJoint("l" + std::to_string(i), p, Transform::fromTranslation({0.8f, 0, 0}));
  p = 2;
  for (int i = 0; i < 3; ++i) p = s.addJoint("r" + std::to_string(i), p, Transform::fromTranslation({-0.8f, 0, 0}));
  return s;
}

// Signed angle of a rotation about +Z, and an angle wrapped into (-pi, pi].
inline float zAngle(const glm::quat& q) { return 2.0f * std::atan2(q.z, q.w); }
inline float wrap(float a) { return std::atan2(std::sin(a), std::cos(a)); }

inline glm::quat randomRotation(std::mt19937& rng, float maxAngle) {
  std::normal_distribution<float> g(0.0f, 1.0f);
  std::uniform_real_distribution<float> a(0.0f, maxAngle);
  glm::vec3 axis(g(rng), g(rng), g(rng));
  if (glm::length(axis) < 1e-6f) axis = glm::vec3(1.0f, 0.0f, 0.0f);
  return glm::angleAxis(a(rng), glm::normalize(axis));
}

inline Pose randomPose(const Skeleton& s, std::mt19937& rng, float maxAngle) {
  Pose p = Pose::rest(s);
  for (Transform& t : p.local) t.rotation = randomRotation(rng, maxAngle) * t.rotation;
  return p;
}

inline float chainLength(const Skeleton& s) {
  float l = 0.0f;
  for (int i = 1; i < s.size(); ++i) l += glm::length(s.rest[i].translation);
  return l;
}

inline glm::vec3 worldPosition(const Skeleton& s, const Pose& p, int joint) {
  return glm::vec3(computeWorld(s, p)[joint][3]);
}

// Largest relative change of any joint-to-parent distance between two poses.
inline float boneLengthChange(const Skeleton& s, const Pose& a, const Pose& b) {
  const std::vector<glm::mat4> wa = computeWorld(s, a), wb = computeWorld(s, b);
  float worst = 0.0f;
  for (int i = 0; i < s.size(); ++i) {
    if (s.parents[i] < 0) continue;
    const float la = glm::length(glm::vec3(wa[i][3] - wa[s.parents[i]][3]));
    const float lb = glm::length(glm::vec3(wb[i][3] - wb[s.parents[i]][3]));
    if (la > 0.0f) worst = std::max(worst, std::abs(la - lb) / la);
  }
  return worst;
}

}  // namespace kinema::test
