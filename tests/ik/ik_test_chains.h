#pragma once
// Chains and random poses shared by the IK tests.
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
