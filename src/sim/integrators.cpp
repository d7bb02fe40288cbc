#include "sim/integrators.h"

#include <algorithm>
#include <cmath>

namespace kinema {
namespace {

// K y for the chain's stiffness matrix (springs between neighbours, the first to the anchor),
// per unit stiffness: (K y)_i = (y_i - y_{i-1}) - (y_{i+1} - y_i), y_{-1} = 0, no spring below the last.
void stiffnessTimes(const std::vector<double>& y, std::vector<double>& out) {
  const int n = static_cast<int>(y.size());
  out.resize(n);
  for (int i = 0; i < n; ++i) {
    const double above = i > 0 ? y[i - 1] : 0.0;
    double f = y[i] - above;
    if (i + 1 < n) f -= y[i + 1] - y[i];
    out[i] = f;
  }
}

// a = -(k/m) K (x + beta v)
void acceleration(const SpringChain& c, const std::vector<double>& x, const std::vector<double>& v,
                  std::vector<double>& a, std::vector<double>& scratch) {
  scratch.resize(x.size());
  for (size_t i = 0; i < x.size(); ++i) scratch[i] = x[i] + c.beta * v[i];
  stiffnessTimes(scratch, a);
  const double s = -c.stiffness / c.mass;
  for (double& ai : a) ai *= s;
}

// (m I + (h beta + h^2) k K) vNext = m v - h k K x, by the Thomas algorithm (K is tridiagonal,
// the matrix symmetric positive definite, so no pivoting is needed).
void implicitVelocity(const SpringChain& c, double h, const std::vector<double>& x, const std::vector<double>& v,
                      std::vector<double>& out) {
  const int n = c.masses;
  const double g = (h * c.beta + h * h) * c.stiffness;
  std::vector<double> kx, diag(n), upper(n), rhs(n);
  stiffnessTimes(x, kx);
  for (int i = 0; i < n; ++i) {
    diag[i] = c.mass + g * (i + 1 < n ? 2.0 : 1.0);
    upper[i] = -g;  // above and below the diagonal alike
    rhs[i] = c.mass * v[i] - h * c.stiffness * kx[i];
  }
  for (int i = 1; i < n; ++i) {
    const double f = upper[i - 1] / diag[i - 1];
    diag[i] -= f * upper[i - 1];
    rhs[i] -= f * rhs[i - 1];
  }
  out.resize(n);
  out[n - 1] = rhs[n - 1] / diag[n - 1];
  for (int i = n - 2; i >= 0; --i) out[i] = (rhs[i] - upper[i] * out[i + 1]) / diag[i];
}

}  // namespace

const char* toString(Integrator integrator) {
  switch (integrator) {
    case Integrator::ExplicitEuler: return "explicit_euler";
    case Integrator::SymplecticEuler: return "symplectic_euler";
    case Integrator::Verlet: return "verlet";
    case Integrator::ImplicitEuler: return "implicit_euler";
  }
  return "explicit_euler";
}

bool fromString(const std::string& s, Integrator& out) {
  for (Integrator i : {Integrator::ExplicitEuler, Integrator::SymplecticEuler, Integrator::Verlet,
                       Integrator::ImplicitEuler})
    if (s == toString(i)) {
      out = i;
      return true;
    }
  return false;
}

void stepChain(const SpringChain& c, Integrator integrator, double h, ChainState& s) {
  const int n = c.masses;
  std::vector<double> a, scratch;
  switch (integrator) {
    case Integrator::ExplicitEuler:
      acceleration(c, s.x, s.v, a, scratch);
      for (int i = 0; i < n; ++i) {
        s.x[i] += h * s.v[i];
        s.v[i] += h * a[i];
      }
      break;
    case Integrator::SymplecticEuler:
      acceleration(c, s.x, s.v, a, scratch);
      for (int i = 0; i < n; ++i) {
        s.v[i] += h * a[i];
        s.x[i] += h * s.v[i];
      }
      break;
    case Integrator::Verlet:
      acceleration(c, s.x, s.v, a, scratch);
      for (int i = 0; i < n; ++i) {
        s.v[i] += 0.5 * h * a[i];
        s.x[i] += h * s.v[i];
      }
      acceleration(c, s.x, s.v, a, scratch);
      for (int i = 0; i < n; ++i) s.v[i] += 0.5 * h * a[i];
      break;
    case Integrator::ImplicitEuler: {
      std::vector<double> next;
      implicitVelocity(c, h, s.x, s.v, next);
      for (int i = 0; i < n; ++i) {
        s.v[i] = next[i];
        s.x[i] += h * next[i];
      }
      break;
    }
  }
}

void oscillatorStepMatrix(Integrator integrator, double w, double zeta, double h, double out[4]) {
  // The scalar scheme applied to (x, v) = (1, 0) and (0, 1): the matrix's two columns.
  for (int col = 0; col < 2; ++col) {
    double x = col == 0 ? 1.0 : 0.0, v = col == 1 ? 1.0 : 0.0;
    auto acc = [&](double px, double pv) { return -w * w * px - 2.0 * zeta * w * pv; };
    switch (integrator) {
      case Integrator::ExplicitEuler: {
        const double a = acc(x, v);
        x += h * v;
        v += h * a;
        break;
      }
      case Integrator::SymplecticEuler:
        v += h * acc(x, v);
        x += h * v;
        break;
      case Integrator::Verlet:
        v += 0.5 * h * acc(x, v);
        x += h * v;
        v += 0.5 * h * acc(x, v);
        break;
      case Integrator::ImplicitEuler:
        v = (v - h * w * w * x) / (1.0 + 2.0 * zeta * w * h + h * h * w * w);
        x += h * v;
        break;
    }
    out[0 + col] = x;  // row 0: x+
    out[2 + col] = v;  // row 1: v+
  }
}

double oscillatorSpectralRadius(Integrator integrator, double w, double zeta, double h) {
  double m[4];
  oscillatorStepMatrix(integrator, w, zeta, h, m);
  const double tr = m[0] + m[3], det = m[0] * m[3] - m[1] * m[2];
  const double disc = 0.25 * tr * tr - det;
  if (disc >= 0.0) {
    const double r = std::sqrt(disc);
    return std::max(std::abs(0.5 * tr + r), std::abs(0.5 * tr - r));
  }
  return std::sqrt(det);  // a complex pair: both have modulus sqrt(det)
}

double oscillatorStabilityLimit(Integrator integrator, double w, double zeta) {
  switch (integrator) {
    case Integrator::ImplicitEuler: return kUnconditionallyStable;
    case Integrator::ExplicitEuler:
      // |1 + h mu| < 1 for the continuous eigenvalues mu = w (-zeta +- sqrt(zeta^2 - 1)).
      return zeta <= 1.0 ? 2.0 * zeta / w : 2.0 / (w * (zeta + std::sqrt(zeta * zeta - 1.0)));
    case Integrator::SymplecticEuler:
      // Jury's conditions on the step matrix: det = 1 - 2 zeta w h, tr = 2 - (w h)^2 - 2 zeta w h;
      // 1 + det > |tr| gives (w h)^2 + 4 zeta (w h) - 4 < 0.
      return 2.0 * (std::sqrt(1.0 + zeta * zeta) - zeta) / w;
    case Integrator::Verlet: {
      if (zeta == 0.0) return 2.0 / w;
      // Scan out to 4 / w (no damped Verlet step is stable past the undamped 2 / w), then bisect.
      const int steps = 4000;
      double stable = 0.0;
      for (int i = 1; i <= steps; ++i) {
        const double h = 4.0 / w * i / steps;
        if (oscillatorSpectralRadius(integrator, w, zeta, h) > 1.0 + 1e-12) {
          double lo = stable, hi = h;
          for (int it = 0; it < 80; ++it) {
            const double mid = 0.5 * (lo + hi);
            (oscillatorSpectralRadius(integrator, w, zeta, mid) > 1.0 + 1e-12 ? hi : lo) = mid;
          }
          return lo;
        }
        stable = h;
      }
      return stable;
    }
  }
  return 0.0;
}

double chainStabilityLimit(const SpringChain& chain, Integrator integrator) {
  double limit = kUnconditionallyStable;
  for (double w : chainModes(chain))
    limit = std::min(limit, oscillatorStabilityLimit(integrator, w, modeDampingRatio(chain, w)));
  return limit;
}

bool chainBlowsUp(const SpringChain& chain, Integrator integrator, double h, const ChainState& start,
                  double seconds, double factor) {
  ChainState s = start;
  const double e0 = chainEnergy(chain, start);
  const long long steps = static_cast<long long>(std::ceil(seconds / h));
  for (long long i = 0; i < steps; ++i) {
    stepChain(chain, integrator, h, s);
    const double e = chainEnergy(chain, s);
    if (!(e <= factor * e0)) return true;  // NaN counts as a blow-up
  }
  return false;
}

}  // namespace kinema
