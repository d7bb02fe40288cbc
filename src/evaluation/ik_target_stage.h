#pragma once
// Stage 5 of the evaluation (evaluation/scene_evaluation_job.h): IK targets whose position
// the clip keys ("ik/targets/K/position.x|y|z" Scalar channels, anim/scalar_property.h).
#include <vector>

#include "anim/sampling.h"
#include "core/pose.h"
#include "scene/scene.h"

namespace kinema {

// The world positions (model space) at `time` of the saved IK targets that clip `clip` keys,
// one per target of `rig` (the scene's, Scene::ik, or the editor's as it saves it); `keyed[k]` is false for a target the clip does not key
// (its position is then the saved one). Components the clip does not key keep the saved
// value. An index that names no clip keys nothing.
void sampleIkTargetPositions(const Scene& scene, const IkRig& rig, int clip, double time,
                             std::vector<glm::vec3>& positions, std::vector<char>& keyed);

// Moves every keyed, active target (IkRig::targetOptions; active when it has none) to its
// keyed position and solves it on `pose` with its own solver, chain and the rig's joint limits,
// in target order, starting from the clip's pose (chain joints the clip does not rotate start
// at rest). Only local rotations of chain joints change. Returns how many were solved.
int solveKeyedIkTargets(const Scene& scene, const IkRig& rig, int clip, double time, Pose& pose);

}  // namespace kinema
