#include "evaluation/scene_poses.h"

namespace kinema {

ScenePoses::ScenePoses(const Scene& scene, int clip, const EvaluationStages& stages, const IkRig* rig)
    : scene_(scene), clip_(clip), stages_(stages), rig_(rig) {}

void ScenePoses::poseAt(double time, Pose& pose) {
  SceneEvaluationJob job;
  job.scene = &scene_;
  job.clip = clip_;
  job.time = time;
  job.stages = stages_;
  job.rig = rig_;
  job.context = &context_;
  job.pose = &pose;
  job.run();
}

}  // namespace kinema
