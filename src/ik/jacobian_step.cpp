#include "ik/jacobian_step.h"

#include <algorithm>
#include <cmath>

namespace kinema::ik_detail {

namespace {

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

// What the line search minimises: the weighted squared distance (and rotation) to every goal.
float objective(const IkChain& c) {
  float f = 0.0f;
  for (const Goal& g : c.goals) {
    const glm::vec3 d = g.position - c.position(g.slot);
    f += g.weight * glm::dot(d, d);
    if (g.hasOrientation) {
      const glm::vec3 r = rotationVector(g.orientation * glm::conjugate(c.rotation[g.slot]));
      f += g.weight * glm::dot(r, r);
    }
  }
  return f;
}

// Scales v so that its largest component is at most `limit` (Buss & Kim's ClampMaxAbs).
void clampMaxAbs(Eigen::VectorXf& v, float limit) {
  const float largest = v.size() ? v.cwiseAbs().maxCoeff() : 0.0f;
  if (largest > limit) v *= limit / largest;
}

}  // namespace

JacobianStepper::JacobianStepper(const IkChain& c, JacobianMethod method) : method_(method) {
  const int m = static_cast<int>(c.joints.size());
  moves_.assign(m, 0);
  for (const Goal& g : c.goals) {
    for (int s = c.parentSlot[g.slot]; s >= 0; s = c.parentSlot[s]) {
      moves_[s] = 1;
      if (s == g.rootSlot) break;
    }
    if (g.hasOrientation) moves_[g.slot] = 1;
    rows_ += g.hasOrientation ? 6 : 3;
    reach_ = std::max(reach_, c.reach(g));
  }
  reach_ = std::max(reach_, 1e-6f);
  e_.resize(rows_);
}

void JacobianStepper::build(const IkChain& c) {
  const int m = static_cast<int>(c.joints.size());
  // Degrees of freedom: 3 world axes per moving slot, or its hinge axis.
  dofs_.clear();
  for (int s = 0; s < m; ++s) {
    if (!moves_[s]) continue;
    const JointLimit* l = c.limit[s];
    if (l && l->type == JointLimitType::Hinge) {
      const glm::quat frame = c.parentRotation(s) * c.skeleton->rest[c.joints[s]].rotation;
      dofs_.push_back({s, glm::normalize(frame * l->axis)});
    } else {
      dofs_.push_back({s, glm::vec3(1.0f, 0.0f, 0.0f)});
      dofs_.push_back({s, glm::vec3(0.0f, 1.0f, 0.0f)});
      dofs_.push_back({s, glm::vec3(0.0f, 0.0f, 1.0f)});
    }
  }
  const int n = static_cast<int>(dofs_.size());
  // Buss & Kim clamp the error vector so each step stays in the linear regime.
  const float maxErrorStep = 0.5f * reach_;
  j_.setZero(rows_, n);
  int row = 0;
  for (const Goal& g : c.goals) {
    const float w = std::sqrt(g.weight);
    const glm::vec3 pe = c.position(g.slot);
    glm::vec3 err = g.position - pe;
    const float len = glm::length(err);
    if (len > maxErrorStep) err *= maxErrorStep / len;
    for (int k = 0; k < 3; ++k) e_(row + k) = w * err[k];
    for (int d = 0; d < n; ++d) {
      if (!inChain(c, dofs_[d].slot, g)) continue;
      const glm::vec3 col = glm::cross(dofs_[d].axis, pe - c.position(dofs_[d].slot));
      for (int k = 0; k < 3; ++k) j_(row + k, d) = w * col[k];
    }
    row += 3;
    if (g.hasOrientation) {
      const glm::vec3 rv = rotationVector(g.orientation * glm::conjugate(c.rotation[g.slot]));
      for (int k = 0; k < 3; ++k) e_(row + k) = w * rv[k];
      for (int d = 0; d < n; ++d)
        if (inChain(c, dofs_[d].slot, g))
          for (int k = 0; k < 3; ++k) j_(row + k, d) = w * dofs_[d].axis[k];
      row += 3;
    }
  }
}

void JacobianStepper::apply(IkChain& c, const Eigen::VectorXf& dthetaIn) {
  Eigen::VectorXf dtheta = dthetaIn;
  // Keep every joint's turn within the step limit (scaling the whole step keeps its direction).
  clampMaxAbs(dtheta, std::min(maxStep_, 0.5f));
  // Children first, so each turn uses its joint's position from this linearisation.
  for (int d = static_cast<int>(dofs_.size()) - 1; d >= 0;) {
    const int s = dofs_[d].slot;
    glm::vec3 v(0.0f);
    while (d >= 0 && dofs_[d].slot == s) {
      v += dofs_[d].axis * dtheta(d);
      --d;
    }
    const float angle = glm::length(v);
    if (angle > 0.0f) c.rotateJoint(s, glm::angleAxis(angle, v / angle));
  }
  c.forwardKinematics();
}

// Backtracking (and, while it pays, expanding) search along `direction` from Buss's step
// `alpha`, on the true error rather than its linearisation. Leaves the best trial applied;
// false when no trial step lowered the error (nothing is changed then).
bool JacobianStepper::lineSearch(IkChain& c, const Eigen::VectorXf& direction, float alpha) {
  const int m = static_cast<int>(c.joints.size());
  saved_.resize(m);
  for (int s = 0; s < m; ++s) saved_[s] = c.pose->local[c.joints[s]].rotation;
  auto restore = [&] {
    for (int s = 0; s < m; ++s) c.pose->local[c.joints[s]].rotation = saved_[s];
    c.forwardKinematics();
  };
  const float f0 = objective(c);
  auto trial = [&](float a) {
    apply(c, a * direction);
    const float f = objective(c);
    restore();
    return f;
  };
  float best = alpha, fBest = trial(alpha);
  if (fBest < f0) {
    for (int k = 0; k < 4; ++k) {  // expand while it keeps improving
      const float f = trial(2.0f * best);
      if (!(f < fBest)) break;
      best *= 2.0f;
      fBest = f;
    }
  } else {
    for (int k = 0; k < 12 && !(fBest < f0); ++k) {  // halve until it improves
      best *= 0.5f;
      fBest = trial(best);
    }
    if (!(fBest < f0)) return false;
  }
  apply(c, best * direction);
  return true;
}

Eigen::VectorXf JacobianStepper::sdls() const {
  // Buss & Kim 2005: each singular direction gets its own damping, the smaller the more
  // its joint turns would move the effectors (M_i) compared with what it asks of them (N_i).
  constexpr float kGammaMax = glm::pi<float>() / 4.0f;
  const int n = static_cast<int>(j_.cols());
  const int blocks = rows_ / 3;
  Eigen::JacobiSVD<Eigen::MatrixXf> svd(j_, Eigen::ComputeThinU | Eigen::ComputeThinV);
  const Eigen::VectorXf& sv = svd.singularValues();
  const Eigen::MatrixXf& u = svd.matrixU();
  const Eigen::MatrixXf& v = svd.matrixV();
  // rho_j: how far one radian of dof j moves all the effectors together.
  Eigen::VectorXf rho = Eigen::VectorXf::Zero(n);
  for (int d = 0; d < n; ++d)
    for (int b = 0; b < blocks; ++b) rho(d) += j_.block<3, 1>(3 * b, d).norm();
  Eigen::VectorXf total = Eigen::VectorXf::Zero(n);
  const float cut = 1e-6f * (sv.size() ? sv(0) : 0.0f);
  for (int i = 0; i < sv.size(); ++i) {
    if (!(sv(i) > cut)) continue;
    const float alpha = u.col(i).dot(e_);
    float nI = 0.0f;
    for (int b = 0; b < blocks; ++b) nI += u.block(3 * b, i, 3, 1).norm();
    const float mI = v.col(i).cwiseAbs().dot(rho) / sv(i);
    const float gamma = (mI > nI ? nI / mI : 1.0f) * kGammaMax;
    Eigen::VectorXf phi = (alpha / sv(i)) * v.col(i);
    clampMaxAbs(phi, gamma);
    total += phi;
  }
  clampMaxAbs(total, kGammaMax);
  return total;
}

bool JacobianStepper::step(IkChain& c, const IkSettings& settings) {
  build(c);
  const int n = static_cast<int>(dofs_.size());
  maxStep_ = settings.maxStepAngle;
  Eigen::VectorXf dtheta;
  switch (method_) {
    case JacobianMethod::Transpose: {
      // Buss: alpha = <e, J J^T e> / <J J^T e, J J^T e>, the best step along J^T e for
      // the linearised error; the line search then measures the true error instead.
      const Eigen::VectorXf jte = j_.transpose() * e_;
      const Eigen::VectorXf jjte = j_ * jte;
      const float den = jjte.squaredNorm();
      const float alpha = den > 0.0f ? e_.dot(jjte) / den : 0.0f;
      if (!jte.allFinite() || !std::isfinite(alpha)) return false;
      if (settings.transposeLineSearch) return alpha > 0.0f ? lineSearch(c, jte, alpha) : false;
      dtheta = alpha * jte;
      break;
    }
    case JacobianMethod::Pinv: {
      Eigen::JacobiSVD<Eigen::MatrixXf> svd(j_, Eigen::ComputeThinU | Eigen::ComputeThinV);
      const Eigen::VectorXf& sv = svd.singularValues();
      const float cut = settings.pinvThreshold * (sv.size() ? sv(0) : 0.0f);
      Eigen::VectorXf ute = svd.matrixU().transpose() * e_;
      for (int i = 0; i < sv.size(); ++i) ute(i) = sv(i) > cut && sv(i) > 0.0f ? ute(i) / sv(i) : 0.0f;
      dtheta = svd.matrixV() * ute;
      break;
    }
    case JacobianMethod::Dls: {
      // J^T (J J^T + lambda^2 I)^-1 e: a rows x rows solve, small for few targets.
      const float lambda = settings.dlsLambda * reach_;
      Eigen::MatrixXf a = j_ * j_.transpose();
      a.diagonal().array() += lambda * lambda;
      dtheta = j_.transpose() * a.ldlt().solve(e_);
      break;
    }
    case JacobianMethod::Sdls: dtheta = sdls(); break;
  }
  if (dtheta.size() != n || !dtheta.allFinite()) return false;
  apply(c, dtheta);
  return true;
}

}  // namespace kinema::ik_detail
