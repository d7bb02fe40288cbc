#include "anim/pose_source.h"

namespace kinema {

void ClipPoses::poseAt(double time, Pose& pose) {
  pose.local.assign(skeleton_.rest.begin(), skeleton_.rest.end());  // keeps its memory
  sampleClip(clip_, static_cast<float>(time), pose, cache_);
}

}  // namespace kinema
