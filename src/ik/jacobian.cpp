// Jacobian IK: the transpose (Buss's step length, or a line search on the true error),
// the SVD pseudo-inverse, damped least squares and selectively damped least squares, one
// JacobianStepper step per iteration (see jacobian_step.h).
#include "ik/ik_chain.h"
#include "ik/jacobian_step.h"

namespace kinema {

using ik_detail::IkChain;
using ik_detail::JacobianMethod;
using ik_detail::JacobianStepper;

namespace {

IkResult solveJacobian(JacobianMethod method, const IkProblem& problem, const IkSettings& settings) {
  IkChain& c = ik_detail::workspace();
  if (IkResult bad; !(bad.message = c.begin(problem, settings)).empty()) return bad;
  IkTrace* trace = settings.trace;
  JacobianStepper stepper(c, method);
  int it = 0;
  while (!c.converged(settings) && it < settings.maxIterations) {
    ++it;
    if (!stepper.step(c, settings)) break;
    c.record(trace, it, IkStep::JacobianStep);
    if (c.stalled(c.maxError(), settings)) break;
  }
  if (!c.converged(settings) && c.straightenIfUnreachable()) c.record(trace, it, IkStep::Straighten);
  return c.result(it, settings);
}

}  // namespace

IkResult solveJacobianTranspose(const IkProblem& problem, const IkSettings& settings) {
  return solveJacobian(JacobianMethod::Transpose, problem, settings);
}
IkResult solveJacobianPinv(const IkProblem& problem, const IkSettings& settings) {
  return solveJacobian(JacobianMethod::Pinv, problem, settings);
}
IkResult solveJacobianDls(const IkProblem& problem, const IkSettings& settings) {
  return solveJacobian(JacobianMethod::Dls, problem, settings);
}
IkResult solveJacobianSdls(const IkProblem& problem, const IkSettings& settings) {
  return solveJacobian(JacobianMethod::Sdls, problem, settings);
}

}  // namespace kinema
