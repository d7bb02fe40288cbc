#pragma once
// Key reduction: a key-per-frame take becomes sparse Linear channels that stay within a
// tolerance of the original at every frame (Blender's Decimate / Simplify are the anchors).
#include <string>

#include "anim/clip.h"

namespace kinema {

struct KeyReductionSettings {
  // Largest allowed change of any joint's world position at any frame (file units, > 0).
  float positionTolerance = 0.01f;
  // Largest allowed change of any reduced rotation channel's local rotation at any frame
  // (radians, > 0).
  float angleTolerance = 0.0174533f;
};

struct KeyReductionReport {
  int keysBefore = 0, keysAfter = 0;  // over every channel of the clip
  float maxPositionError = 0.0f;      // file units, measured over every joint and frame
  float maxAngleError = 0.0f;         // radians, over the reduced rotation channels
};

// Reduces every uniformly Linear rotation and translation channel (other channels are copied
// as they are). Each channel is split Douglas-Peucker style: a segment between two kept keys
// stays when the straight (slerp) segment is within the channel's budget at every original
// key and frame inside it, otherwise it is split at its worst point. A rotation's budget is
// the angle tolerance or, when smaller, the position tolerance over the farthest joint it
// carries (rest pose). The whole clip is then sampled through sampleClip at every frame
// (clipFrameCount) and compared in world space; where a joint is off by more than the
// tolerance, the budgets of the channels above it are halved and those channels reduced
// again, until every frame passes (at worst a channel keeps all its keys).
struct KeyReductionJob {
  const Skeleton* skeleton = nullptr;
  const Clip* clip = nullptr;
  KeyReductionSettings settings;
  Clip* output = nullptr;                // written: the reduced clip
  KeyReductionReport* report = nullptr;  // optional

  std::string validate() const;
  bool run() const;
};

}  // namespace kinema
