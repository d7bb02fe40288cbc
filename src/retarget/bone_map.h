#pragma once
// Which joint of one skeleton plays which joint of another: found by name or by the shape
// of the hierarchy (findHumanoid), joined through the canonical humanoid bones
// (mapThroughHumanoid), or written by hand (io/bone_map_file.h).
#include <string>
#include <vector>

#include "anim/clip_source_map.h"
#include "core/result.h"
#include "core/skeleton.h"
#include "retarget/humanoid_bones.h"

namespace kinema {

// How findHumanoid read a skeleton.
enum class HumanoidSource { Names, Topology };

struct HumanoidReading {
  HumanoidMap bones;
  HumanoidSource source = HumanoidSource::Names;
};

// Reads a skeleton as a humanoid. First by joint names (CMU/cgspeed, Mixamo "mixamorig:",
// Blender rigify/metarig, GAMES105, Kinema's default character; sides from Left/Right, L/R
// and l/r prefixes and .L/_L suffixes); the hips are then where the legs meet and the
// spine chain is the path from the hips to where the arms meet. When names do not give
// every required bone (isRequired), by topology on the rest pose (world space, Y up):
// the hips are the first joint with two branches reaching far below it (legs) and one above;
// along each limb the long bones are upper/lower leg (arm); left is +side where
// side = up x forward, forward being the way the feet point (+Z when they do not say).
// Fails with one sentence when neither reading finds every required bone.
Result<HumanoidReading> findHumanoid(const Skeleton& skeleton);

// One mapped joint: `source` drives `target` (joint indices in the two skeletons).
struct BonePair {
  int source = -1;
  int target = -1;
};

struct BoneMap {
  std::vector<BonePair> pairs;  // in target joint order once normalised (see validate)

  // Empty when every index lies in its skeleton, no joint appears twice on one side and the
  // hierarchy agrees: when source a is an ancestor of source b, target(b) is not an ancestor
  // of target(a). Otherwise one sentence naming the first problem ("incompatible skeletons").
  std::string validate(const Skeleton& source, const Skeleton& target) const;
  int targetOf(int sourceJoint) const;
  int sourceOf(int targetJoint) const;
};

// Every canonical bone both readings have becomes a pair. Fingers are paired only when both
// skeletons have fingers on both hands.
BoneMap mapThroughHumanoid(const HumanoidMap& source, const HumanoidMap& target);
// Each joint onto the joint of the same name (a skeleton onto itself or a copy of it).
BoneMap mapByIdenticalNames(const Skeleton& source, const Skeleton& target);

// The map as a clip keeps it (Clip::sourceMap): source joints by name, in the map's order.
ClipSourceMap toClipSourceMap(const BoneMap& map, const Skeleton& source, const std::string& file, int clip);
// Back to joint indices of `source` (the motion file's skeleton, read again); fails with one
// line naming a source joint that skeleton does not have, or a map that does not validate.
Result<BoneMap> fromClipSourceMap(const ClipSourceMap& kept, const Skeleton& source, const Skeleton& target);

// Joint i of `skeleton`: the canonical bone it plays in `reading`, or nullptr.
const char* humanoidRoleOf(const HumanoidMap& reading, int joint);

}  // namespace kinema
