#pragma once
// A Clip rearranged once for sampling (PlaybackSamplingJob), the way ozz-animation's runtime
// Animation is built from its RawAnimation: the Clip stays the editable form, this one is
// read-only and rebuilt after edits.
#include <cstdint>
#include <vector>

#include "anim/clip.h"

namespace kinema {

// Channels of one clip that share a key grid (the same key times, as imported motion does)
// and interpolate every segment Linear or every segment Step. Their keys are stored
// frame-major in blocks of four tracks, components apart (x0 x1 x2 x3 y0 ... ): the keys a
// time needs are two consecutive rows, read front to back whether the clip plays or jumps,
// and four tracks interpolate at once. Rotation keys are stored normalised as sampling
// normalises them, so sampling them is the same slerp.
struct PlaybackGrid {
  std::vector<float> times;  // seconds, strictly increasing, at least two
  // Blocks of four tracks in each row, in this order: translations, scales, rotations.
  int translationBlocks = 0, scaleBlocks = 0, rotationBlocks = 0;
  int rowFloats = 0;        // 12 per translation or scale block, 16 per rotation block
  std::vector<float> rows;  // times.size() rows of rowFloats (local space, as the channels)
  // Per lane (4 per block, blocks in row order): the joint written. A block's unused lanes
  // repeat its first track, so they write the same value to the same place.
  std::vector<int> joints;
  // Per lane: 1 for a Linear channel, 0 for a Step one; blockHasStep: per block, any 0.
  std::vector<float> linear;
  std::vector<uint8_t> blockHasStep;

  int keyCount() const { return static_cast<int>(times.size()); }
  int blockCount() const { return translationBlocks + scaleBlocks + rotationBlocks; }
};

struct PlaybackClip {
  // Poses sampled from it have at least this many joints; channels of other joints and
  // Scalar channels are left out, as sampleClip skips them.
  int jointCount = 0;
  std::vector<PlaybackGrid> grids;
  // The other channels (Euler, Bezier, TCB, Hermite, ..., grids of fewer than
  // kMinGridTracks tracks, single keys, channels with modifiers), sampled one by one as
  // sampleClip does.
  std::vector<Channel> channels;

  // Grids shorter than this stay channels: a block of one track wastes three lanes.
  static constexpr int kMinGridTracks = 4;

  // Builds it from `clip` for a skeleton of `jointCount` joints. Where several channels
  // animate the same part of one joint (translation, rotation or Euler, scale) only the
  // last counts, as in sampleClip. O(keys); the clip need not be valid, but an invalid one
  // samples as sampleClip would sample it.
  static PlaybackClip build(const Clip& clip, int jointCount);

  int trackCount() const;  // channels sampled per time, grids and others together
};

}  // namespace kinema
