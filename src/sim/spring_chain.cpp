#include "sim/spring_chain.h"

#include <cmath>

namespace kinema {

std::string SpringChain::validate() const {
  if (masses < 1) return "the chain needs at least one mass";
  if (!(mass > 0.0) || !std::isfinite(mass)) return "mass must be a positive finite number";
  if (!(stiffness > 0.0) || !std::isfinite(stiffness)) return "stiffness must be a positive finite number";
  if (!(beta >= 0.0) || !std::isfinite(beta)) return "damping (beta) must be a finite number >= 0";
  return "";
}

double chainEnergy(const SpringChain& chain, const ChainState& s) {
  double kinetic = 0.0, spring = 0.0, above = 0.0;  // the anchor does not move
  for (int i = 0; i < chain.masses; ++i) {
    kinetic += s.v[i] * s.v[i];
    const double stretch = s.x[i] - above;
    spring += stretch * stretch;
    above = s.x[i];
  }
  return 0.5 * chain.mass * kinetic + 0.5 * chain.stiffness * spring;
}

std::vector<double> chainModes(const SpringChain& chain) {
  const double n = chain.masses, pi = 3.14159265358979323846;
  std::vector<double> w(chain.masses);
  for (int j = 1; j <= chain.masses; ++j)
    w[j - 1] = 2.0 * std::sqrt(chain.stiffness / chain.mass) * std::sin((2.0 * j - 1.0) * pi / (2.0 * (2.0 * n + 1.0)));
  return w;
}

double betaForHighestModeRatio(const SpringChain& chain, double zeta) {
  return 2.0 * zeta / chainModes(chain).back();
}

}  // namespace kinema
