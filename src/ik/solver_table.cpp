#include "ik/solver_table.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <random>

#include "ik/solver_comparison.h"

namespace kinema {

std::string SolverTableOptions::validate() const {
  if (bones < 2 || bones > 200) return "the chain needs 2 to 200 bones";
  if (targets < 1 || targets > 100000) return "give 1 to 100000 targets";
  if (!std::isfinite(tolerance) || !(tolerance > 0.0f)) return "the tolerance must be > 0";
  if (maxIterations < 1) return "the iteration cap must be at least 1";
  if (timingRepeats < 1) return "time each solve at least once";
  if (solvers.empty()) return "no solver to compare";
  return {};
}

std::vector<SolverTableRow> computeSolverTable(const SolverTableOptions& o) {
  std::vector<SolverTableRow> rows;
  if (!o.validate().empty()) return rows;
  // A 3D chain along +X, each joint bent a little about alternating axes so no solver
  // starts in the straight chain's singularity.
  TeachingChain chain;
  chain.planar = false;
  chain.boneLengths.assign(o.bones, 1.0f);
  chain.startAngles.assign(o.bones, 0.1f);
  TeachingSkeleton ts = makeTeachingSkeleton(chain);
  for (int j = 1; j < o.bones; j += 2)
    ts.skeleton.rest[j].rotation = glm::angleAxis(0.1f, glm::vec3(0.0f, 1.0f, 0.0f));
  const Pose start = Pose::rest(ts.skeleton);
  const float reach = chain.reach();
  std::mt19937 rng(o.seed);
  std::normal_distribution<float> gauss(0.0f, 1.0f);
  std::uniform_real_distribution<float> unit(0.0f, 1.0f);
  auto direction = [&] {
    glm::vec3 d(gauss(rng), gauss(rng), gauss(rng));
    return glm::length(d) > 1e-6f ? glm::normalize(d) : glm::vec3(1.0f, 0.0f, 0.0f);
  };
  std::vector<glm::vec3> reachable, unreachable;
  for (int i = 0; i < o.targets; ++i) {
    // Uniform in the ball of 0.9 reach; unreachable between 1.1 and 1.5 reach.
    reachable.push_back(direction() * (0.9f * reach * std::cbrt(unit(rng))));
    unreachable.push_back(direction() * (reach * (1.1f + 0.4f * unit(rng))));
  }
  for (IkSolver solver : o.solvers)
    for (int set = 0; set < 2; ++set) {
      const std::vector<glm::vec3>& targets = set == 0 ? reachable : unreachable;
      SolverTableRow row;
      row.solver = solver;
      row.reachable = set == 0;
      row.targets = static_cast<int>(targets.size());
      double iterations = 0.0, ms = 0.0, error = 0.0;
      for (const glm::vec3& target : targets) {
        IkSettings settings;
        settings.tolerance = o.tolerance;
        settings.maxIterations = o.maxIterations;
        IkTarget t;
        t.effector = ts.skeleton.size() - 1;
        t.position = target;
        std::vector<double> times;
        IkResult result;
        for (int r = 0; r < o.timingRepeats; ++r) {
          Pose pose = start;
          IkProblem p;
          p.skeleton = &ts.skeleton;
          p.pose = &pose;
          p.targets = {t};
          const auto t0 = std::chrono::steady_clock::now();
          result = solveIk(solver, p, settings);
          times.push_back(std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count());
        }
        std::nth_element(times.begin(), times.begin() + times.size() / 2, times.end());
        iterations += result.iterations;
        ms += times[times.size() / 2];
        error += result.error;
        if (result.converged) ++row.converged;
      }
      const double n = static_cast<double>(targets.size());
      row.meanIterations = iterations / n;
      row.meanMilliseconds = ms / n;
      row.millisecondsPerIteration = iterations > 0.0 ? ms / iterations : 0.0;
      row.meanError = error / n;
      rows.push_back(row);
    }
  return rows;
}

}  // namespace kinema
