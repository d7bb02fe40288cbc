#pragma once
// The FABRIK paper's comparison (Aristidou & Lasenby 2011, table 1) re-run on our solvers:
// one chain, many random targets inside and outside its reach, and per solver the mean
// iterations and time to converge. No GL; `kinema demo solver-table` prints and plots it.
#include <cstdint>
#include <string>
#include <vector>

#include "ik/ik_solver.h"

namespace kinema {

struct SolverTableOptions {
  int bones = 10;             // a straight-ish 3D chain of unit bones (ball joints)
  int targets = 100;          // random targets per set (reachable, unreachable)
  std::uint32_t seed = 1;     // the targets are a fixed function of the seed
  float tolerance = 1e-2f;    // as in the paper's table, 0.01 of a unit bone
  int maxIterations = 1000;
  int timingRepeats = 3;      // each solve timed this many times, the median kept
  std::vector<IkSolver> solvers{IkSolver::Ccd, IkSolver::Fabrik, IkSolver::JacobianTranspose,
                                IkSolver::JacobianPinv, IkSolver::JacobianDls};
  std::string validate() const;
};

struct SolverTableRow {
  IkSolver solver = IkSolver::Ccd;
  bool reachable = true;       // which set of targets
  int targets = 0;
  int converged = 0;           // how many reached the tolerance (unreachable: none can)
  double meanIterations = 0.0;
  double meanMilliseconds = 0.0;          // per solve (median of the repeats)
  double millisecondsPerIteration = 0.0;  // sum of time / sum of iterations
  double meanError = 0.0;
};

// Rows in solver order, reachable first then unreachable for each solver.
std::vector<SolverTableRow> computeSolverTable(const SolverTableOptions& options);

}  // namespace kinema
