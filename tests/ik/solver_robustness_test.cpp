// Unreachable and degenerate targets, several effectors, limits and tracing.
#include <gtest/gtest.h>

#include "ik/ik_solver.h"
#include "ik_test_chains.h"
#include "test_support.h"

namespace kinema {
namespace KINEMA_UNITY_ID {

const IkSolver kIterative[] = {IkSolver::Ccd, IkSolver::Fabrik, IkSolver::JacobianTranspose, IkSolver::JacobianPinv,
                               IkSolver::JacobianDls, IkSolver::JacobianSdls};

IkProblem problemFor(const Skeleton& s, Pose& pose, int effector, const glm::vec3& target) {
  IkProblem p;
  p.skeleton = &s;
  p.pose = &pose;
  p.targets.push_back({});
  p.targets[0].effector = effector;
  p.targets[0].position = target;
  return p;
}

TEST(IkSolvers, UnreachableTargetsStraightenTheChainTowardsThem) {
  std::mt19937 rng(7);
  const Skeleton s = test::makeChain(10, &rng);
  const float chain = test::chainLength(s);
  for (IkSolver solver : kIterative) {
    for (int k = 0; k < 20; ++k) {
      Pose pose = test::randomPose(s, rng, 0.6f);
      const glm::vec3 dir = glm::normalize(test::randomRotation(rng, 3.14f) * glm::vec3(0, 1, 0));
      const glm::vec3 target = dir * chain * 1.5f;
      IkProblem p = problemFor(s, pose, 9, target);
      const IkResult r = solveIk(solver, p, IkSettings{});
      EXPECT_FALSE(r.converged);
      const std::vector<glm::mat4> w = computeWorld(s, pose);
      for (int i = 1; i < s.size(); ++i) {
        const glm::vec3 bone = glm::normalize(glm::vec3(w[i][3] - w[i - 1][3]));
        const float angle = std::atan2(glm::length(glm::cross(bone, dir)), glm::dot(bone, dir));
        EXPECT_LT(angle, 1e-3f) << toString(solver) << " bone " << i;
      }
      EXPECT_NEAR(r.error, chain * 0.5f, 1e-4f * chain);
    }
  }
}

// Random targets including degenerate ones; never a NaN, never a crash. The case count
// comes from KINEMA_PROPERTY_CASES (100,000 here by default, fewer in CI).
TEST(IkSolvers, NoNanOverRandomAndDegenerateTargets) {
  const int cases = test::propertyCases(100000);
  std::mt19937 rng(99);
  std::uniform_real_distribution<float> u(-6.0f, 6.0f);
  const IkSolver all[] = {IkSolver::TwoBone, IkSolver::Ccd, IkSolver::Fabrik, IkSolver::JacobianTranspose,
                          IkSolver::JacobianPinv, IkSolver::JacobianDls, IkSolver::JacobianSdls};
  const float nan = std::numeric_limits<float>::quiet_NaN(), inf = std::numeric_limits<float>::infinity();
  for (int k = 0; k < cases; ++k) {
    Skeleton s = test::makeChain(4, &rng);
    if (k % 5 == 0) s.rest[1 + k % 3].translation = glm::vec3(0.0f);  // a zero-length bone
    Pose pose = k % 3 == 0 ? Pose::rest(s) : test::randomPose(s, rng, 1.5f);  // rest = collinear
    glm::vec3 target(u(rng), u(rng), u(rng));
    if (k % 7 == 0) target = test::worldPosition(s, pose, k % 4);  // exactly at a joint
    if (k % 13 == 0) target = glm::vec3(1e15f, -1e15f, 1e15f);
    const bool bad = k % 11 == 0;
    if (bad) target[k % 3] = (k % 2) ? nan : inf;
    const Pose before = pose;
    IkProblem p = problemFor(s, pose, 3, target);
    IkSettings settings;
    settings.maxIterations = 10;
    const IkSolver solver = all[k % 7];
    const IkResult r = solveIk(solver, p, settings);
    if (bad) {
      ASSERT_FALSE(r.message.empty());
      for (int i = 0; i < s.size(); ++i) ASSERT_EQ(pose.local[i], before.local[i]);
      continue;
    }
    ASSERT_TRUE(r.message.empty()) << r.message;
    for (int i = 0; i < s.size(); ++i)
      ASSERT_TRUE(pose.local[i].isFinite()) << toString(solver) << " case " << k << " joint " << i;
    ASSERT_TRUE(std::isfinite(r.error)) << toString(solver) << " case " << k;
  }
}

using test::twoArms;

TEST(IkSolvers, TwoHandsReachTwoTargetsWithASharedSpine) {
  const Skeleton s = twoArms();
  const int cases = test::propertyCases(100);
  for (IkSolver solver : {IkSolver::Fabrik, IkSolver::JacobianDls, IkSolver::JacobianPinv, IkSolver::JacobianSdls,
                          IkSolver::Ccd}) {
    std::mt19937 rng(5);
    int converged = 0;
    for (int k = 0; k < cases; ++k) {
      const Pose goal = test::randomPose(s, rng, 0.5f);
      Pose pose = test::randomPose(s, rng, 0.3f);
      const Pose before = pose;
      IkProblem p = problemFor(s, pose, 5, test::worldPosition(s, goal, 5));
      p.targets.push_back({});
      p.targets[1].effector = 8;
      p.targets[1].position = test::worldPosition(s, goal, 8);
      // The default settings (cap of 100 iterations, stall stop on) but for the
      // tolerance; CCD, which needs far more sweeps for two hands, gets 500.
      IkSettings settings;
      settings.tolerance = 1e-3f * 4.4f;
      if (solver == IkSolver::Ccd) {
        settings.maxIterations = 500;
        settings.stallFraction = 0.0f;
      }
      const IkResult r = solveIk(solver, p, settings);
      ASSERT_TRUE(r.message.empty()) << r.message;
      for (int i = 0; i < s.size(); ++i) ASSERT_TRUE(pose.local[i].isFinite()) << toString(solver) << " joint " << i;
      const float e1 = glm::length(test::worldPosition(s, pose, 5) - p.targets[0].position);
      const float e2 = glm::length(test::worldPosition(s, pose, 8) - p.targets[1].position);
      ASSERT_TRUE(std::isfinite(e1) && std::isfinite(e2));
      EXPECT_NEAR(r.error, std::max(e1, e2), 1e-4f) << toString(solver);
      if (r.converged) {
        ++converged;
        EXPECT_LE(std::max(e1, e2), settings.tolerance * 1.01f);
      }
      EXPECT_LE(test::boneLengthChange(s, before, pose), 1e-5f) << toString(solver);
      EXPECT_VEC3_NEAR(test::worldPosition(s, pose, 0), test::worldPosition(s, before, 0), 1e-6f);
      for (int i = 0; i < s.size(); ++i) EXPECT_EQ(pose.local[i].translation, before.local[i].translation);
    }
    // The targets come from one pose of the whole rig, so both are reachable at once.
    // FABRIK fits the rigid chest to both arms in its backward pass and finishes with
    // DLS steps after 10 passes; with passes alone it reached 94.3 % within 100 (and only
    // 51 % within 500 with the paper's plain centroid of per-arm proposals for the chest).
    EXPECT_GE(converged, (cases * 99 + 99) / 100) << toString(solver) << ": " << converged << "/" << cases;
    std::printf("[ two hands ] %-14s converged %d/%d\n", toString(solver), converged, cases);
  }
}

// Two hands with limits on every joint of the rig, the chest (a sub-base with two arms)
// included: limits hold at the end for every solver, and FABRIK, which applies the chest's
// and the shoulders' limits in its backward pass too, converges within the default cap.
TEST(IkSolvers, TwoHandsWithLimitsOnTheSharedSpine) {
  const Skeleton s = twoArms();
  IkRig rig;
  const int n = s.size();
  rig.setLimit(n, 1, JointLimit::cone({0, 1, 0}, 0.4f, -0.3f, 0.3f));  // spine
  rig.setLimit(n, 2, JointLimit::euler(EulerOrder::XYZ, glm::vec3(-0.3f), glm::vec3(0.3f)));  // chest
  for (int side = 0; side < 2; ++side) {
    const int a = 3 + 3 * side;
    const float x = side == 0 ? 1.0f : -1.0f;
    rig.setLimit(n, a, JointLimit::cone({x, 0, 0}, 0.8f, -0.5f, 0.5f));  // shoulder
    rig.setLimit(n, a + 1, JointLimit::hinge({0, 0, 1}, -1.5f, 1.5f));    // elbow
    rig.setLimit(n, a + 2, JointLimit::cone({x, 0, 0}, 0.6f, -0.3f, 0.3f));  // wrist
  }
  const int cases = test::propertyCases(200);
  for (IkSolver solver : kIterative) {
    for (int finishAfter : {10, 0}) {  // 0: FABRIK's passes alone, for the record
      if (finishAfter == 0 && solver != IkSolver::Fabrik) continue;
      std::mt19937 rng(23);
      int converged = 0;
      for (int k = 0; k < cases; ++k) {
        Pose goal = test::randomPose(s, rng, 0.8f);
        for (int i = 0; i < n; ++i)
          goal.local[i].rotation = applyJointLimit(rig.limits[i], s.rest[i].rotation, goal.local[i].rotation);
        Pose pose = Pose::rest(s);
        IkProblem p = problemFor(s, pose, 5, test::worldPosition(s, goal, 5));
        p.targets.push_back({});
        p.targets[1].effector = 8;
        p.targets[1].position = test::worldPosition(s, goal, 8);
        p.rig = &rig;
        IkSettings settings;
        settings.tolerance = 1e-3f * 4.4f;
        settings.fabrikFinishAfter = finishAfter;
        if (finishAfter == 0) settings.maxIterations = 500;
        if (solver == IkSolver::Ccd || solver == IkSolver::JacobianTranspose) settings.maxIterations = 2000;
        const IkResult r = solveIk(solver, p, settings);
        ASSERT_TRUE(r.message.empty()) << r.message;
        converged += r.converged;
        for (int i = 0; i < n; ++i)
          EXPECT_LE(jointLimitViolation(rig.limits[i], s.rest[i].rotation, pose.local[i].rotation), 1e-3f)
              << toString(solver) << " joint " << i;
      }
      std::printf("[ limited hands ] %-20s %s converged %d/%d\n", toString(solver),
                  finishAfter ? "" : "(passes only, cap 500)", converged, cases);
      if (finishAfter == 0) continue;
      // CCD (98 % measured) and the transpose (35 %, with or without line search) stall
      // against the limits of this rig; the bars below only catch them getting worse.
      const int percent = solver == IkSolver::Ccd ? 90 : solver == IkSolver::JacobianTranspose ? 30 : 99;
      EXPECT_GE(converged, (cases * percent + 99) / 100) << toString(solver) << ": " << converged << "/" << cases;
    }
  }
}

// FABRIK's rigid sub-base fit on degenerate input: shoulders on top of the chest (zero
// offsets, so the fit sees only the chest itself), with reachable targets (both must
// converge), a target on the chest, or one far away (finite, bones kept).
TEST(IkSolvers, FabrikSubBaseFitHandlesDegenerateRigs) {
  Skeleton s = twoArms();
  s.rest[3].translation = glm::vec3(0.0f);
  s.rest[6].translation = glm::vec3(0.0f);
  std::mt19937 rng(17);
  int reachable = 0, converged = 0;
  for (int k = 0; k < 300; ++k) {
    Pose pose = k % 2 ? Pose::rest(s) : test::randomPose(s, rng, 1.0f);
    const Pose before = pose;
    const Pose goal = test::randomPose(s, rng, 0.5f);
    const glm::vec3 a = test::worldPosition(s, goal, 5);
    glm::vec3 b = test::worldPosition(s, goal, 8);                             // reachable
    if (k % 3 == 1) b = test::worldPosition(s, pose, 2);                        // at the chest
    if (k % 3 == 2) b = test::worldPosition(s, test::randomPose(s, rng, 1.0f), 8) * 100.0f;  // far away
    IkProblem p = problemFor(s, pose, 5, a);
    p.targets.push_back({});
    p.targets[1].effector = 8;
    p.targets[1].position = b;
    IkSettings settings;
    settings.tolerance = 1e-3f * 4.4f;
    settings.maxIterations = 500;
    settings.stallFraction = 0.0f;
    const IkResult r = solveFabrik(p, settings);
    if (k % 3 == 0) {
      ++reachable;
      converged += r.converged;
    }
    ASSERT_TRUE(r.message.empty()) << r.message;
    ASSERT_TRUE(std::isfinite(r.error)) << "case " << k;
    for (int i = 0; i < s.size(); ++i) ASSERT_TRUE(pose.local[i].isFinite()) << "case " << k << " joint " << i;
    EXPECT_LE(test::boneLengthChange(s, before, pose), 1e-5f) << "case " << k;
  }
  EXPECT_GE(converged, reachable * 99 / 100) << converged << "/" << reachable;
  std::printf("[ zero shoulders ] fabrik converged %d/%d\n", converged, reachable);
}

// Limits of one kind on every joint, then the three kinds mixed along the chain.
JointLimit limitFor(int kind, int joint) {
  const int k = kind != 0 ? kind : joint % 3 == 0 ? 3 : joint % 3;  // mixed: cone, hinge, Euler, cone, ...
  return k == 1   ? JointLimit::hinge({0, 0, 1}, -1.0f, 1.0f)
         : k == 2 ? JointLimit::euler(EulerOrder::XYZ, glm::vec3(-0.5f), glm::vec3(0.5f))
                  : JointLimit::cone({0, 1, 0}, 0.6f, -0.3f, 0.3f);
}

TEST(IkSolvers, EverySolverHonoursJointLimits) {
  const char* kindName[] = {"mixed", "hinge", "euler", "cone"};
  const int cases = test::propertyCases(200);
  for (int kind = 0; kind < 4; ++kind) {
    std::mt19937 rng(11);
    const Skeleton s = test::makeChain(10, &rng);
    IkRig rig;
    for (int i = 0; i < s.size(); ++i) rig.setLimit(s.size(), i, limitFor(kind, i));
    const float chain = test::chainLength(s);
    for (IkSolver solver : kIterative) {
     for (int passesOnly = 0; passesOnly < (solver == IkSolver::Fabrik ? 2 : 1); ++passesOnly) {
      std::mt19937 targets(11 + kind);
      int converged = 0;
      for (int k = 0; k < cases; ++k) {
        // Targets made by FK of a random pose that respects the limits: reachable.
        Pose goal = test::randomPose(s, targets, 0.8f);
        for (int i = 0; i < s.size(); ++i)
          goal.local[i].rotation = applyJointLimit(rig.limits[i], s.rest[i].rotation, goal.local[i].rotation);
        Pose pose = Pose::rest(s);  // every case starts from the straight rest chain
        IkProblem p = problemFor(s, pose, 9, test::worldPosition(s, goal, 9));
        p.rig = &rig;
        IkSettings settings;
        settings.tolerance = 1e-3f * chain;
        settings.maxIterations = solver == IkSolver::JacobianTranspose ? 5000 : 500;
        if (passesOnly) settings.fabrikFinishAfter = 0;  // for the record: FABRIK without its DLS finish
        const IkResult r = solveIk(solver, p, settings);
        converged += r.converged;
        for (int i = 0; i < s.size(); ++i)
          EXPECT_LE(jointLimitViolation(rig.limits[i], s.rest[i].rotation, pose.local[i].rotation), 1e-3f)
              << toString(solver) << " joint " << i;
      }
      std::printf("[ limits ] %-6s %-20s converged %d/%d%s\n", kindName[kind], toString(solver), converged, cases,
                  passesOnly ? " (passes only)" : "");
      if (passesOnly) continue;
      // The bar is 99 %. FABRIK reaches it with its DLS finish (passes alone, 1000
      // cases: 86 % with the three kinds mixed, 80.5 % before the hinge twist). Known short
      // of it (1000 cases, see the README): CCD (95-99.7 %) and the Jacobian transpose
      // (92.6-97.8 %), which stall against limits.
      int percent = 99;
      if (solver == IkSolver::Ccd || solver == IkSolver::JacobianTranspose) percent = 85;
      EXPECT_GE(converged, (cases * percent + 99) / 100)
          << kindName[kind] << " limits: " << toString(solver) << " converged " << converged << "/" << cases;
     }
    }
  }
}

TEST(IkSolvers, TraceRecordsEveryStepAndChangesNothing) {
  std::mt19937 rng(3);
  const Skeleton s = test::makeChain(5, &rng);
  const Pose start = test::randomPose(s, rng, 0.5f);
  const glm::vec3 target = test::worldPosition(s, test::randomPose(s, rng, 0.5f), 4);
  for (IkSolver solver : kIterative) {
    Pose a = start, b = start;
    IkProblem pa = problemFor(s, a, 4, target), pb = problemFor(s, b, 4, target);
    IkTrace trace;
    IkSettings traced;
    traced.trace = &trace;
    const IkResult ra = solveIk(solver, pa, IkSettings{});
    const IkResult rb = solveIk(solver, pb, traced);
    EXPECT_EQ(ra.iterations, rb.iterations);
    for (int i = 0; i < s.size(); ++i) EXPECT_EQ(a.local[i], b.local[i]) << toString(solver);
    ASSERT_EQ(trace.joints, (std::vector<int>{0, 1, 2, 3, 4}));
    ASSERT_FALSE(trace.entries.empty());
    EXPECT_EQ(trace.entries.front().step, IkStep::Start);
    EXPECT_EQ(trace.entries.back().iteration, rb.iterations);
    EXPECT_NEAR(trace.entries.back().error, rb.error, 1e-6f);
    size_t perIteration = solver == IkSolver::Ccd ? 4 : solver == IkSolver::Fabrik ? 2 : 1;
    EXPECT_EQ(trace.entries.size(), 1 + perIteration * rb.iterations) << toString(solver);
    if (solver == IkSolver::Fabrik) {
      EXPECT_EQ(trace.entries[1].step, IkStep::FabrikBackward);
      EXPECT_VEC3_NEAR(trace.entries[1].positions.back(), target, 1e-6f);  // backward starts at the target
      EXPECT_EQ(trace.entries[2].step, IkStep::FabrikForward);
    }
    if (solver == IkSolver::Ccd) {
      EXPECT_EQ(trace.entries[1].joint, 3);  // the joint nearest the effector turns first
      EXPECT_EQ(trace.entries[4].joint, 0);
    }
  }
}

// The transpose's line search only takes steps that lower the true error (with one target
// the traced error never rises), and each of its steps ends no worse than Buss's step
// from the same pose, since Buss's step is its first trial.
TEST(IkSolvers, TransposeLineSearchNeverRaisesTheError) {
  std::mt19937 rng(31);
  const Skeleton s = test::makeChain(10, &rng);
  const float chain = test::chainLength(s);
  for (int k = 0; k < 50; ++k) {
    Pose pose = test::randomPose(s, rng, 0.6f);
    IkProblem p = problemFor(s, pose, 9, test::worldPosition(s, test::randomPose(s, rng, 0.6f), 9));
    IkTrace trace;
    IkSettings settings;
    settings.tolerance = 1e-3f * chain;
    settings.maxIterations = 300;
    settings.transposeLineSearch = true;
    settings.trace = &trace;
    const IkResult r = solveJacobianTranspose(p, settings);
    ASSERT_TRUE(r.message.empty());
    for (size_t i = 1; i < trace.entries.size(); ++i)
      ASSERT_LE(trace.entries[i].error, trace.entries[i - 1].error * (1.0f + 1e-5f)) << "case " << k << " step " << i;
    // One step each from the same random pose.
    const Pose start = test::randomPose(s, rng, 1.2f);
    const glm::vec3 target = test::worldPosition(s, test::randomPose(s, rng, 1.2f), 9);
    Pose a = start, b = start;
    IkProblem pa = problemFor(s, a, 9, target), pb = problemFor(s, b, 9, target);
    IkSettings one;
    one.maxIterations = 1;
    const float buss = solveJacobianTranspose(pa, one).error;
    one.transposeLineSearch = true;
    const float searched = solveJacobianTranspose(pb, one).error;
    EXPECT_LE(searched, buss * (1.0f + 1e-5f)) << "case " << k;
  }
}

// FABRIK's hybrid finish, step by step: pairs of passes first, then DLS steps, counted as
// iterations; with fabrikFinishAfter = 0 the trace holds passes only.
TEST(IkSolvers, FabrikFinishesWithDlsStepsOnlyWhereAllowed) {
  std::mt19937 rng(11);
  const Skeleton s = test::makeChain(10, &rng);
  IkRig rig;
  for (int i = 0; i < s.size(); ++i) rig.setLimit(s.size(), i, limitFor(0, i));
  int sawFinish = 0;
  for (int k = 0; k < 40; ++k) {
    Pose goal = test::randomPose(s, rng, 0.8f);
    for (int i = 0; i < s.size(); ++i)
      goal.local[i].rotation = applyJointLimit(rig.limits[i], s.rest[i].rotation, goal.local[i].rotation);
    for (int finishAfter : {10, 0}) {
      Pose pose = Pose::rest(s);
      IkProblem p = problemFor(s, pose, 9, test::worldPosition(s, goal, 9));
      p.rig = &rig;
      IkTrace trace;
      IkSettings settings;
      settings.tolerance = 1e-3f * test::chainLength(s);
      settings.fabrikFinishAfter = finishAfter;
      settings.trace = &trace;
      const IkResult r = solveFabrik(p, settings);
      ASSERT_TRUE(r.message.empty());
      int passes = 0, steps = 0;
      for (size_t i = 1; i < trace.entries.size(); ++i) {
        const IkStep st = trace.entries[i].step;
        if (st == IkStep::FabrikForward) ++passes;
        if (st == IkStep::JacobianStep) {
          ++steps;
        } else {
          ASSERT_EQ(steps, 0) << "a FABRIK pass after the DLS finish began, case " << k;
        }
      }
      EXPECT_EQ(passes + steps, r.iterations) << "case " << k;
      EXPECT_EQ(trace.entries.back().iteration, r.iterations);
      if (finishAfter == 0) EXPECT_EQ(steps, 0);
      else EXPECT_LE(passes, 10);
      if (finishAfter != 0 && steps > 0) ++sawFinish;
    }
  }
  EXPECT_GT(sawFinish, 0) << "no case needed the finish: the test does not exercise it";
}

// A valid pose may hold non-unit quaternions (found by fuzz_ik): every solver hands back
// unit rotations for the chain it worked on, even where a joint did not need to turn
// (the target already reached), and solves as if the input had been unit.
TEST(IkSolvers, NonUnitStartRotationsComeBackUnit) {
  const IkSolver all[] = {IkSolver::TwoBone, IkSolver::Ccd, IkSolver::Fabrik, IkSolver::JacobianTranspose,
                          IkSolver::JacobianPinv, IkSolver::JacobianDls, IkSolver::JacobianSdls};
  std::mt19937 rng(41);
  const Skeleton s = test::makeChain(4, &rng);
  for (IkSolver solver : all) {
    for (int k = 0; k < 20; ++k) {
      const Pose unit = test::randomPose(s, rng, 1.0f);
      Pose scaled = unit;
      // Only the chain's joints (IK root j1): what lies above is outside the solver's care.
      for (int i = 1; i < s.size(); ++i) scaled.local[i].rotation *= (k % 2 ? 3.0f : 0.2f);
      // Half the cases: the target is where the effector already is, so nothing turns.
      Pose other = test::randomPose(s, rng, 1.0f);
      other.local[0] = unit.local[0];
      const glm::vec3 target = test::worldPosition(s, k % 4 < 2 ? unit : other, 3);
      Pose a = unit, b = scaled;
      IkProblem pa = problemFor(s, a, 3, target), pb = problemFor(s, b, 3, target);
      pa.targets[0].root = pb.targets[0].root = 1;
      const IkResult ra = solveIk(solver, pa, IkSettings{}), rb = solveIk(solver, pb, IkSettings{});
      ASSERT_TRUE(rb.message.empty()) << rb.message;
      for (int i = 1; i < s.size(); ++i)
        EXPECT_NEAR(glm::length(b.local[i].rotation), 1.0f, 1e-5f) << toString(solver) << " joint " << i;
      EXPECT_EQ(ra.converged, rb.converged) << toString(solver);
      EXPECT_NEAR(ra.error, rb.error, 1e-3f) << toString(solver);  // iterations round differently
    }
  }
}

TEST(IkSolvers, BadInputIsReportedAndTheposeIsLeftAlone) {
  const Skeleton s = test::makeChain(4);
  Pose pose = Pose::rest(s);
  IkProblem p = problemFor(s, pose, 3, {0, 1, 0});
  p.targets[0].root = 3;
  EXPECT_NE(solveCcd(p, IkSettings{}).message, "");
  p.targets[0].root = -1;
  p.targets[0].effector = 42;
  EXPECT_NE(solveFabrik(p, IkSettings{}).message, "");
  p.targets[0].effector = 3;
  p.targets[0].weight = 0.0f;
  EXPECT_NE(solveJacobianDls(p, IkSettings{}).message, "");
}

}  // namespace
}  // namespace kinema
