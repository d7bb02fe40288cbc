// The four integrators against closed forms (seed 003, 16.5): on an undamped oscillator
// explicit Euler multiplies the energy by exactly 1 + w^2 h^2 per step and backward Euler
// divides it by the same; symplectic Euler and velocity Verlet keep their modified energies to
// rounding, so the energy stays in a derived band. On a damped chain the first time step that
// blows up (energy above 10x within 5 s) is within 5 % of each scheme's derived limit.
#include "sim/integrators.h"

#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <cmath>

namespace kinema {
namespace KINEMA_UNITY_ID {

SpringChain oneMass(double k, double m) {
  SpringChain c;
  c.masses = 1;
  c.mass = m;
  c.stiffness = k;
  c.beta = 0.0;
  return c;
}

ChainState state1(double x, double v) { return ChainState{{x}, {v}}; }

TEST(Integrators, ExplicitEulerGrowsAndBackwardEulerShrinksEnergyByOnePlusW2H2) {
  const SpringChain c = oneMass(400.0, 2.0);  // w^2 = 200
  for (double h : {0.001, 0.01, 0.05}) {
    const double factor = 1.0 + 200.0 * h * h;
    ChainState fwd = state1(0.1, -0.3), bwd = fwd;
    double eF = chainEnergy(c, fwd), eB = eF;
    for (int step = 0; step < 50; ++step) {
      stepChain(c, Integrator::ExplicitEuler, h, fwd);
      stepChain(c, Integrator::ImplicitEuler, h, bwd);
      const double nF = chainEnergy(c, fwd), nB = chainEnergy(c, bwd);
      EXPECT_NEAR(nF / eF, factor, 1e-12 * factor) << "h=" << h << " step " << step;
      EXPECT_NEAR(nB / eB, 1.0 / factor, 1e-12) << "h=" << h << " step " << step;
      eF = nF;
      eB = nB;
    }
  }
}

TEST(Integrators, SymplecticEulerAndVerletKeepTheirModifiedEnergies) {
  const double k = 900.0, m = 1.0, w = 30.0;
  const SpringChain c = oneMass(k, m);
  for (double h : {0.002, 0.02, 0.06}) {  // w h = 0.06, 0.6, 1.8 (all below 2)
    const double wh = w * h;
    ChainState se = state1(0.05, 0.7), vv = se;
    const double e0 = chainEnergy(c, se);
    auto qSymplectic = [&](const ChainState& s) {  // v^2 + w^2 x^2 - h w^2 x v
      return s.v[0] * s.v[0] + w * w * s.x[0] * s.x[0] - h * w * w * s.x[0] * s.v[0];
    };
    auto qVerlet = [&](const ChainState& s) {  // v^2 + w^2 x^2 (1 - (w h)^2 / 4)
      return s.v[0] * s.v[0] + w * w * s.x[0] * s.x[0] * (1.0 - wh * wh / 4.0);
    };
    const double q0s = qSymplectic(se), q0v = qVerlet(vv);
    // |h w^2 x v| <= (w h / 2)(v^2 + w^2 x^2), so E / E0 stays within these bands.
    const double hiS = (1 + wh / 2) / (1 - wh / 2 > 0 ? 1 - wh / 2 : 1e-300);
    const double loV = 1.0 - wh * wh / 4.0;
    for (int step = 0; step < 20000; ++step) {
      stepChain(c, Integrator::SymplecticEuler, h, se);
      stepChain(c, Integrator::Verlet, h, vv);
      ASSERT_NEAR(qSymplectic(se) / q0s, 1.0, 1e-9) << "h=" << h << " step " << step;
      ASSERT_NEAR(qVerlet(vv) / q0v, 1.0, 1e-9) << "h=" << h << " step " << step;
      const double rs = chainEnergy(c, se) / e0, rv = chainEnergy(c, vv) / e0;
      if (wh < 2.0) {
        if (1 - wh / 2 > 0) {
          ASSERT_LE(rs, hiS * (1 + 1e-9));
          ASSERT_GE(rs, (1 / hiS) * (1 - 1e-9));
        }
        ASSERT_LE(rv, (1.0 / loV) * (1 + 1e-9));
        ASSERT_GE(rv, loV * (1 - 1e-9));
      }
    }
  }
}

TEST(Integrators, ChainModesMatchTheStiffnessMatrixsEigenvalues) {
  for (int n : {1, 2, 5, 12}) {
    SpringChain c;
    c.masses = n;
    c.mass = 0.5;
    c.stiffness = 300.0;
    Eigen::MatrixXd k = Eigen::MatrixXd::Zero(n, n);
    for (int i = 0; i < n; ++i) {  // spring i joins mass i to mass i-1 (the anchor for i = 0)
      k(i, i) += c.stiffness;
      if (i > 0) {
        k(i - 1, i - 1) += c.stiffness;
        k(i, i - 1) -= c.stiffness;
        k(i - 1, i) -= c.stiffness;
      }
    }
    Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eig(k / c.mass);
    const std::vector<double> w = chainModes(c);
    for (int j = 0; j < n; ++j) EXPECT_NEAR(w[j], std::sqrt(eig.eigenvalues()[j]), 1e-9 * w[j]) << n << " " << j;
  }
}

// The closed-form limits against a plain scan of the step matrix's spectral radius.
TEST(Integrators, ClosedFormLimitsAgreeWithTheStepMatrix) {
  for (Integrator s : {Integrator::ExplicitEuler, Integrator::SymplecticEuler, Integrator::Verlet})
    for (double zeta : {0.0, 0.05, 0.3, 0.9}) {
      if (s == Integrator::ExplicitEuler && zeta == 0.0) continue;  // unstable at every step
      const double w = 40.0;
      const double limit = oscillatorStabilityLimit(s, w, zeta);
      double scanned = 0.0;
      for (int i = 1; i <= 200000; ++i) {
        const double h = 5.0 / w * i / 200000;
        if (oscillatorSpectralRadius(s, w, zeta, h) > 1.0 + 1e-12) break;
        scanned = h;
      }
      EXPECT_NEAR(scanned, limit, 3e-5 / w + 1e-6 * limit) << toString(s) << " zeta " << zeta;
    }
  EXPECT_NEAR(oscillatorStabilityLimit(Integrator::ExplicitEuler, 10.0, 0.2), 0.04, 1e-15);
  EXPECT_NEAR(oscillatorStabilityLimit(Integrator::SymplecticEuler, 10.0, 0.0), 0.2, 1e-15);
  EXPECT_NEAR(oscillatorStabilityLimit(Integrator::Verlet, 10.0, 0.0), 0.2, 1e-15);
  EXPECT_EQ(oscillatorStabilityLimit(Integrator::ImplicitEuler, 10.0, 0.2), kUnconditionallyStable);
  for (double h : {0.01, 1.0, 100.0}) EXPECT_LT(oscillatorSpectralRadius(Integrator::ImplicitEuler, 10.0, 0.0, h), 1.0);
}

// The damped chain the demo draws: 10 masses, highest mode near 100 rad/s with damping
// ratio 0.3. Measured on a 1 % grid of steps, the first that blows up lies within 5 % above
// the derived limit, and 5 % below it the energy only falls.
TEST(Integrators, TheMeasuredBlowUpStepMatchesTheDerivedLimit) {
  SpringChain c;
  c.masses = 10;
  c.mass = 1.0;
  c.stiffness = 2500.0;
  c.beta = betaForHighestModeRatio(c, 0.3);
  EXPECT_NEAR(modeDampingRatio(c, chainModes(c).back()), 0.3, 1e-12);
  ChainState start;
  start.x.assign(10, 0.0);
  start.v.assign(10, 0.0);
  start.x[9] = 0.01;  // the tip pulled down: every mode starts moving
  for (Integrator s : {Integrator::ExplicitEuler, Integrator::SymplecticEuler, Integrator::Verlet}) {
    const double limit = chainStabilityLimit(c, s);
    ASSERT_TRUE(std::isfinite(limit) && limit > 0.0) << toString(s);
    EXPECT_FALSE(chainBlowsUp(c, s, 0.95 * limit, start)) << toString(s);
    double measured = 0.0;
    for (int pct = 90; pct <= 150; ++pct)
      if (chainBlowsUp(c, s, limit * pct / 100.0, start)) {
        measured = limit * pct / 100.0;
        break;
      }
    EXPECT_GE(measured, limit) << toString(s);
    EXPECT_LE(measured, 1.05 * limit) << toString(s) << ": measured " << measured << ", derived " << limit;
  }
  // Explicit Euler's limit is 2 zeta / w_max = beta here, the same for every mode.
  EXPECT_NEAR(chainStabilityLimit(c, Integrator::ExplicitEuler), c.beta, 1e-12);
  // Backward Euler never blows up, even at 100x explicit Euler's limit, and loses energy.
  const double big = 100.0 * c.beta;
  EXPECT_FALSE(chainBlowsUp(c, Integrator::ImplicitEuler, big, start, 5.0, 1.0));
}

TEST(Integrators, NamesAndBadChains) {
  Integrator i;
  ASSERT_TRUE(fromString("verlet", i));
  EXPECT_EQ(i, Integrator::Verlet);
  EXPECT_FALSE(fromString("rk4", i));
  SpringChain c;
  EXPECT_EQ(c.validate(), "");
  c.masses = 0;
  EXPECT_NE(c.validate(), "");
  c = SpringChain{};
  c.beta = -1.0;
  EXPECT_NE(c.validate().find("beta"), std::string::npos);
}

}  // namespace
}  // namespace kinema
