#pragma once
// Stage 6 of the evaluation (evaluation/scene_evaluation_job.h): the scene's dynamic chains
// (spring bones, Scene::simulation.springChains) played live over the animated pose.
#include <climits>
#include <functional>
#include <vector>

#include "core/math.h"
#include "core/pose.h"
#include "scene/scene.h"
#include "sim/spring_bones.h"

namespace kinema {

// What the live chains carry from one evaluated frame to the next; owned by the caller
// (the editor keeps one across frames; a one-off evaluation may pass a fresh one).
struct DynamicsState {
  SpringBoneState springs;
  int clip = -1;
  long long revision = -1, startFrame = LLONG_MIN, frame = LLONG_MIN;
  std::vector<int> joints;            // the chains' joints
  std::vector<glm::quat> rotations;   // their simulated local rotations at `frame`
  long long framesSimulated = 0;      // total, for tests and the editor's state dump
};

// Whole frame `frame` (clamped up to `startFrame`) of clip `clip` on its grid
// (Scene::frameGrid): the chains simulated one step per frame from `startFrame` at rest, each
// step driven by `animatedAt(f, pose)` (stages 1 to 5 at frame f, from the rest pose), and
// their local rotations written into `pose`. A frame after the state's reuses its simulation
// (playback is one step a frame); another clip, `revision` (the caller's count of scene
// edits), start frame, or an earlier frame simulates again from the start. Nothing without
// chains or clip: `state` is then forgotten.
void applyDynamicChains(const Scene& scene, int clip, long long startFrame, long long frame, long long revision,
                        const std::function<void(long long frame, Pose& pose)>& animatedAt, DynamicsState& state,
                        Pose& pose);

}  // namespace kinema
