#pragma once
// Where a job below the evaluation pipeline gets the poses of the motion it works on
// (retargeting's source, the simulation bakes' input, crowds' members): ClipPoses samples the
// bare clip; evaluation/scene_poses.h evaluates the scene through the pipeline (modifiers,
// keyed IK targets, ...), which the CLI and the editor pass so every consumer sees the
// stages the editor shows. Poses are local, one transform per joint.
#include "anim/sampling.h"
#include "core/pose.h"

namespace kinema {

class PoseSource {
 public:
  virtual ~PoseSource() = default;
  // The pose at `time` (seconds of the clip's own time, finite; channels clamp to their
  // keys) into `pose`, which holds one transform per joint; joints the motion does not
  // animate are set to the source's base pose (the rest pose unless the source says).
  virtual void poseAt(double time, Pose& pose) = 0;
};

// The clip's keys alone (sampleClip over the rest pose, cursors kept between calls).
class ClipPoses final : public PoseSource {
 public:
  ClipPoses(const Skeleton& skeleton, const Clip& clip) : skeleton_(skeleton), clip_(clip) {}
  void poseAt(double time, Pose& pose) override;

 private:
  const Skeleton& skeleton_;
  const Clip& clip_;
  SamplingCache cache_;
};

}  // namespace kinema
