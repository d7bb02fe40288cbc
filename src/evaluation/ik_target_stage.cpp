#include "evaluation/ik_target_stage.h"

#include "anim/channel_modifiers.h"
#include "anim/scalar_property.h"
#include "ik/ik_solver.h"

namespace kinema {

void sampleIkTargetPositions(const Scene& scene, const IkRig& rig, int clip, double time,
                             std::vector<glm::vec3>& positions, std::vector<char>& keyed) {
  const std::vector<IkTarget>& targets = rig.targets;
  positions.resize(targets.size());
  keyed.assign(targets.size(), 0);
  for (size_t k = 0; k < targets.size(); ++k) positions[k] = targets[k].position;
  if (clip < 0 || clip >= static_cast<int>(scene.clips.size()) || targets.empty()) return;
  for (const Channel& ch : scene.clips[clip].channels) {
    if (ch.target != ChannelTarget::Scalar || ch.times.empty()) continue;
    const ScalarProperty p = parseScalarProperty(ch.property);
    if (p.kind != ScalarPropertyKind::IkTargetPosition || p.ikTarget >= static_cast<int>(targets.size())) continue;
    positions[p.ikTarget][p.component] = sampleModifiedChannel(ch, static_cast<float>(time)).x;
    keyed[p.ikTarget] = 1;
  }
}

namespace {
bool rotationKeyed(const Scene& scene, int clip, int joint) {
  for (const Channel& ch : scene.clips[clip].channels)
    if (ch.joint == joint && (ch.target == ChannelTarget::Rotation || ch.target == ChannelTarget::Euler)) return true;
  return false;
}
}  // namespace

int solveKeyedIkTargets(const Scene& scene, const IkRig& rig, int clip, double time, Pose& pose) {
  std::vector<glm::vec3> positions;
  std::vector<char> keyed;
  sampleIkTargetPositions(scene, rig, clip, time, positions, keyed);
  const Skeleton& s = scene.skeleton;
  int solved = 0;
  for (size_t k = 0; k < positions.size(); ++k) {
    if (!keyed[k]) continue;
    IkTargetOptions options;
    if (k < rig.targetOptions.size()) options = rig.targetOptions[k];
    if (!options.active) continue;
    IkTarget target = rig.targets[k];
    target.position = positions[k];
    // A chain length decides the root as in the editor (Blender's chain length).
    if (options.chainLength > 0 && target.effector >= 0 && target.effector < s.size()) {
      int root = target.effector;
      for (int n = 0; n < options.chainLength && s.parents[root] >= 0; ++n) root = s.parents[root];
      target.root = root;
    }
    if (!target.validate(s).empty()) continue;
    // The solve starts from the clip's pose: chain joints whose rotation the clip does not key
    // start at rest, not where a previous evaluation's solve left them (the editor's working
    // pose), so a frame solves the same however it was reached.
    const int root = ikRootOf(s, target, options.solver == IkSolver::TwoBone);
    for (int j = s.parents[target.effector]; j >= 0; j = s.parents[j]) {
      if (!rotationKeyed(scene, clip, j)) pose.local[j].rotation = s.rest[j].rotation;
      if (j == root) break;
    }
    IkProblem problem;
    problem.skeleton = &s;
    problem.pose = &pose;
    problem.rig = &rig;
    problem.targets = {target};
    if (!problem.validate(options.solver == IkSolver::TwoBone).empty()) continue;
    solveIk(options.solver, problem, IkSettings{});
    ++solved;
  }
  return solved;
}

}  // namespace kinema
