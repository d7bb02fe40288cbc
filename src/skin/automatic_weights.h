#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include "core/math.h"
#include "core/skeleton.h"

namespace kinema {

enum class AutomaticWeightsMethod {
  // Seed 001: each bone a capsule of radius r; w = max(0, r - d) / r, normalised, with d
  // measured as the vertex's distance to the bone minus its distance to the nearest bone
  // (so the nearest bone always weighs most and no vertex is left unweighted; why in
  // automatic_weights.cpp). A bone blends in only where it is within r of being nearest.
  Capsule,
  // w = 1 / d^power to every bone segment, keeping the largest, normalised.
  InverseDistance,
  // Rigid binding: weight 1 on the nearest bone.
  Nearest,
};

// Binds vertices to a skeleton without painting. A "bone" is the segment from a joint to
// one of its children and belongs to the parent joint (rotating that joint moves it);
// a joint without children is a point. Output is MeshPrimitive's influence layout:
// kMaxInfluences entries per vertex, largest first, zero padded, at most maxInfluences
// non-zero, summing to 1; every vertex gets at least one influence. Joint numbers are
// skeleton joint indices (a skin listing every joint in order, so they equal skin indices).
struct AutomaticWeightsJob {
  const Skeleton* skeleton = nullptr;
  const std::vector<glm::mat4>* bindWorld = nullptr;  // world transform per joint at bind time
  const std::vector<glm::vec3>* positions = nullptr;  // bind-pose vertices, same space as bindWorld
  AutomaticWeightsMethod method = AutomaticWeightsMethod::Capsule;
  // Capsule radius of each joint's bones (one per joint), or empty: then each bone's radius
  // is capsuleRadiusScale times its length, so long limbs reach as far as thick ones.
  std::vector<float> capsuleRadius;
  float capsuleRadiusScale = 0.35f;
  float inverseDistancePower = 4.0f;
  int maxInfluences = 4;  // 1..kMaxInfluences
  std::vector<uint16_t>* outJoints = nullptr;
  std::vector<float>* outWeights = nullptr;

  std::string validate() const;
  bool run() const;
};

}  // namespace kinema
