#pragma once
#include <string>
#include <vector>

#include "core/pose.h"

namespace kinema {

// What a channel animates on its joint.
enum class ChannelTarget { Translation, Rotation, Scale };
// How values between two keys are found. The keyframe engine adds the cubic modes.
enum class Interpolation { Step, Linear };

const char* toString(ChannelTarget target);
const char* toString(Interpolation interpolation);

// One animated property of one joint, with its own key times.
struct Channel {
  int joint = -1;
  ChannelTarget target = ChannelTarget::Rotation;
  Interpolation interpolation = Interpolation::Linear;
  std::vector<float> times;        // seconds, strictly increasing
  std::vector<glm::vec4> values;   // one per key: (x, y, z, -) or a quaternion (x, y, z, w)

  float startTime() const { return times.empty() ? 0.0f : times.front(); }
  float endTime() const { return times.empty() ? 0.0f : times.back(); }
};

struct Clip {
  std::string name;
  std::vector<Channel> channels;
  // Seconds per frame for frame-based sources (BVH); 0 when the clip has no frame grid.
  double frameTime = 0.0;

  // The last key time over all channels (clips start at time 0).
  float duration() const;
  // Time of frame N, computed the same way as the keys of frame-based clips, so that
  // sampling at it returns that frame's values exactly.
  float frameToTime(long long frame) const;
  // Empty when every channel names a joint of the skeleton, times are finite and strictly
  // increasing, and values are finite (one per key).
  std::string validate(const Skeleton& skeleton) const;
};

// Writes the clip's value at `time` into pose (which holds the rest pose or another
// base for joints the clip does not animate). Time is clamped to each channel's keys:
// before the first key it holds the first value, after the last key the last value.
// Rotations are normalised and interpolated along the shortest arc.
void sampleClip(const Clip& clip, float time, Pose& pose);

}  // namespace kinema
