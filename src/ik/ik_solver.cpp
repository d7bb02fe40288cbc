#include "ik/ik_solver.h"

#include <cmath>

namespace kinema {

const char* toString(IkSolver solver) {
  switch (solver) {
    case IkSolver::TwoBone: return "two-bone";
    case IkSolver::Ccd: return "ccd";
    case IkSolver::Fabrik: return "fabrik";
    case IkSolver::JacobianTranspose: return "jacobian-transpose";
    case IkSolver::JacobianPinv: return "jacobian-pinv";
    case IkSolver::JacobianDls: return "jacobian-dls";
    case IkSolver::JacobianSdls: return "jacobian-sdls";
  }
  return "ccd";
}

std::optional<IkSolver> ikSolverFromString(const std::string& name) {
  for (IkSolver s : {IkSolver::TwoBone, IkSolver::Ccd, IkSolver::Fabrik, IkSolver::JacobianTranspose,
                     IkSolver::JacobianPinv, IkSolver::JacobianDls, IkSolver::JacobianSdls})
    if (name == toString(s)) return s;
  return std::nullopt;
}

const char* toString(IkStep step) {
  switch (step) {
    case IkStep::Start: return "start";
    case IkStep::CcdJoint: return "ccd-joint";
    case IkStep::FabrikBackward: return "fabrik-backward";
    case IkStep::FabrikForward: return "fabrik-forward";
    case IkStep::JacobianStep: return "jacobian-step";
    case IkStep::TwoBone: return "two-bone";
    case IkStep::Straighten: return "straighten";
  }
  return "start";
}

int ikRootOf(const Skeleton& skeleton, const IkTarget& target, bool twoBone) {
  if (target.root >= 0) return target.root;
  if (target.effector < 0 || target.effector >= skeleton.size()) return -1;
  int j = target.effector;
  if (twoBone) {
    const int mid = target.mid >= 0 ? target.mid : skeleton.parents[j];
    return mid >= 0 ? skeleton.parents[mid] : -1;
  }
  while (skeleton.parents[j] >= 0) j = skeleton.parents[j];
  return j;
}

std::string IkTarget::validate(const Skeleton& skeleton) const {
  const int n = skeleton.size();
  if (effector < 0 || effector >= n) return "effector joint " + std::to_string(effector) + " does not exist";
  const std::string& name = skeleton.names[effector];
  if (root >= n) return "root joint " + std::to_string(root) + " does not exist";
  if (root >= 0 && (root == effector || !skeleton.isInSubtree(effector, root)))
    return "IK root '" + skeleton.names[root] + "' is not an ancestor of effector '" + name + "'";
  if (root < 0 && skeleton.parents[effector] < 0) return "effector '" + name + "' has no parent joint to move";
  if (!isFinite(position)) return "target position for '" + name + "' is not finite";
  if (hasOrientation && (!isFinite(orientation) || glm::dot(orientation, orientation) < 1e-12f))
    return "target orientation for '" + name + "' is not a finite non-zero quaternion";
  if (!std::isfinite(weight) || !(weight > 0.0f)) return "target weight for '" + name + "' must be positive";
  if (hasPole && !isFinite(pole)) return "pole for '" + name + "' is not finite";
  if (mid >= n) return "middle joint " + std::to_string(mid) + " does not exist";
  return {};
}

std::string IkProblem::validate(bool twoBone) const {
  if (!skeleton || !pose) return "no skeleton or pose";
  const Skeleton& s = *skeleton;
  if (pose->size() != s.size())
    return "the pose has " + std::to_string(pose->size()) + " joints, the skeleton " + std::to_string(s.size());
  if (targets.empty()) return "no IK target";
  for (int i = 0; i < 4; ++i)
    if (!isFinite(glm::vec3(rootTransform[i]))) return "root transform is not finite";
  if (rig) {
    std::string bad = rig->validate(s);
    if (!bad.empty()) return bad;
  }
  for (const IkTarget& t : targets) {
    std::string bad = t.validate(s);
    if (!bad.empty()) return bad;
    const int root = ikRootOf(s, t, twoBone);
    if (twoBone) {
      const int mid = t.mid >= 0 ? t.mid : s.parents[t.effector];
      if (mid < 0 || mid == t.effector || !s.isInSubtree(t.effector, mid))
        return "two-bone: '" + s.names[t.effector] + "' needs a middle joint above it";
      if (root < 0 || root == mid || !s.isInSubtree(mid, root))
        return "two-bone: the root must lie above the middle joint '" + s.names[mid] + "'";
    }
    for (int j = t.effector; j >= 0; j = s.parents[j]) {
      if (!pose->local[j].isFinite()) return "pose of joint '" + s.names[j] + "' is not finite";
      if (j == root) break;
    }
  }
  return {};
}

std::string IkRig::validate(const Skeleton& skeleton) const {
  if (!limits.empty() && static_cast<int>(limits.size()) != skeleton.size())
    return "the IK rig has " + std::to_string(limits.size()) + " joint limits for " +
           std::to_string(skeleton.size()) + " joints";
  for (size_t i = 0; i < limits.size(); ++i) {
    const std::string bad = limits[i].validate();
    if (!bad.empty()) return "joint limit of '" + skeleton.names[i] + "': " + bad;
  }
  for (const IkTarget& t : targets) {
    const std::string bad = t.validate(skeleton);
    if (!bad.empty()) return bad;
  }
  return {};
}

IkResult solveIk(IkSolver solver, const IkProblem& problem, const IkSettings& settings) {
  switch (solver) {
    case IkSolver::TwoBone: return solveTwoBone(problem, settings);
    case IkSolver::Ccd: return solveCcd(problem, settings);
    case IkSolver::Fabrik: return solveFabrik(problem, settings);
    case IkSolver::JacobianTranspose: return solveJacobianTranspose(problem, settings);
    case IkSolver::JacobianPinv: return solveJacobianPinv(problem, settings);
    case IkSolver::JacobianDls: return solveJacobianDls(problem, settings);
    case IkSolver::JacobianSdls: return solveJacobianSdls(problem, settings);
  }
  return solveCcd(problem, settings);
}

}  // namespace kinema
