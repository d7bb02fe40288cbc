#pragma once
#include <vector>

#include "anim/clip.h"
#include "core/rotation.h"

namespace kinema {

// Cursors for sequential playback: one per channel, the index of the first key after the
// last sampled time. Reusing a cache makes playback O(1) per channel (the cursor is
// checked, then advanced by one segment); a jump anywhere else falls back to a binary
// search. The cache only speeds sampling up: results never depend on it.
struct SamplingCache {
  std::vector<int> cursors;
};

// A sampled value `v` of `ch` into its joint's local transform `t` (rotations are unit
// [x, y, z, w] already; Scalar channels belong to no transform and leave it alone).
inline void applyChannelValue(const Channel& ch, const glm::vec4& v, Transform& t) {
  switch (ch.target) {
    case ChannelTarget::Translation: t.translation = glm::vec3(v); break;
    case ChannelTarget::Scale: t.scale = glm::vec3(v); break;
    case ChannelTarget::Rotation: t.rotation = glm::quat(v.w, v.x, v.y, v.z); break;
    case ChannelTarget::Euler: t.rotation = eulerToQuat(glm::vec3(v), ch.eulerOrder); break;
    case ChannelTarget::Scalar: break;
  }
}

// The index of the first key after `time` (0: before the first key; keyCount(): at or
// after the last), using and updating `cursor` when given.
int upperKey(const Channel& channel, float time, int* cursor = nullptr);

// The channel's value at `time`, clamped to its keys: (x, y, z, -) for translation, scale
// and Euler angles, a unit quaternion (x, y, z, w) for rotation, (s, -, -, -) for scalars.
glm::vec4 sampleChannel(const Channel& channel, float time, int* cursor = nullptr);

// The plain evaluation the fast paths above are held to (tests): binary search, every
// rotation key normalised, slerp by acos and sin. Same values to 1e-6, several times slower.
glm::vec4 sampleChannelReference(const Channel& channel, float time);

// sampleClip (clip.h) with cursors kept in `cache` (resized to the clip as needed). For many
// samples of one unchanging clip (playback, export), PlaybackSamplingJob on a PlaybackClip
// built once (anim/playback_sampling_job.h) gives the same values several times faster.
void sampleClip(const Clip& clip, float time, Pose& pose, SamplingCache& cache);

}  // namespace kinema
