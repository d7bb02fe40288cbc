#pragma once
// Sampling a PlaybackClip into a pose, as an ozz-style job (like ozz's SamplingJob): explicit
// inputs and outputs, a caller-owned context, validate(). Same values as sampleClip and
// sampleChannelReference (to 1e-6; key times, clamping and interpolation alike), several
// times faster on shared key grids, at sequential and random times alike.
#include <string>
#include <vector>

#include "anim/playback_clip.h"

namespace kinema {

// Cursors for one PlaybackClip: per grid and per other channel, the index of the first key
// after the last sampled time. Only hints: a cursor that does not fit the time (a jump, a
// context used with another clip) is replaced by a binary search, so results never depend
// on it. run() sizes it to the clip.
struct PlaybackContext {
  std::vector<int> gridCursors;
  std::vector<int> channelCursors;
};

struct PlaybackSamplingJob {
  const PlaybackClip* clip = nullptr;
  PlaybackContext* context = nullptr;
  // Seconds, finite; each channel clamps it to its keys (the first key's value before it,
  // the last key's after it).
  float time = 0.0f;
  // Local transforms (pose.local), outputCount >= clip->jointCount. The parts of joints the
  // clip animates are overwritten; the rest keep what they hold (the rest pose, another base).
  Transform* output = nullptr;
  int outputCount = 0;

  // Empty when the inputs are usable; otherwise what is wrong with them.
  std::string validate() const;
  // Runs the job; returns false (and writes nothing) when validate() fails.
  bool run() const;
};

// The job on a whole pose (pose.size() >= clip.jointCount); false when validate() fails.
bool samplePlayback(const PlaybackClip& clip, float time, Pose& pose, PlaybackContext& context);

}  // namespace kinema
