#pragma once
#include <limits>
#include <string>

#include "sim/spring_chain.h"

namespace kinema {

// The four time-stepping schemes the chapter compares, for x' = v, v' = a(x, v) = F / m:
//  ExplicitEuler    x+ = x + h v,   v+ = v + h a(x, v)                 (forward Euler)
//  SymplecticEuler  v+ = v + h a(x, v),  x+ = x + h v+                  (semi-implicit)
//  Verlet           velocity Verlet: v' = v + h/2 a(x, v), x+ = x + h v',
//                   v+ = v' + h/2 a(x+, v')  (damping read at the half-step velocity)
//  ImplicitEuler    v+ = v + h a(x+, v+),  x+ = x + h v+                (backward Euler: a
//                   linear solve per step, tridiagonal for the chain)
enum class Integrator { ExplicitEuler, SymplecticEuler, Verlet, ImplicitEuler };

const char* toString(Integrator integrator);
bool fromString(const std::string& s, Integrator& out);

// Advances the chain by one step of h seconds (h > 0).
void stepChain(const SpringChain& chain, Integrator integrator, double h, ChainState& state);

// The same scheme on one damped oscillator x'' = -w^2 x - 2 zeta w x': the 2x2 matrix taking
// (x, v) to (x+, v+), row-major {a, b, c, d}. Each mode of the chain evolves by it exactly.
void oscillatorStepMatrix(Integrator integrator, double omega, double zeta, double h, double out[4]);
// Its spectral radius (largest eigenvalue modulus): above 1, that mode grows without bound.
double oscillatorSpectralRadius(Integrator integrator, double omega, double zeta, double h);

// The largest stable time step for one mode (rad/s, damping ratio), from the scheme's step
// matrix: closed forms where they exist (explicit Euler 2 zeta / w; symplectic Euler
// 2 (sqrt(1 + zeta^2) - zeta) / w; Verlet, undamped, 2 / w), otherwise the first h where the
// spectral radius passes 1 (found by a scan and bisection). Infinity for implicit Euler.
double oscillatorStabilityLimit(Integrator integrator, double omega, double zeta);

// The chain's largest stable step: the smallest of its modes' limits.
double chainStabilityLimit(const SpringChain& chain, Integrator integrator);

// A measured limit: starting from `start`, steps the chain for `seconds` and reports whether
// its energy rose above `factor` times the starting energy (the test of a blow-up).
bool chainBlowsUp(const SpringChain& chain, Integrator integrator, double h, const ChainState& start,
                  double seconds = 5.0, double factor = 10.0);

constexpr double kUnconditionallyStable = std::numeric_limits<double>::infinity();

}  // namespace kinema
