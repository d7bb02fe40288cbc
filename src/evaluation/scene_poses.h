#pragma once
// A PoseSource (anim/pose_source.h) that evaluates a scene's clip through the one pipeline,
// for the jobs below it: retargeting a take, the simulation bakes, crowds. The jobs that
// simulate (spring bones, ragdolls) take it with stages.dynamics off: they are the dynamics.
#include "anim/pose_source.h"
#include "evaluation/scene_evaluation_job.h"

namespace kinema {

class ScenePoses final : public PoseSource {
 public:
  // scene.clips[clip] from the rest pose, with `stages` and the IK targets of `rig` (null:
  // scene.ik; the editor passes its document's); the scene and the rig must outlive this.
  ScenePoses(const Scene& scene, int clip, const EvaluationStages& stages = {}, const IkRig* rig = nullptr);
  void poseAt(double time, Pose& pose) override;

 private:
  const Scene& scene_;
  int clip_;
  EvaluationStages stages_;
  const IkRig* rig_;
  EvaluationContext context_;  // sampling cursors and the live chains' state between calls
};

}  // namespace kinema
