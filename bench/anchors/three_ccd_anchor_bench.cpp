// Kinema's CCD and FABRIK beside three.js 0.187's CCDIKSolver, on three.js's own problem
// (../shared/anchors/three-ccd/perf_three_ccd.mjs pins it): a 10-bone chain of unit bones
// along +Y, 1,000 reachable and 200 unreachable seeded targets, each solved from the straight
// rest pose, tolerance 0.01 checked before every sweep, at most 1,000 sweeps.
// The program first runs the script (node, in the build folder's copy with three installed),
// which times three.js and writes its exact targets and per-target sweep counts; then it
// replays those targets through Kinema, checks that CCD takes the same number of sweeps on
// every reachable target, and times each solve (the median of 3 passes, as the script does).
//   ./build/bench/anchors/three_ccd_anchor_bench
#include <nlohmann/json.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <string>
#include <vector>

#include "anchor_timing.h"
#include "core/forward_kinematics.h"
#include "ik/ik_solver.h"

namespace {

using namespace kinema;
using Clock = std::chrono::steady_clock;

constexpr int kBones = 10;
constexpr float kTolerance = 0.01f;  // 1e-3 x chain length
constexpr int kMaxSweeps = 1000;
constexpr int kPasses = 3;

struct Solves {
  std::vector<int> sweeps;
  std::vector<bool> converged;
  std::vector<double> us;  // per target, median over passes
};

// Every target from the straight rest pose; `reachableRun`: no stall stop (three's loop runs
// to the tolerance or the cap), otherwise the solver's defaults (it stops once stalled and
// straightens the chain towards the target).
Solves solveAll(IkSolver solver, const Skeleton& chain, const std::vector<glm::vec3>& targets, size_t begin,
                size_t end, bool reachableRun) {
  IkSettings settings;
  settings.tolerance = kTolerance;
  settings.maxIterations = kMaxSweeps;
  if (reachableRun) settings.stallFraction = 0.0f;
  IkProblem problem;
  problem.skeleton = &chain;
  problem.targets.resize(1);
  problem.targets[0].effector = kBones;
  problem.targets[0].root = 0;
  const Pose rest = Pose::rest(chain);
  Pose pose = rest;
  problem.pose = &pose;
  Solves out;
  std::vector<std::vector<double>> times(end - begin);
  for (int pass = 0; pass < kPasses; ++pass)
    for (size_t i = begin; i < end; ++i) {
      pose = rest;
      problem.targets[0].position = targets[i];
      const auto t0 = Clock::now();
      const IkResult r = solveIk(solver, problem, settings);
      const auto t1 = Clock::now();
      times[i - begin].push_back(std::chrono::duration<double, std::micro>(t1 - t0).count());
      if (pass == 0) {
        out.sweeps.push_back(r.iterations);
        out.converged.push_back(r.converged);
      }
    }
  for (auto& t : times) out.us.push_back(anchor::median(t));
  return out;
}

// For callgrind: one solver on the given targets from the straight rest pose, untimed;
// `reachableRun` as in solveAll. Each solver has its own entry so --toggle-collect can
// name it ('*ccdSolveLoop*', '*fabrikSolveLoop*').
int solveLoop(IkSolver solver, const Skeleton& chain, const std::vector<glm::vec3>& targets, bool reachableRun) {
  IkSettings settings;
  settings.tolerance = kTolerance;
  settings.maxIterations = kMaxSweeps;
  if (reachableRun) settings.stallFraction = 0.0f;
  IkProblem problem;
  problem.skeleton = &chain;
  problem.targets.resize(1);
  problem.targets[0].effector = kBones;
  problem.targets[0].root = 0;
  const Pose rest = Pose::rest(chain);
  Pose pose = rest;
  problem.pose = &pose;
  int sweeps = 0;
  for (const glm::vec3& t : targets) {
    pose = rest;
    problem.targets[0].position = t;
    sweeps += solveIk(solver, problem, settings).iterations;
  }
  return sweeps;
}
__attribute__((noinline)) int ccdSolveLoop(const Skeleton& chain, const std::vector<glm::vec3>& targets,
                                           bool reachableRun) {
  return solveLoop(IkSolver::Ccd, chain, targets, reachableRun);
}
__attribute__((noinline)) int fabrikSolveLoop(const Skeleton& chain, const std::vector<glm::vec3>& targets,
                                              bool reachableRun) {
  return solveLoop(IkSolver::Fabrik, chain, targets, reachableRun);
}

double mean(const std::vector<double>& v) {
  double s = 0.0;
  for (double x : v) s += x;
  return v.empty() ? 0.0 : s / static_cast<double>(v.size());
}
double meanInt(const std::vector<int>& v) {
  double s = 0.0;
  for (int x : v) s += x;
  return v.empty() ? 0.0 : s / static_cast<double>(v.size());
}

}  // namespace

