// IK solvers on the FABRIK paper's test (Aristidou & Lasenby 2011): a 10-joint chain,
// random reachable targets, tolerance 1e-3 x chain length; also unreachable targets.
// Each benchmark iteration solves one case from a fixed list (the pose is reset first).
// Counters: iters_mean / iters_median = solver iterations per solve, us_per_iter.
// two-hands/*: several effectors (FABRIK sub-bases vs stacked Jacobian rows).
//   ./build/bench/ik_bench --benchmark_min_time=1
#include <benchmark/benchmark.h>

#include <algorithm>
#include <random>
#include <vector>

#include "core/forward_kinematics.h"
#include "ik/ik_solver.h"
#include "ik/two_bone_job.h"
#include "ik_test_chains.h"  // tests/ik: the rigs the IK tests use

namespace kinema {
namespace {

constexpr int kCases = 1000;

Skeleton chain(int joints) {
  Skeleton s;
  for (int i = 0; i < joints; ++i)
    s.addJoint("j" + std::to_string(i), i - 1, Transform::fromTranslation(glm::vec3(0.0f, i == 0 ? 0.0f : 1.0f, 0.0f)));
  return s;
}

Pose randomPose(const Skeleton& s, std::mt19937& rng, float maxAngle) {
  std::normal_distribution<float> g(0.0f, 1.0f);
  std::uniform_real_distribution<float> a(0.0f, maxAngle);
  Pose p = Pose::rest(s);
  for (Transform& t : p.local) {
    const glm::vec3 axis(g(rng), g(rng), g(rng));
    t.rotation = glm::angleAxis(a(rng), glm::normalize(axis));
  }
  return p;
}

struct Cases {
  Skeleton skeleton;
  std::vector<Pose> starts;
  std::vector<glm::vec3> targets;
  float length = 0.0f;
};

// Start poses and targets: FK of random poses (each joint turned up to 0.6 rad about a
// random axis), or points 1.5 chain lengths away in a random direction (unreachable).
Cases makeCases(int joints, bool reachable) {
  Cases c;
  c.skeleton = chain(joints);
  c.length = static_cast<float>(joints - 1);
  std::mt19937 rng(2011);
  for (int k = 0; k < kCases; ++k) {
    c.starts.push_back(randomPose(c.skeleton, rng, 0.6f));
    if (reachable) {
      c.targets.push_back(glm::vec3(computeWorld(c.skeleton, randomPose(c.skeleton, rng, 0.6f))[joints - 1][3]));
    } else {
      std::normal_distribution<float> g(0.0f, 1.0f);
      c.targets.push_back(glm::normalize(glm::vec3(g(rng), g(rng), g(rng))) * 1.5f * c.length);
    }
  }
  return c;
}

void run(benchmark::State& state, IkSolver solver, int joints, bool reachable, bool lineSearch = false) {
  const Cases cases = makeCases(joints, reachable);
  IkSettings settings;
  settings.transposeLineSearch = lineSearch;
  settings.tolerance = 1e-3f * cases.length;
  settings.maxIterations = solver == IkSolver::JacobianTranspose ? 20000 : 1000;
  settings.stallFraction = reachable ? 0.0f : settings.stallFraction;  // reachable: run to tolerance
  IkProblem problem;
  problem.skeleton = &cases.skeleton;
  problem.targets.push_back({});
  problem.targets[0].effector = joints - 1;
  problem.targets[0].root = 0;
  // One untimed pass over every case for the iteration statistics.
  std::vector<int> iterations;
  int converged = 0;
  for (int k = 0; k < kCases; ++k) {
    Pose pose = cases.starts[k];
    problem.pose = &pose;
    problem.targets[0].position = cases.targets[k];
    const IkResult r = solveIk(solver, problem, settings);
    iterations.push_back(r.iterations);
    converged += r.converged;
  }
  double sum = 0.0;
  for (int i : iterations) sum += i;
  std::vector<int> sorted = iterations;
  std::sort(sorted.begin(), sorted.end());
  Pose pose;
  long long solves = 0, iters = 0;
  int k = 0;
  for (auto _ : state) {
    pose = cases.starts[k];
    problem.pose = &pose;
    problem.targets[0].position = cases.targets[k];
    const IkResult r = solveIk(solver, problem, settings);
    benchmark::DoNotOptimize(r);
    iters += r.iterations;
    ++solves;
    k = (k + 1) % kCases;
  }
  state.counters["iters_mean"] = sum / kCases;
  state.counters["iters_median"] = sorted[kCases / 2];
  state.counters["converged_pct"] = 100.0 * converged / kCases;
  state.counters["us_per_iter"] =
      benchmark::Counter(static_cast<double>(iters) * 1e-6, benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
  state.SetItemsProcessed(solves);
}

// The two-bone job alone, as ozz's sample runs its IKTwoBoneJob: the model-space inputs
// of the 3-joint arm's cases (FK of each start pose, the shoulder as IK root, no pole) are
// computed before timing; each iteration runs one job (validate() included unless
// `unchecked`), cycling through the 1000 cases.
void runTwoBoneJob(benchmark::State& state, bool reachable, bool unchecked) {
  const Cases cases = makeCases(3, reachable);
  glm::quat startCorrection, midCorrection;
  bool reached = false;
  std::vector<TwoBoneIkJob> jobs(kCases);
  for (int k = 0; k < kCases; ++k) {
    const std::vector<glm::mat4> w = computeWorld(cases.skeleton, cases.starts[k]);
    TwoBoneIkJob& job = jobs[k];
    job.startPosition = glm::vec3(w[0][3]);
    job.startRotation = glm::normalize(glm::quat_cast(glm::mat3(w[0])));
    job.midPosition = glm::vec3(w[1][3]);
    job.midRotation = glm::normalize(glm::quat_cast(glm::mat3(w[1])));
    job.endPosition = glm::vec3(w[2][3]);
    job.target = cases.targets[k];
    job.startCorrection = &startCorrection;
    job.midCorrection = &midCorrection;
    job.reached = &reached;
  }
  long long solves = 0;
  int k = 0;
  for (auto _ : state) {
    if (unchecked)
      jobs[k].runUnchecked();
    else
      benchmark::DoNotOptimize(jobs[k].run());
    benchmark::DoNotOptimize(startCorrection);
    benchmark::DoNotOptimize(midCorrection);
    benchmark::ClobberMemory();
    ++solves;
    k = (k + 1) % kCases;
  }
  state.SetItemsProcessed(solves);
}

// Two hands on a shared spine (hips - spine - chest, then two arms of three bones 0.8
// long): both targets from FK of one random pose of the whole rig (every joint turned up
// to 0.5 rad), starts from poses turned up to 0.3 rad; tolerance 1e-3 x 4.4 (hips to hand).
using test::twoArms;

void runTwoHands(benchmark::State& state, IkSolver solver, bool passesOnly = false) {
  const Skeleton skeleton = twoArms();
  std::mt19937 rng(2011);
  std::vector<Pose> starts;
  std::vector<glm::vec3> left, right;
  for (int k = 0; k < kCases; ++k) {
    const std::vector<glm::mat4> goal = computeWorld(skeleton, randomPose(skeleton, rng, 0.5f));
    left.push_back(glm::vec3(goal[5][3]));
    right.push_back(glm::vec3(goal[8][3]));
    starts.push_back(randomPose(skeleton, rng, 0.3f));
  }
  IkSettings settings;  // the defaults: a cap of 100 iterations, stall stop on
  settings.tolerance = 1e-3f * 4.4f;
  if (passesOnly) settings.fabrikFinishAfter = 0;  // FABRIK without its DLS finish
  IkProblem problem;
  problem.skeleton = &skeleton;
  problem.targets.resize(2);
  problem.targets[0].effector = 5;
  problem.targets[1].effector = 8;
  std::vector<int> iterations;
  int converged = 0;
  for (int k = 0; k < kCases; ++k) {
    Pose pose = starts[k];
    problem.pose = &pose;
    problem.targets[0].position = left[k];
    problem.targets[1].position = right[k];
    const IkResult r = solveIk(solver, problem, settings);
    iterations.push_back(r.iterations);
    converged += r.converged;
  }
  double sum = 0.0;
  for (int i : iterations) sum += i;
  std::sort(iterations.begin(), iterations.end());
  Pose pose;
  long long iters = 0;
  int k = 0;
  for (auto _ : state) {
    pose = starts[k];
    problem.pose = &pose;
    problem.targets[0].position = left[k];
    problem.targets[1].position = right[k];
    const IkResult r = solveIk(solver, problem, settings);
    benchmark::DoNotOptimize(r);
    iters += r.iterations;
    k = (k + 1) % kCases;
  }
  state.counters["iters_mean"] = sum / kCases;
  state.counters["iters_median"] = iterations[kCases / 2];
  state.counters["converged_pct"] = 100.0 * converged / kCases;
  state.counters["us_per_iter"] =
      benchmark::Counter(static_cast<double>(iters) * 1e-6, benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
}

void registerAll() {
  const IkSolver iterative[] = {IkSolver::Ccd, IkSolver::Fabrik, IkSolver::JacobianTranspose, IkSolver::JacobianPinv,
                                IkSolver::JacobianDls, IkSolver::JacobianSdls};
  for (bool reachable : {true, false}) {
    const std::string kind = reachable ? "reachable" : "unreachable";
    for (IkSolver s : iterative)
      benchmark::RegisterBenchmark(("ik10/" + kind + "/" + toString(s)).c_str(),
                                   [=](benchmark::State& st) { run(st, s, 10, reachable); })
          ->Unit(benchmark::kMicrosecond);
    benchmark::RegisterBenchmark(("ik10/" + kind + "/jacobian-transpose-line-search").c_str(),
                                 [=](benchmark::State& st) { run(st, IkSolver::JacobianTranspose, 10, reachable, true); })
        ->Unit(benchmark::kMicrosecond);
    benchmark::RegisterBenchmark(("ik3/" + kind + "/two-bone").c_str(),
                                 [=](benchmark::State& st) { run(st, IkSolver::TwoBone, 3, reachable); })
        ->Unit(benchmark::kNanosecond);
    benchmark::RegisterBenchmark(("ik3/" + kind + "/two-bone-job").c_str(),
                                 [=](benchmark::State& st) { runTwoBoneJob(st, reachable, false); })
        ->Unit(benchmark::kNanosecond);
    benchmark::RegisterBenchmark(("ik3/" + kind + "/two-bone-job-unchecked").c_str(),
                                 [=](benchmark::State& st) { runTwoBoneJob(st, reachable, true); })
        ->Unit(benchmark::kNanosecond);
  }
  for (IkSolver s : {IkSolver::Fabrik, IkSolver::JacobianDls, IkSolver::JacobianPinv, IkSolver::JacobianSdls})
    benchmark::RegisterBenchmark((std::string("two-hands/") + toString(s)).c_str(),
                                 [=](benchmark::State& st) { runTwoHands(st, s); })
        ->Unit(benchmark::kMicrosecond);
  benchmark::RegisterBenchmark("two-hands/fabrik-passes-only",
                               [=](benchmark::State& st) { runTwoHands(st, IkSolver::Fabrik, true); })
      ->Unit(benchmark::kMicrosecond);
}

}  // namespace
}  // namespace kinema

int main(int argc, char** argv) {
  kinema::registerAll();
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
