#pragma once
#include <optional>
#include <string>
#include <vector>

#include "anim/clip.h"

namespace kinema {

// What the editor's I key does: keys the chosen joints' local transforms from `pose` at
// `time`, into existing channels of the clip or new ones.
struct InsertKeyframeJob {
  std::vector<int> joints;
  bool translation = true, rotation = true, scale = false;
  float time = 0.0f;
  // When set, every key written carries these settings (the editor's key preferences):
  // `settings` for translation, scale and Euler keys, `rotationSettings` for quaternion
  // keys (whose interpolation must suit rotations). Unset: the defaults described below.
  std::optional<KeySettings> settings, rotationSettings;

  std::string validate(const Skeleton& skeleton, const Pose& pose) const;
};

// New channels get Bezier keys with auto-clamped handles (rotations too: quaternion
// components, as Blender keys them): automatic handles, so two keys ease in and out and
// inserting a key between others keeps the motion smooth. A key inserted into an existing channel takes the settings of the key it
// follows. Rotation keys take the sign nearest the previous key; Euler keys are unwrapped
// to within pi of it. Returns the number of keys written.
int insertKeyframe(Clip& clip, const InsertKeyframeJob& job, const Pose& pose);

}  // namespace kinema
