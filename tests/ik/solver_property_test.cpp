// Every iterative solver on random reachable targets (made by FK of random poses) on
// chains of 3, 10 and 30 joints: converges in >= 99 % of cases, keeps bone lengths and
// the IK root, and never produces NaN.
#include <gtest/gtest.h>

#include "ik/ik_solver.h"
#include "ik_test_chains.h"
#include "test_support.h"

namespace kinema {
namespace KINEMA_UNITY_ID {

struct Case {
  IkSolver solver;
  int joints;
  bool lineSearch = false;  // transpose: line search instead of Buss's step
};

class SolverProperty : public ::testing::TestWithParam<Case> {};

IkSettings settingsFor(IkSolver solver, float chain) {
  IkSettings s;
  s.tolerance = 1e-3f * chain;
  s.maxIterations = 1000;
  if (solver == IkSolver::JacobianTranspose) {
    // The transpose method crawls along badly conditioned directions: give it room
    // and do not let slow progress count as a stall.
    s.maxIterations = 20000;
    s.stallFraction = 0.0f;
  }
  return s;
}

TEST_P(SolverProperty, ReachesRandomReachableTargets) {
  const Case c = GetParam();
  std::mt19937 rng(1234 + c.joints);
  const Skeleton s = test::makeChain(c.joints, &rng);
  const float chain = test::chainLength(s);
  const int cases = test::propertyCases(c.joints == 30 ? 100 : 200);
  int converged = 0;
  float worstFailure = 0.0f;
  double iterationSum = 0.0;
  for (int k = 0; k < cases; ++k) {
    const Pose goal = test::randomPose(s, rng, 0.6f);
    const glm::vec3 target = test::worldPosition(s, goal, c.joints - 1);
    Pose pose = test::randomPose(s, rng, 0.6f);
    const Pose before = pose;
    IkProblem p;
    p.skeleton = &s;
    p.pose = &pose;
    p.targets.push_back({});
    p.targets[0].effector = c.joints - 1;
    p.targets[0].position = target;
    IkSettings settings = settingsFor(c.solver, chain);
    settings.transposeLineSearch = c.lineSearch;
    const IkResult r = solveIk(c.solver, p, settings);
    ASSERT_TRUE(r.message.empty()) << r.message;
    iterationSum += r.iterations;
    const float err = glm::length(test::worldPosition(s, pose, c.joints - 1) - target);
    ASSERT_TRUE(std::isfinite(err));
    EXPECT_NEAR(r.error, err, 1e-4f * chain) << "reported error matches the pose";
    if (r.converged) {
      ++converged;
      EXPECT_LE(err, settings.tolerance * 1.01f);
    } else {
      worstFailure = std::max(worstFailure, err);
    }
    EXPECT_LE(test::boneLengthChange(s, before, pose), 1e-5f);
    EXPECT_VEC3_NEAR(test::worldPosition(s, pose, 0), test::worldPosition(s, before, 0), 1e-6f);
    for (int i = 0; i < s.size(); ++i) EXPECT_EQ(pose.local[i].translation, before.local[i].translation);
  }
  EXPECT_GE(converged, (cases * 99 + 99) / 100)
      << toString(c.solver) << " on " << c.joints << " joints: " << converged << "/" << cases
      << " converged, worst miss " << worstFailure;
  std::printf("[ property ] %s%s %d joints: converged %d/%d, mean iterations %.1f\n", toString(c.solver),
              c.lineSearch ? " (line search)" : "", c.joints, converged, cases, iterationSum / cases);
}

std::vector<Case> allCases() {
  std::vector<Case> v;
  for (IkSolver s : {IkSolver::Ccd, IkSolver::Fabrik, IkSolver::JacobianTranspose, IkSolver::JacobianPinv,
                     IkSolver::JacobianDls, IkSolver::JacobianSdls})
    for (int n : {3, 10, 30}) v.push_back({s, n});
  for (int n : {3, 10, 30}) v.push_back({IkSolver::JacobianTranspose, n, true});
  return v;
}

INSTANTIATE_TEST_SUITE_P(AllSolvers, SolverProperty, ::testing::ValuesIn(allCases()),
                         [](const ::testing::TestParamInfo<Case>& info) {
                           std::string name = toString(info.param.solver);
                           for (char& ch : name)
                             if (ch == '-') ch = '_';
                           return name + (info.param.lineSearch ? "_line_search_" : "_") +
                                  std::to_string(info.param.joints);
                         });

}  // namespace
}  // namespace kinema
