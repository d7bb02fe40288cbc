#pragma once
// The part of `kinema retarget` that the editor's File > Import Motion onto Character… runs
// too: the automatic bone map (names, then topology) and the retargeted clip with its root
// motion scaled by the hip heights and its feet on the target's floor. Foot locking and key
// reduction stay separate steps (foot_locking.h, key_reduction.h).
#include <string>

#include "anim/clip.h"
#include "anim/pose_source.h"
#include "core/result.h"
#include "core/skeleton.h"
#include "retarget/bone_map.h"

namespace kinema {

// A map found from two humanoid readings, and how ("names", "topology" or "names and
// topology"). Fails with "LABEL: reason" when a side is not a humanoid.
struct AutomaticBoneMap {
  BoneMap map;
  std::string mapBy;
};
Result<AutomaticBoneMap> automaticBoneMap(const Result<HumanoidReading>& source, const Result<HumanoidReading>& target,
                                          const std::string& sourceLabel, const std::string& targetLabel);

// What retargetMotion is given. The readings may be null (a hand-written map on a skeleton
// that reads as no humanoid): root motion then goes between the topmost mapped joints,
// unscaled. mapLabel names the map in errors ("" : an automatic map, "SOURCE onto TARGET").
struct RetargetMotionInput {
  const Skeleton* source = nullptr;
  const Clip* clip = nullptr;
  PoseSource* sourcePoses = nullptr;  // optional: the clip's poses (RetargetJob::sourcePoses)
  const HumanoidReading* sourceHuman = nullptr;
  const Skeleton* target = nullptr;
  const HumanoidReading* targetHuman = nullptr;
  const BoneMap* map = nullptr;
  bool inPlace = false;
  std::string sourceLabel;
  std::string targetLabel;
  std::string mapLabel;
};

// The clip played by the target (RetargetJob) and the job's root settings, for reports.
struct RetargetedMotion {
  Clip clip;
  float rootScale = 1.0f;
  float sourceFloor = 0.0f;
  float targetFloor = 0.0f;
};
// Validates the map against both skeletons, sets the root motion up (hips to hips scaled by
// restHipHeight, floors from footFloors, the target's feet grounded) and runs RetargetJob.
// Fails with one line naming the file (label) at fault; nothing is computed then.
Result<RetargetedMotion> retargetMotion(const RetargetMotionInput& in);

}  // namespace kinema
