#pragma once
// Pose transfer from one skeleton's clip onto another skeleton, through world-space
// rotations relative to each rest pose (ozz-style job: explicit inputs, one output).
#include <string>
#include <vector>

#include "anim/clip.h"
#include "anim/pose_source.h"
#include "core/result.h"
#include "retarget/bone_map.h"

namespace kinema {

// For each mapped pair (s -> t) and frame f, in world space (Y up, the skeletons unplaced):
//   target world rotation(t) = D(f) * A * target rest world rotation(t),
//   D(f) = source world rotation(s, f) * inverse(source rest world rotation(s)),
// the source bone's turn away from its rest, applied in world space, so bone axes and rolls
// never matter. A turns the target's rest bone onto the source's rest bone (their directions
// to the next mapped joint; two such directions at a branching joint), so a T-pose take
// drives an A-pose character with the same world bone directions. World rotations become
// local ones down the target hierarchy; unmapped target joints keep their rest local
// rotation. The root-motion joint's world position is rootScale times the source root's
// world position (file units), its height measured from each side's floor: target height =
// targetFloor + rootScale * (source height - sourceFloor), so a foot planted on the source's
// floor lands on the target's (footFloors gives the two floors from the feet); with
// targetFeet, the whole take is then moved up or down so the lowest those joints come over it
// is targetFloor (the legs' proportions differ, so the ratio alone misses by centimetres).
// inPlace keeps the root at its rest X and Z instead.
struct RetargetJob {
  const Skeleton* source = nullptr;
  const Clip* sourceClip = nullptr;  // sampled at its frames 0 .. nearestFrame(duration)
  // Optional: the source's poses at those times (null: sourceClip's keys alone). The CLI and
  // the editor pass the pipeline's (evaluation/scene_poses.h): modifiers, keyed IK targets.
  PoseSource* sourcePoses = nullptr;
  const Skeleton* target = nullptr;
  const BoneMap* map = nullptr;       // must validate against the two skeletons
  int sourceRoot = -1;                // the joints root motion goes between (-1: none);
  int targetRoot = -1;                //   targetRoot must be in the map
  float rootScale = 1.0f;             // > 0, finite: target hip height / source hip height
  float sourceFloor = 0.0f;           // world Y of each side's planted feet (finite; file units)
  float targetFloor = 0.0f;
  std::vector<int> targetFeet;        // target joints grounded on targetFloor (empty: none)
  bool inPlace = false;

  // Written: one Linear key per source frame on a rotation channel of every mapped target
  // joint, and a translation channel on targetRoot; same name and frame time as the source.
  Clip* output = nullptr;

  std::string validate() const;
  bool run() const;  // false (nothing written) when validate() fails
};

// The number of frames of a clip on its frame grid (1 for an empty clip).
int clipFrameCount(const Clip& clip);

// Hip height above the lowest foot or toe joint in the rest pose (world Y, file units),
// the length root motion is scaled by. Fails when the reading has no hips or feet, or the
// legs have no length.
Result<float> restHipHeight(const Skeleton& skeleton, const HumanoidMap& humanoid);

// The floors root heights are measured from (world Y, file units): the lowest any foot or
// toe joint of `source` comes over `clip` (a take's rest pose may stand anywhere: BVH rests
// often put the hips at the origin), and the lowest foot or toe joint of the target's rest
// pose (a character stands on its floor). Fails when a reading has no feet. `sourcePoses`
// as RetargetJob's (null: the clip's keys alone).
struct FootFloors {
  float source = 0.0f;
  float target = 0.0f;
};
Result<FootFloors> footFloors(const Skeleton& source, const Clip& clip, const HumanoidMap& sourceHumanoid,
                              const Skeleton& target, const HumanoidMap& targetHumanoid,
                              PoseSource* sourcePoses = nullptr);

}  // namespace kinema
