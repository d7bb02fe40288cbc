#include "evaluation/dynamics_stage.h"

#include <algorithm>

namespace kinema {

void applyDynamicChains(const Scene& scene, int clip, long long startFrame, long long frame, long long revision,
                        const std::function<void(long long frame, Pose& pose)>& animatedAt, DynamicsState& state,
                        Pose& pose) {
  const std::vector<SpringBoneChain>& chains = scene.simulation.springChains;
  if (chains.empty() || clip < 0 || clip >= static_cast<int>(scene.clips.size()) ||
      pose.size() != scene.skeleton.size()) {
    state.frame = LLONG_MIN;
    return;
  }
  const FrameGrid grid = scene.frameGrid(clip);
  frame = std::max(frame, startFrame);
  if (state.clip != clip || state.revision != revision || state.startFrame != startFrame || frame < state.frame) {
    state.springs.reset();
    state.clip = clip;
    state.revision = revision;
    state.startFrame = startFrame;
    state.frame = startFrame - 1;
    state.joints.clear();
    for (const SpringBoneChain& c : chains) state.joints.insert(state.joints.end(), c.joints.begin(), c.joints.end());
    state.rotations.assign(state.joints.size(), glm::quat(1, 0, 0, 0));
  }
  if (frame > state.frame) {
    SpringBoneJob job;
    Pose step = Pose::rest(scene.skeleton);
    job.skeleton = &scene.skeleton;
    job.chains = &chains;
    job.dt = static_cast<float>(grid.secondsPerFrame);
    job.pose = &step;
    job.state = &state.springs;
    if (!job.validate().empty()) return;
    for (long long f = state.frame + 1; f <= frame; ++f) {
      step = Pose::rest(scene.skeleton);
      animatedAt(f, step);
      job.run();
      ++state.framesSimulated;
    }
    for (size_t i = 0; i < state.joints.size(); ++i) state.rotations[i] = step.local[state.joints[i]].rotation;
    state.frame = frame;
  }
  for (size_t i = 0; i < state.joints.size(); ++i) pose.local[state.joints[i]].rotation = state.rotations[i];
}

}  // namespace kinema
