#include "ik/ik_solver.h"

#include <cmath>

#include "ik/ik_chain.h"

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

namespace {

using ik_detail::finiteFloats;
using ik_detail::finiteTransform;

// One target of a problem whose skeleton, pose and placement passed: true only where
// IkTarget::validate and IkProblem::validate's per-target checks would all pass, in one
// walk from the effector up (the checks' own walks are isInSubtree, ikRootOf and the
// pose loop). False also in cases that may be valid but are not the common ones; the
// caller then runs the full checks, which give the message.
bool plainTarget(const Skeleton& s, const Pose& pose, const IkTarget& t, bool twoBone) {
  const int n = s.size();
  if (t.effector < 0 || t.effector >= n || t.root >= n || t.mid >= n) return false;
  if (!finiteFloats(&t.position.x, 3) || !std::isfinite(t.weight) || !(t.weight > 0.0f)) return false;
  if (t.hasOrientation &&
      (!finiteFloats(&t.orientation.x, 4) || !(glm::dot(t.orientation, t.orientation) >= 1e-12f)))
    return false;
  if (t.hasPole && !finiteFloats(&t.pole.x, 3)) return false;
  const int* parents = s.parents.data();
  const Transform* local = pose.local.data();
  if (!finiteTransform(local[t.effector])) return false;
  int j = t.effector;
  if (twoBone) {
    // The middle joint: given, or the effector's parent; a proper ancestor either way.
    const int mid = t.mid >= 0 ? t.mid : parents[j];
    if (mid < 0 || mid == j) return false;
    do {
      j = parents[j];
      if (j < 0 || !finiteTransform(local[j])) return false;
    } while (j != mid);
    // The root: given, or the middle joint's parent; a proper ancestor of the middle.
    const int root = t.root >= 0 ? t.root : parents[mid];
    if (root < 0 || root == mid) return false;
    do {
      j = parents[j];
      if (j < 0 || !finiteTransform(local[j])) return false;
    } while (j != root);
    return true;
  }
  if (t.root >= 0) {
    if (t.root == j) return false;
    do {
      j = parents[j];
      if (j < 0 || !finiteTransform(local[j])) return false;
    } while (j != t.root);
    return true;
  }
  if (parents[j] < 0) return false;  // no parent joint to move
  for (j = parents[j]; j >= 0; j = parents[j])
    if (!finiteTransform(local[j])) return false;
  return true;
}

// The whole problem, without a rig (a rig goes through the full checks).
bool plainProblem(const IkProblem& p, bool twoBone) {
  if (!p.skeleton || !p.pose || p.rig || p.targets.empty() || p.pose->size() != p.skeleton->size()) return false;
  if (!ik_detail::finitePlacement(p.rootTransform)) return false;
  for (const IkTarget& t : p.targets)
    if (!plainTarget(*p.skeleton, *p.pose, t, twoBone)) return false;
  return true;
}

}  // namespace

std::string IkProblem::validate(bool twoBone) const {
  // The common case (every check passes) without building any message.
  if (plainProblem(*this, twoBone)) return {};
  return ik_detail::validateInFull(*this, twoBone);
}

namespace ik_detail {

bool plainlyValid(const IkProblem& problem, bool twoBone) { return plainProblem(problem, twoBone); }

std::string validateInFull(const IkProblem& problem, bool twoBone) {
  const Skeleton* skeleton = problem.skeleton;
  const Pose* pose = problem.pose;
  const IkRig* rig = problem.rig;
  const std::vector<IkTarget>& targets = problem.targets;
  const glm::mat4& rootTransform = problem.rootTransform;
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

}  // namespace ik_detail

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
