// Teaching mode's model: what CCD and FABRIK do step by step on the seed's 3-bone chain
// (seed 002), and the comparison's cursors.
#include <gtest/gtest.h>

#include <cmath>

#include "ik/solver_comparison.h"
#include "test_support.h"

namespace kinema {
namespace KINEMA_UNITY_ID {

const TeachingCase& preset(const char* name) {
  const TeachingCase* c = findTeachingPreset(name);
  EXPECT_NE(c, nullptr) << name;
  return *c;
}

const SolverRun& runOf(const SolverComparison& c, IkSolver s) {
  for (const SolverRun& r : c.runs)
    if (r.solver == s) return r;
  ADD_FAILURE() << "no run of " << toString(s);
  return c.runs.front();
}

float boneLength(const IkTraceEntry& e, int bone) { return glm::length(e.positions[bone + 1] - e.positions[bone]); }

TEST(TeachingPresets, TheIssuesPresetsExistAreValidAndSolve) {
  for (const char* name : {"ccd-steps", "fabrik-steps", "two-bone-unreachable", "two-bone-two-solutions", "unreachable",
                           "near-root", "long-chain", "hinge-limits"}) {
    const TeachingCase* c = findTeachingPreset(name);
    ASSERT_NE(c, nullptr) << name;
    EXPECT_EQ(c->validate(), "") << name;
    SolverComparison cmp;
    ASSERT_EQ(startComparison(*c, cmp, 1), "") << name;
    ASSERT_EQ(cmp.runs.size(), c->solvers.size());
    for (const SolverRun& r : cmp.runs) {
      ASSERT_FALSE(r.trace.entries.empty()) << name;
      EXPECT_EQ(r.trace.entries[0].step, IkStep::Start);
      EXPECT_EQ(r.cursor, 0);
      EXPECT_GE(r.totalMilliseconds, 0.0);
    }
  }
  EXPECT_EQ(findTeachingPreset("no-such-case"), nullptr);
  EXPECT_EQ(preset("long-chain").chain.boneLengths.size(), 20u);  // 20 rotating joints + the effector
  // Unreachable by construction: the target lies beyond the sum of the bone lengths.
  const TeachingCase& far = preset("unreachable");
  EXPECT_GT(glm::length(far.target - far.chain.base), far.chain.reach());
}

TEST(TeachingSkeleton, RestPoseIsTheBentStartAndHingeLimitsAreRelativeToTheParentBone) {
  TeachingChain chain;
  chain.boneLengths = {1.0f, 2.0f};
  chain.startAngles = {glm::half_pi<float>(), -glm::half_pi<float>()};
  chain.limits.resize(3);
  chain.limits[1] = JointLimit::hinge({0, 0, 1}, -1.0f, 0.5f);
  const TeachingSkeleton s = makeTeachingSkeleton(chain);
  ASSERT_EQ(s.skeleton.size(), 3);
  // Up 1 along +Y, then turned back to +X: the effector at (2, 1) by hand.
  glm::vec3 p(0.0f);
  glm::quat r(1, 0, 0, 0);
  for (int j = 0; j < 3; ++j) {
    p += r * s.start.local[j].translation;
    r = r * s.start.local[j].rotation;
  }
  EXPECT_VEC3_NEAR(p, glm::vec3(2.0f, 1.0f, 0.0f), 1e-5f);
  // Joint 1 starts at -pi/2 from its parent bone; the rig's limit is relative to that rest.
  EXPECT_NEAR(s.rig.limits[1].minAngle, -1.0f + glm::half_pi<float>(), 1e-6f);
  EXPECT_NEAR(s.rig.limits[1].maxAngle, 0.5f + glm::half_pi<float>(), 1e-6f);
}

// Seed 002, CCD figure (a)-(d): the joint before the effector turns first, then the one
// before it, then the root; each turn leaves joint, effector and target on one line.
TEST(CcdSteps, VisitsJointsLastFirstAndMakesJointEffectorTargetCollinear) {
  SolverComparison cmp;
  ASSERT_EQ(startComparison(preset("ccd-steps"), cmp, 1), "");
  const SolverRun& ccd = runOf(cmp, IkSolver::Ccd);
  ASSERT_TRUE(cmp.setup.chain.limits.empty());  // the unclamped case
  const glm::vec3 target = cmp.setup.target;
  ASSERT_EQ(ccd.trace.joints, (std::vector<int>{0, 1, 2, 3}));
  int steps = 0;
  for (size_t k = 1; k < ccd.trace.entries.size(); ++k) {
    const IkTraceEntry& e = ccd.trace.entries[k];
    if (e.step != IkStep::CcdJoint) continue;
    // Sub-step n of an iteration turns joint 2, 1, 0 (the effector is joint 3).
    const int expected = 2 - static_cast<int>((k - 1) % 3);
    EXPECT_EQ(e.joint, expected) << "entry " << k;
    EXPECT_EQ(e.iteration, static_cast<int>((k - 1) / 3) + 1) << "entry " << k;
    const glm::vec3 toEffector = e.positions[3] - e.positions[e.joint], toTarget = target - e.positions[e.joint];
    const float sine = glm::length(glm::cross(toEffector, toTarget)) / (glm::length(toEffector) * glm::length(toTarget));
    EXPECT_LT(sine, 1e-4f) << "entry " << k;
    EXPECT_GT(glm::dot(toEffector, toTarget), 0.0f) << "entry " << k;  // same side: pointing at the target
    // Only the turned joint's descendants moved.
    for (int j = 0; j <= e.joint; ++j)
      EXPECT_VEC3_NEAR(e.positions[j], ccd.trace.entries[k - 1].positions[j], 1e-6f);
    ++steps;
  }
  EXPECT_GE(steps, 6);  // at least two sweeps on this case
  EXPECT_TRUE(ccd.result.converged);
}

// Seed 002, FABRIK figure (a)-(f): backward from the target (the root leaves its base),
// forward from the base (the root goes back); bone lengths never change.
TEST(FabrikSteps, BackwardPassMovesTheRootOffItsBaseForwardPassRestoresIt) {
  SolverComparison cmp;
  ASSERT_EQ(startComparison(preset("fabrik-steps"), cmp, 1), "");
  const SolverRun& fabrik = runOf(cmp, IkSolver::Fabrik);
  const std::vector<float>& lengths = cmp.setup.chain.boneLengths;
  const glm::vec3 base = cmp.setup.chain.base, target = cmp.setup.target;
  int backward = 0, forward = 0;
  for (size_t k = 1; k < fabrik.trace.entries.size(); ++k) {
    const IkTraceEntry& e = fabrik.trace.entries[k];
    ASSERT_TRUE(e.step == IkStep::FabrikBackward || e.step == IkStep::FabrikForward) << toString(e.step);
    // Passes alternate, backward first.
    EXPECT_EQ(e.step, k % 2 == 1 ? IkStep::FabrikBackward : IkStep::FabrikForward) << "entry " << k;
    for (int b = 0; b < 3; ++b) EXPECT_NEAR(boneLength(e, b), lengths[b], 1e-5f) << "entry " << k << " bone " << b;
    if (e.step == IkStep::FabrikBackward) {
      ++backward;
      EXPECT_VEC3_NEAR(e.positions[3], target, 1e-5f);
      EXPECT_GT(glm::length(e.positions[0] - base), 1e-4f) << "entry " << k << ": root still on its base";
    } else {
      ++forward;
      EXPECT_VEC3_NEAR(e.positions[0], base, 1e-5f);
    }
  }
  EXPECT_GE(backward, 2);
  EXPECT_EQ(backward, forward);
  EXPECT_TRUE(fabrik.result.converged);
}

TEST(SolverComparison, SubStepIterationStepAndConvergenceFollowTheTrace) {
  SolverComparison cmp;
  ASSERT_EQ(startComparison(preset("ccd-steps"), cmp, 1), "");
  const SolverRun& ccd = runOf(cmp, IkSolver::Ccd);
  const SolverRun& fabrik = runOf(cmp, IkSolver::Fabrik);
  EXPECT_EQ(ccd.previous(), nullptr);
  stepSubStep(cmp);
  EXPECT_EQ(ccd.cursor, 1);
  EXPECT_EQ(fabrik.cursor, 1);
  EXPECT_EQ(ccd.previous(), &ccd.trace.entries[0]);
  // From a sub-step inside iteration 1 to the end of iteration 1 (CCD has 3 sub-steps per
  // sweep: entries 1..3, FABRIK 2 passes: entries 1..2), then to the end of iteration 2
  // (entries 4..6 and 3..4).
  stepIteration(cmp);
  EXPECT_EQ(ccd.cursor, 3);
  EXPECT_EQ(fabrik.cursor, 2);
  stepIteration(cmp);
  EXPECT_EQ(ccd.cursor, 6);
  EXPECT_EQ(fabrik.cursor, 4);
  resetCursors(cmp);
  stepIteration(cmp);
  EXPECT_EQ(ccd.cursor, 3);
  EXPECT_EQ(fabrik.cursor, 2);
  runToEnd(cmp);
  EXPECT_TRUE(ccd.finished());
  EXPECT_TRUE(fabrik.finished());
  const int end = ccd.cursor;
  stepSubStep(cmp);
  EXPECT_EQ(ccd.cursor, end);  // nothing past the end

  // Convergence: the error after each whole iteration, read off the trace by index.
  const std::vector<float> conv = ccd.convergence();
  ASSERT_EQ(static_cast<int>(conv.size()), ccd.result.iterations + 1);
  for (int i = 0; i <= ccd.result.iterations; ++i) EXPECT_EQ(conv[i], ccd.trace.entries[3 * i].error) << i;
  const std::vector<float> fc = fabrik.convergence();
  ASSERT_EQ(static_cast<int>(fc.size()), fabrik.result.iterations + 1);
  for (int i = 0; i <= fabrik.result.iterations; ++i) EXPECT_EQ(fc[i], fabrik.trace.entries[2 * i].error) << i;
  EXPECT_EQ(conv.back(), ccd.result.error);

  // A new target: both solved again, cursors back at the start.
  stepIteration(cmp);
  const glm::vec3 moved(-0.8f, 1.2f, 0.0f);
  ASSERT_EQ(setTarget(cmp, moved), "");
  EXPECT_VEC3_NEAR(cmp.setup.target, moved, 0.0f);
  for (const SolverRun& r : cmp.runs) {
    EXPECT_EQ(r.cursor, 0);
    EXPECT_TRUE(r.result.converged);
    EXPECT_LT(glm::length(r.trace.entries.back().positions.back() - moved), 1.001e-3f);
  }
}

// The step-by-step replay reveals the convergence only as far as the cursor: at every
// cursor the revealed errors are the whole run's for the iterations finished before the
// cursor's iteration, and the cursor's own error for that iteration; never a later one.
TEST(SolverComparison, ConvergenceIsRevealedUpToTheCursor) {
  SolverComparison cmp;
  ASSERT_EQ(startComparison(preset("ccd-steps"), cmp, 1), "");
  for (SolverRun& run : cmp.runs) {
    const std::vector<float> all = run.convergence();
    ASSERT_GE(all.size(), 3u) << toString(run.solver);
    for (int k = 0; k < static_cast<int>(run.trace.entries.size()); ++k) {
      run.cursor = k;
      const std::vector<float> so = run.convergenceSoFar();
      const int it = run.trace.entries[k].iteration;
      ASSERT_EQ(static_cast<int>(so.size()), it + 1) << toString(run.solver) << " cursor " << k;
      for (int i = 0; i < it; ++i) EXPECT_EQ(so[i], all[i]) << toString(run.solver) << " cursor " << k;
      EXPECT_EQ(so.back(), run.trace.entries[k].error) << toString(run.solver) << " cursor " << k;
    }
    EXPECT_EQ(run.convergenceSoFar(), all) << "at the end the whole curve";
    run.cursor = 0;
    EXPECT_EQ(run.convergenceSoFar().size(), 1u) << "at the start the start point alone";
  }
}

// Every preset starts with the target well away from the effector (a target on the
// effector hides the target's circle and gives the solvers nothing to show).
TEST(TeachingPresets, EveryTargetStartsAwayFromTheEffector) {
  for (const TeachingCase& c : teachingPresets()) {
    SolverComparison cmp;
    ASSERT_EQ(startComparison(c, cmp, 1), "") << c.name;
    const glm::vec3 effector = cmp.runs[0].trace.entries[0].positions.back();
    // The effector by hand: the bones' directions are the running sums of the start angles.
    glm::vec3 p = c.chain.base;
    float angle = 0.0f;
    for (size_t b = 0; b < c.chain.boneLengths.size(); ++b) {
      angle += c.chain.startAngles[b];
      p += c.chain.boneLengths[b] * glm::vec3(std::cos(angle), std::sin(angle), 0.0f);
    }
    EXPECT_VEC3_NEAR(effector, p, 1e-4f);
    EXPECT_GE(glm::length(cmp.setup.target - p), 0.2f * c.chain.reach()) << c.name;
  }
}

TEST(SolverComparison, InvalidCasesAreRefusedWithOneLine) {
  TeachingCase c = preset("ccd-steps");
  c.chain.boneLengths[1] = 0.0f;
  SolverComparison cmp;
  const std::string bad = startComparison(c, cmp, 1);
  EXPECT_NE(bad.find("length"), std::string::npos) << bad;
  EXPECT_EQ(bad.find('\n'), std::string::npos);
  c = preset("ccd-steps");
  c.solvers = {IkSolver::TwoBone};
  EXPECT_NE(startComparison(c, cmp, 1), "");
}

}  // namespace
}  // namespace kinema
