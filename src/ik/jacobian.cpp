// Jacobian IK: the analytic Jacobian (axis x (effector - joint) per rotational degree of
// freedom, the axis itself for orientation rows), one 3-row block per target, solved by
// the transpose (Buss's step length), the SVD pseudo-inverse, or damped least squares.
#include <Eigen/Dense>
#include <algorithm>

#include "ik/ik_chain.h"

namespace kinema {

using ik_detail::Goal;
using ik_detail::IkChain;

namespace {

enum class Method { Transpose, Pinv, Dls };

struct Dof {
  int slot;
  glm::vec3 axis;  // world axis, unit
};

// Rotation vector (axis * angle, angle in [0, pi]) of q.
glm::vec3 rotationVector(const glm::quat& qIn) {
  glm::quat q = safeNormalize(qIn);
  if (q.w < 0.0f) q = -q;
  const glm::vec3 v(q.x, q.y, q.z);
  const float s = glm::length(v);
  if (s < 1e-12f) return 2.0f * v;
  return v * (2.0f * std::atan2(s, q.w) / s);
}

bool inChain(const IkChain& c, int s, const Goal& g) {
  // s lies between the goal's root and its effector (inclusive).
  return s >= g.rootSlot && s < g.rootSlot + c.subtreeSize[g.rootSlot] && g.slot >= s &&
         g.slot < s + c.subtreeSize[s];
}

IkResult solveJacobian(Method method, const IkProblem& problem, const IkSettings& settings) {
  IkChain c;
  if (IkResult bad; !(bad.message = c.begin(problem, settings)).empty()) return bad;
  IkTrace* trace = settings.trace;
  const int m = static_cast<int>(c.joints.size());

  // Degrees of freedom: every slot that moves some effector (3 world axes, or its hinge
  // axis), plus effectors with an orientation target.
  std::vector<char> moves(m, 0);
  int rows = 0;
  float reach = 0.0f;
  for (const Goal& g : c.goals) {
    for (int s = c.parentSlot[g.slot]; s >= 0; s = c.parentSlot[s]) {
      moves[s] = 1;
      if (s == g.rootSlot) break;
    }
    if (g.hasOrientation) moves[g.slot] = 1;
    rows += g.hasOrientation ? 6 : 3;
    reach = std::max(reach, c.reach(g));
  }
  std::vector<Dof> dofs;
  const float lambda = settings.dlsLambda * std::max(reach, 1e-6f);
  // Buss & Kim clamp the error vector so each step stays in the linear regime.
  const float maxErrorStep = 0.5f * std::max(reach, 1e-6f);
  Eigen::MatrixXf j;
  Eigen::VectorXf e(rows), dtheta;
  int it = 0;
  while (!c.converged(settings) && it < settings.maxIterations) {
    ++it;
    dofs.clear();
    for (int s = 0; s < m; ++s) {
      if (!moves[s]) continue;
      const JointLimit* l = c.limit[s];
      if (l && l->type == JointLimitType::Hinge) {
        const glm::quat frame = c.parentRotation(s) * c.skeleton->rest[c.joints[s]].rotation;
        dofs.push_back({s, glm::normalize(frame * l->axis)});
      } else {
        dofs.push_back({s, glm::vec3(1.0f, 0.0f, 0.0f)});
        dofs.push_back({s, glm::vec3(0.0f, 1.0f, 0.0f)});
        dofs.push_back({s, glm::vec3(0.0f, 0.0f, 1.0f)});
      }
    }
    const int n = static_cast<int>(dofs.size());
    j.setZero(rows, n);
    int row = 0;
    for (const Goal& g : c.goals) {
      const float w = std::sqrt(g.weight);
      const glm::vec3 pe = c.position(g.slot);
      glm::vec3 err = g.position - pe;
      const float len = glm::length(err);
      if (len > maxErrorStep) err *= maxErrorStep / len;
      for (int k = 0; k < 3; ++k) e(row + k) = w * err[k];
      for (int d = 0; d < n; ++d) {
        if (!inChain(c, dofs[d].slot, g)) continue;
        const glm::vec3 col = glm::cross(dofs[d].axis, pe - c.position(dofs[d].slot));
        for (int k = 0; k < 3; ++k) j(row + k, d) = w * col[k];
      }
      row += 3;
      if (g.hasOrientation) {
        const glm::vec3 rv = rotationVector(g.orientation * glm::conjugate(c.rotation[g.slot]));
        for (int k = 0; k < 3; ++k) e(row + k) = w * rv[k];
        for (int d = 0; d < n; ++d)
          if (inChain(c, dofs[d].slot, g))
            for (int k = 0; k < 3; ++k) j(row + k, d) = w * dofs[d].axis[k];
        row += 3;
      }
    }
    switch (method) {
      case Method::Transpose: {
        // Buss: alpha = <e, J J^T e> / <J J^T e, J J^T e>, the best step along J^T e.
        const Eigen::VectorXf jte = j.transpose() * e;
        const Eigen::VectorXf jjte = j * jte;
        const float den = jjte.squaredNorm();
        dtheta = den > 0.0f ? Eigen::VectorXf((e.dot(jjte) / den) * jte) : Eigen::VectorXf::Zero(n);
        break;
      }
      case Method::Pinv: {
        Eigen::JacobiSVD<Eigen::MatrixXf> svd(j, Eigen::ComputeThinU | Eigen::ComputeThinV);
        const Eigen::VectorXf& sv = svd.singularValues();
        const float cut = settings.pinvThreshold * (sv.size() ? sv(0) : 0.0f);
        Eigen::VectorXf ute = svd.matrixU().transpose() * e;
        for (int i = 0; i < sv.size(); ++i) ute(i) = sv(i) > cut && sv(i) > 0.0f ? ute(i) / sv(i) : 0.0f;
        dtheta = svd.matrixV() * ute;
        break;
      }
      case Method::Dls: {
        // J^T (J J^T + lambda^2 I)^-1 e: a rows x rows solve, small for few targets.
        Eigen::MatrixXf a = j * j.transpose();
        a.diagonal().array() += lambda * lambda;
        dtheta = j.transpose() * a.ldlt().solve(e);
        break;
      }
    }
    if (!dtheta.allFinite()) break;
    // Keep every joint's turn within the step limit (scaling the whole step keeps its direction).
    const float maxTurn = std::min(settings.maxStepAngle, 0.5f);
    const float largest = dtheta.cwiseAbs().maxCoeff();
    if (largest > maxTurn) dtheta *= maxTurn / largest;
    // Children first, so each turn uses its joint's position from this linearisation.
    for (int d = n - 1; d >= 0;) {
      const int s = dofs[d].slot;
      glm::vec3 v(0.0f);
      while (d >= 0 && dofs[d].slot == s) {
        v += dofs[d].axis * dtheta(d);
        --d;
      }
      const float angle = glm::length(v);
      if (angle > 0.0f) c.rotateJoint(s, glm::angleAxis(angle, v / angle));
    }
    c.forwardKinematics();
    c.record(trace, it, IkStep::JacobianStep);
    if (c.stalled(c.maxError(), settings)) break;
  }
  if (!c.converged(settings) && c.straightenIfUnreachable()) c.record(trace, it, IkStep::Straighten);
  return c.result(it, settings);
}

}  // namespace

IkResult solveJacobianTranspose(const IkProblem& problem, const IkSettings& settings) {
  return solveJacobian(Method::Transpose, problem, settings);
}
IkResult solveJacobianPinv(const IkProblem& problem, const IkSettings& settings) {
  return solveJacobian(Method::Pinv, problem, settings);
}
IkResult solveJacobianDls(const IkProblem& problem, const IkSettings& settings) {
  return solveJacobian(Method::Dls, problem, settings);
}

}  // namespace kinema
