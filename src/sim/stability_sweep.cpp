#include "sim/stability_sweep.h"

#include <algorithm>
#include <cmath>

namespace kinema {

std::string StabilitySweepOptions::validate() const {
  if (std::string e = chain.validate(); !e.empty()) return e;
  if (!(zeta > 0.0 && zeta <= 1.0)) return "zeta must be in (0, 1]";
  if (!(seconds > 0.0 && seconds <= 60.0)) return "seconds must be in (0, 60]";
  if (!(blowUpFactor > 1.0) || !std::isfinite(blowUpFactor)) return "the blow-up factor must be above 1";
  if (!(tipDisplacement != 0.0) || !std::isfinite(tipDisplacement)) return "the tip displacement must be non-zero";
  return "";
}

StabilitySweep runStabilitySweep(const StabilitySweepOptions& o) {
  StabilitySweep sweep;
  sweep.chain = o.chain;
  sweep.chain.beta = betaForHighestModeRatio(o.chain, o.zeta);
  sweep.omegaMax = chainModes(sweep.chain).back();
  ChainState start;
  start.x.assign(sweep.chain.masses, 0.0);
  start.v.assign(sweep.chain.masses, 0.0);
  start.x.back() = o.tipDisplacement;

  const Integrator schemes[] = {Integrator::ExplicitEuler, Integrator::SymplecticEuler, Integrator::Verlet,
                                Integrator::ImplicitEuler};
  for (Integrator s : schemes) {
    SchemeLimits l;
    l.integrator = s;
    l.derived = chainStabilityLimit(sweep.chain, s);
    if (std::isfinite(l.derived))
      for (int pct = 50; pct <= 150; ++pct)
        if (chainBlowsUp(sweep.chain, s, l.derived * pct / 100.0, start, o.seconds, o.blowUpFactor)) {
          l.measured = l.derived * pct / 100.0;
          break;
        }
    sweep.limits.push_back(l);
  }
  const double explicitLimit = sweep.limits[0].derived;
  sweep.steps = {0.8 * explicitLimit, 1.2 * explicitLimit, 1.05 * sweep.limits[1].derived,
                 1.05 * sweep.limits[2].derived, 10.0 * explicitLimit};
  std::sort(sweep.steps.begin(), sweep.steps.end());

  const double e0 = chainEnergy(sweep.chain, start);
  for (Integrator s : schemes)
    for (double h : sweep.steps) {
      StabilityRun run;
      run.integrator = s;
      run.step = h;
      ChainState st = start;
      const long long n = static_cast<long long>(std::ceil(o.seconds / h));
      // At most about 2,000 samples per run are kept (plots), every step is simulated.
      const long long every = std::max<long long>(1, n / 2000);
      auto record = [&](long long i) {
        run.times.push_back(static_cast<double>(i) * h);
        run.tip.push_back(st.x.back());
        run.energyRatio.push_back(chainEnergy(sweep.chain, st) / e0);
      };
      record(0);
      for (long long i = 1; i <= n; ++i) {
        stepChain(sweep.chain, s, h, st);
        const double ratio = chainEnergy(sweep.chain, st) / e0;
        if (!run.blewUp && !(ratio <= o.blowUpFactor)) {
          run.blewUp = true;
          run.blowUpTime = static_cast<double>(i) * h;
        }
        if (i % every == 0 || i == n) record(i);
        if (!(ratio < 1e12)) break;  // far past any plot: stop before it overflows
      }
      sweep.runs.push_back(std::move(run));
    }
  return sweep;
}

}  // namespace kinema
