#pragma once
// Analytic two-bone IK as an ozz-style job: model-space inputs of three joints (start,
// mid, end), local rotation corrections out. No skeleton, no allocation; solveTwoBone
// computes the inputs from a pose and applies the corrections.
#include <string>

#include "core/transform.h"

namespace kinema {

struct TwoBoneIkJob {
  // Inputs, all in model space. Rotations are unit; joints between start and mid (or mid
  // and end) may exist, they only have to stay rigid.
  glm::vec3 startPosition{0.0f};
  glm::quat startRotation{1.0f, 0.0f, 0.0f, 0.0f};
  glm::vec3 midPosition{0.0f};
  glm::quat midRotation{1.0f, 0.0f, 0.0f, 0.0f};
  glm::vec3 endPosition{0.0f};
  glm::vec3 target{0.0f};
  // The side the mid joint bends to, a direction from the start joint (its part along
  // start->target is ignored). Zero or parallel to start->target: the side the mid joint
  // is on now. The bend axis follows from it, so none is asked for.
  glm::vec3 pole{0.0f};
  float twistAngle = 0.0f;  // turns the bend plane about start->target (radians, right hand)
  // Share of the full correction applied, 0..1: slerp from identity.
  float weight = 1.0f;
  // Soft IK, 0..1: share of the reach (|start-mid| + |mid-end|) near full extension over
  // which the end approaches the target exponentially, so it never snaps straight; 0: off.
  float soften = 0.0f;

  // Outputs: multiply onto the joints' local rotations, local = local * correction.
  glm::quat* startCorrection = nullptr;
  glm::quat* midCorrection = nullptr;
  bool* reached = nullptr;  // optional: the target is within reach and softening left it alone
  // Optional: the same corrections as model-space turns (start joint about its position;
  // mid joint about its own, before the start's turn), D = R * correction * R^-1.
  glm::quat* startTurn = nullptr;
  glm::quat* midTurn = nullptr;

  // Empty when the inputs are usable; otherwise what is wrong with them.
  std::string validate() const;
  // Runs the job; returns false (and writes nothing) when validate() fails.
  bool run() const;
  // run() without validate(), for callers that have checked their inputs once.
  void runUnchecked() const;
};

}  // namespace kinema
