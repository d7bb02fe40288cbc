#pragma once
// The plain evaluation the sampling fast paths are held to: every channel through
// sampleChannelReference (binary search, normalised keys, slerp by acos and sin), applied in
// clip order onto a base pose, and the largest component difference between two poses.
#include "anim/clip.h"

namespace kinema::test {

// `base` with each channel's reference value at `time` written in clip order (the last channel
// of a part wins, as in sampleClip); Scalar channels, joints outside the pose and channels
// without keys are skipped.
Pose referencePose(const Clip& clip, const Pose& base, float time);

// The largest absolute difference of any translation, rotation or scale component.
float maxPoseDifference(const Pose& a, const Pose& b);

}  // namespace kinema::test
