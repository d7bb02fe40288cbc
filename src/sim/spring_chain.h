#pragma once
#include <string>
#include <vector>

namespace kinema {

// The teaching problem of the physics chapter (seed 003, 16.5): a chain of `masses` equal
// point masses hanging from a fixed anchor, each joined to the one above by a spring of
// stiffness k with a dashpot beside it (damping c = beta * k, Kelvin-Voigt). Motion is along
// the chain (one coordinate per mass: its displacement from rest, metres), so the system is
// linear and each scheme's stability follows from its modes. SI units throughout.
struct SpringChain {
  int masses = 10;          // >= 1
  double mass = 1.0;        // kg per mass, > 0
  double stiffness = 1e4;   // N/m per spring, > 0
  double beta = 0.0;        // s: dashpot coefficient per spring = beta * stiffness, >= 0

  std::string validate() const;
};

// Position and velocity of every mass (m, m/s), masses entries each; index 0 hangs from the anchor.
struct ChainState {
  std::vector<double> x, v;
};

// Kinetic plus spring energy (J); zero only at rest.
double chainEnergy(const SpringChain& chain, const ChainState& state);

// The chain's natural angular frequencies (rad/s), lowest first: for a fixed-free chain of N
// equal masses and springs, w_j = 2 sqrt(k/m) sin((2j - 1) pi / (2 (2N + 1))), j = 1..N.
std::vector<double> chainModes(const SpringChain& chain);

// A mode's damping ratio under stiffness-proportional damping: zeta = beta * w / 2.
inline double modeDampingRatio(const SpringChain& chain, double omega) { return 0.5 * chain.beta * omega; }
// The beta that gives the chain's highest mode the damping ratio zeta.
double betaForHighestModeRatio(const SpringChain& chain, double zeta);

}  // namespace kinema