int main(int argc, char** argv) {
  const std::string dir = KINEMA_THREE_CCD_DIR;
  // Instructions per solve (the targets of an earlier run, no node), one command line:
  //   valgrind --tool=callgrind --toggle-collect='*ccdSolveLoop*'
  //     ./build/bench/anchors/three_ccd_anchor_bench callgrind-ccd
  // callgrind-ccd / callgrind-fabrik: the reachable targets; callgrind-ccd-unreachable /
  // callgrind-fabrik-unreachable: the unreachable ones (toggle '*fabrikSolveLoop*' for FABRIK).
  const std::string mode = argc > 1 ? argv[1] : "";
  const bool callgrind = mode.rfind("callgrind-", 0) == 0;
  const std::string targetsPath = dir + "/targets.json", resultsPath = dir + "/results.json",
                    summaryPath = dir + "/summary.json";
  const std::string command = "cd '" + dir + "' && '" + KINEMA_NODE +
                              "' perf_three_ccd.mjs --targets-out targets.json --results-out results.json > summary.json";
  if (!callgrind) std::printf("running three.js: %s\n", command.c_str());
  std::fflush(stdout);
  if (!callgrind && std::system(command.c_str()) != 0) {
    std::fprintf(stderr, "error: the three.js script failed (is three installed in %s?)\n", dir.c_str());
    return 1;
  }
  nlohmann::json summary, rows, list;
  try {
    std::ifstream(summaryPath) >> summary;
    std::ifstream(resultsPath) >> rows;
    std::ifstream(targetsPath) >> list;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "error: cannot read the script's output: %s\n", e.what());
    return 1;
  }
  std::vector<glm::vec3> targets;
  for (const auto& t : list) targets.emplace_back(t[0].get<float>(), t[1].get<float>(), t[2].get<float>());
  const size_t reachable = summary["reachable"]["n"].get<size_t>(), all = targets.size();
  const double threeReach = summary["reachable"]["mean_us_per_solve"].get<double>();
  const double threeUnreach = summary["unreachable"]["mean_us_per_solve"].get<double>();
  const double threeSweeps = summary["reachable"]["mean_sweeps"].get<double>();

  Skeleton chain;
  for (int i = 0; i <= kBones; ++i)
    chain.addJoint("j" + std::to_string(i), i - 1,
                   Transform::fromTranslation(glm::vec3(0.0f, i == 0 ? 0.0f : 1.0f, 0.0f)));

  if (mode == "dump") {
    // Per target: solver, index, iterations, final error and the effector's world position,
    // to compare two builds' answers (diff the outputs).
    const Pose rest = Pose::rest(chain);
    for (IkSolver solver : {IkSolver::Ccd, IkSolver::Fabrik})
      for (size_t i = 0; i < all; ++i) {
        IkSettings settings;
        settings.tolerance = kTolerance;
        settings.maxIterations = kMaxSweeps;
        if (i < reachable) settings.stallFraction = 0.0f;
        IkProblem problem;
        problem.skeleton = &chain;
        problem.targets.resize(1);
        problem.targets[0].effector = kBones;
        problem.targets[0].root = 0;
        problem.targets[0].position = targets[i];
        Pose pose = rest;
        problem.pose = &pose;
        const IkResult r = solveIk(solver, problem, settings);
        const glm::vec3 e(computeWorld(chain, pose)[kBones][3]);
        std::printf("%s %zu %d %.9g %.9g %.9g %.9g\n", toString(solver), i, r.iterations, r.error, e.x, e.y, e.z);
      }
    return 0;
  }
  if (callgrind) {
    const bool far = mode.find("-unreachable") != std::string::npos;
    const std::vector<glm::vec3> some(far ? targets.begin() + reachable : targets.begin(),
                                      far ? targets.end() : targets.begin() + reachable);
    const bool fabrik = mode.rfind("callgrind-fabrik", 0) == 0;
    if (!fabrik && mode.rfind("callgrind-ccd", 0) != 0) {
      std::fprintf(stderr, "error: unknown mode '%s'\n", mode.c_str());
      return 1;
    }
    const int iterations = fabrik ? fabrikSolveLoop(chain, some, !far) : ccdSolveLoop(chain, some, !far);
    std::printf("%zu %s solves, %d iterations: instructions / %zu = per solve\n", some.size(),
                fabrik ? "FABRIK" : "CCD", iterations, some.size());
    return 0;
  }
  // Same answers first: CCD's sweep count on every reachable target equals three's.
  const Solves ccd = solveAll(IkSolver::Ccd, chain, targets, 0, reachable, true);
  int sameSweeps = 0, bothConverged = 0, worstGap = 0;
  for (size_t i = 0; i < reachable; ++i) {
    const int three = rows[i]["sweeps"].get<int>();
    sameSweeps += ccd.sweeps[i] == three;
    bothConverged += ccd.converged[i] && rows[i]["converged"].get<bool>();
    if (ccd.sweeps[i] != three) {
      worstGap = std::max(worstGap, std::abs(ccd.sweeps[i] - three));
      std::printf("target %zu: Kinema CCD %d sweeps, three.js %d (final distance %.6g, tolerance %g)\n", i,
                  ccd.sweeps[i], three, rows[i]["final_err"].get<double>(), kTolerance);
    }
  }
  const Solves fabrik = solveAll(IkSolver::Fabrik, chain, targets, 0, reachable, true);
  int fabrikConverged = 0;
  for (bool c : fabrik.converged) fabrikConverged += c;
  const Solves ccdFar = solveAll(IkSolver::Ccd, chain, targets, reachable, all, false);
  const Solves fabrikFar = solveAll(IkSolver::Fabrik, chain, targets, reachable, all, false);

  std::printf("\nKinema beside three.js %s CCDIKSolver (%s), %zu reachable + %zu unreachable targets\n",
              summary["three_version"].get<std::string>().c_str(), summary["node"].get<std::string>().c_str(),
              reachable, all - reachable);
  std::printf("CCD sweep counts equal to three.js's on %d of %zu reachable targets; converged on both: %d\n",
              sameSweeps, reachable, bothConverged);
  std::printf("\n| work | Kinema | three.js CCDIKSolver | ratio |\n|---|---|---|---|\n");
  std::printf("| CCD, reachable (mean per solve) | %.3g us, %.3g sweeps | %.3g us, %.3g sweeps | %.3f |\n",
              mean(ccd.us), meanInt(ccd.sweeps), threeReach, threeSweeps, mean(ccd.us) / threeReach);
  std::printf("| FABRIK, reachable (mean per solve) | %.3g us, %.3g iterations, %d converged | %.3g us (CCD) | %.3f |\n",
              mean(fabrik.us), meanInt(fabrik.sweeps), fabrikConverged, threeReach, mean(fabrik.us) / threeReach);
  std::printf("| CCD, unreachable (stall stop, then straightened) | %.3g us, %.3g sweeps | %.3g us, %d sweeps | %.3f |\n",
              mean(ccdFar.us), meanInt(ccdFar.sweeps), threeUnreach, kMaxSweeps, mean(ccdFar.us) / threeUnreach);
  std::printf("| FABRIK, unreachable | %.3g us, %.3g iterations | %.3g us (CCD) | %.3f |\n", mean(fabrikFar.us),
              meanInt(fabrikFar.sweeps), threeUnreach, mean(fabrikFar.us) / threeUnreach);
  // float against three's double: a target whose distance lands within rounding of the
  // tolerance may take one sweep more or less; more than that is a different solver.
  const bool same = worstGap <= 1 && sameSweeps >= static_cast<int>(reachable) * 99 / 100;
  if (!same) std::printf("the sweep counts differ: the CCD rows compare different work\n");
  return same ? 0 : 1;
}
