#pragma once
#include <optional>
#include <string>
#include <vector>

#include "core/pose.h"
#include "ik/ik_rig.h"
#include "ik/ik_solver_kind.h"
#include "ik/ik_target.h"
#include "ik/ik_trace.h"

namespace kinema {


struct IkSettings {
  float tolerance = 1e-3f;  // converged when every effector is this close (file units)
  int maxIterations = 100;
  // Stop early when the error has improved by less than this fraction over the last
  // `stallWindow` iterations (0 disables).
  float stallFraction = 1e-4f;
  int stallWindow = 8;
  // CCD damping and Jacobian step clamp: the most a joint turns in one step (radians).
  float maxStepAngle = glm::pi<float>();
  float dlsLambda = 0.1f;         // DLS damping as a fraction of the chain's reach
  float pinvThreshold = 1e-4f;     // singular values below this (relative) are dropped
  // Jacobian transpose: search the step length on the true error (backtracking from
  // Buss's step, expanding while it pays) instead of taking Buss's step as it is.
  bool transposeLineSearch = false;
  // FABRIK with limits or several effectors: after at most this many passes (fewer once a
  // pass gains < 20 %), finish with damped least squares steps (see fabrik.cpp); 0 = FABRIK
  // passes only, however slow.
  int fabrikFinishAfter = 10;
  float twoBoneSoften = 0.0f;      // two-bone: soften distance near full extension
  IkTrace* trace = nullptr;        // records every step when set; nullptr costs nothing
};

struct IkResult {
  bool converged = false;  // every effector within tolerance (two-bone: target reached)
  int iterations = 0;      // CCD sweeps, FABRIK backward+forward pairs, Jacobian steps
  float error = 0.0f;      // largest effector distance to its target at the end
  std::string message;     // why it failed validation (then nothing was changed)
};

// Inputs of every solver: the skeleton, the pose it edits in place (only local
// rotations of chain joints change), the placement of the skeleton, limits and targets.
struct IkProblem {
  const Skeleton* skeleton = nullptr;
  Pose* pose = nullptr;
  const IkRig* rig = nullptr;  // limits (may be null: no limits)
  std::vector<IkTarget> targets;
  glm::mat4 rootTransform{1.0f};

  // Empty when the inputs are usable; otherwise what is wrong with them.
  std::string validate(bool twoBone = false) const;
};

IkResult solveTwoBone(const IkProblem& problem, const IkSettings& settings);
IkResult solveCcd(const IkProblem& problem, const IkSettings& settings);
IkResult solveFabrik(const IkProblem& problem, const IkSettings& settings);
IkResult solveJacobianTranspose(const IkProblem& problem, const IkSettings& settings);
IkResult solveJacobianPinv(const IkProblem& problem, const IkSettings& settings);
IkResult solveJacobianDls(const IkProblem& problem, const IkSettings& settings);
// Selectively damped least squares (Buss & Kim 2005): per singular direction damping.
IkResult solveJacobianSdls(const IkProblem& problem, const IkSettings& settings);
IkResult solveIk(IkSolver solver, const IkProblem& problem, const IkSettings& settings);

}  // namespace kinema
