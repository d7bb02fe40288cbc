#pragma once
#include <string>
#include <vector>

#include "sim/integrators.h"

namespace kinema {

// What `kinema demo stiff-springs` shows: the same damped chain run by each scheme at a few
// growing time steps, with each scheme's derived stability limit beside the step where it is
// measured to blow up (energy above blowUpFactor x its start within `seconds`, on a 1 % grid).
struct StabilitySweepOptions {
  SpringChain chain{10, 1.0, 2500.0, 0.0};  // beta is set from zeta
  double zeta = 0.3;          // damping ratio of the highest mode, (0, 1]
  double seconds = 5.0;       // simulated time per run
  double blowUpFactor = 10.0;
  double tipDisplacement = 0.01;  // m: the start state, the last mass pulled down, at rest

  std::string validate() const;
};

// One scheme at one step: the tip's displacement and the energy over time.
struct StabilityRun {
  Integrator integrator = Integrator::ExplicitEuler;
  double step = 0.0;                 // s
  std::vector<double> times;         // s, one per recorded sample
  std::vector<double> tip;           // m
  std::vector<double> energyRatio;   // E / E0
  bool blewUp = false;               // energy passed blowUpFactor x E0
  double blowUpTime = 0.0;           // s, when it did
};

struct SchemeLimits {
  Integrator integrator = Integrator::ExplicitEuler;
  double derived = 0.0;   // chainStabilityLimit (infinite for implicit Euler)
  double measured = 0.0;  // first blow-up step on a 1 % grid from 0.5x to 1.5x derived; 0 when none
};

struct StabilitySweep {
  SpringChain chain;            // with beta set
  double omegaMax = 0.0;        // rad/s
  std::vector<double> steps;    // the columns, ascending (s)
  std::vector<SchemeLimits> limits;  // one per scheme, in Integrator order
  std::vector<StabilityRun> runs;    // scheme-major: runs[s * steps.size() + c]
};

// Columns: 0.8x and 1.2x explicit Euler's limit, 1.05x symplectic Euler's and Verlet's, and
// 10x explicit Euler's: each column crosses one more scheme's limit; implicit Euler survives all.
StabilitySweep runStabilitySweep(const StabilitySweepOptions& options);

}  // namespace kinema
