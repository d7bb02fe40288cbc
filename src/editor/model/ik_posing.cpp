#include "editor/model/ik_posing.h"

#include <chrono>

#include "core/forward_kinematics.h"
#include "editor/model/edit_labels.h"
#include "core/rotation.h"

namespace kinema {

glm::vec3 effectorPosition(const Document& doc, int joint) {
  if (joint < 0 || joint >= doc.skeleton().size()) return glm::vec3(0.0f);
  return glm::vec3(doc.worldTransforms()[joint][3]);
}

std::string beginIkTargetDrag(Document& doc, int target) {
  if (target < 0 || target >= static_cast<int>(doc.ikTargets().size()))
    return "no IK target " + std::to_string(target);
  const std::string error = doc.beginDrag("Move IK target of " + jointsPhrase(doc.skeleton(), {doc.ikTargets()[target].target.effector}));
  if (error.empty()) doc.setDrivenIkTarget(target);
  return error;
}

std::string updateIkTargetDrag(Document& doc, int target, const glm::vec3& position) {
  if (!(std::isfinite(position.x) && std::isfinite(position.y) && std::isfinite(position.z)))
    return "the target position is not finite";
  if (target < 0 || target >= static_cast<int>(doc.ikTargets().size()))
    return "no IK target " + std::to_string(target);
  doc.setDrivenIkTarget(target);
  return doc.updateDrag([&](DocumentEdit& e) {
    e.targets[target].target.position = position;
    return std::string();
  });
}

std::string beginAutoIkDrag(Document& doc, int joint, int chainLength, IkSolver solver) {
  const Skeleton& s = doc.skeleton();
  if (joint < 0 || joint >= s.size()) return "no joint " + std::to_string(joint);
  if (s.parents[joint] < 0) return "'" + s.names[joint] + "' has no parent for auto-IK to move";
  if (chainLength < 1) return "the auto-IK chain length must be at least 1";
  PoseIkTarget t;
  t.target.effector = joint;
  t.target.position = effectorPosition(doc, joint);
  int depth = 0;
  for (int j = s.parents[joint]; j >= 0; j = s.parents[j]) ++depth;
  t.chainLength = std::min(chainLength, depth);
  t.solver = solver;
  // Two-bone needs exactly two bones; otherwise use DLS, which handles any length.
  if (solver == IkSolver::TwoBone && t.chainLength != 2) t.solver = IkSolver::JacobianDls;
  const std::string error = doc.beginDrag("Move " + s.names[joint] + " by auto IK");
  if (!error.empty()) return error;
  doc.setTemporaryIkTarget(t);
  return {};
}

std::string updateAutoIkDrag(Document& doc, const glm::vec3& position) {
  if (!doc.dragging() || !doc.temporaryIkTarget()) return "no auto-IK drag in progress";
  if (!(std::isfinite(position.x) && std::isfinite(position.y) && std::isfinite(position.z)))
    return "the target position is not finite";
  PoseIkTarget t = *doc.temporaryIkTarget();
  t.target.position = position;
  doc.setTemporaryIkTarget(t);
  return doc.updateDrag([](DocumentEdit&) { return std::string(); });
}

}  // namespace kinema
