#pragma once
// Bone map files (docs/kinema-format.md, "Bone maps"): a JSON object from source joint
// names to target joint names; either side may instead name a canonical humanoid bone
// ("LeftUpperLeg"), which stands for the joint the skeleton's humanoid reading gives it.
#include <string>

#include <nlohmann/json.hpp>

#include "core/result.h"
#include "io/input_limits.h"
#include "retarget/bone_map.h"

namespace kinema {

// One skeleton side of a map: the skeleton, its humanoid reading (nullptr when it has none)
// and what to call it in messages ("the source (walk.bvh)").
struct BoneMapSide {
  const Skeleton* skeleton = nullptr;
  const HumanoidMap* humanoid = nullptr;
  std::string label;
};

// Errors are one line: "SOURCE: \"KEY\": what" (SOURCE names the file). A name that is
// neither a joint nor a canonical bone the reading has, a joint mapped twice on either side
// and a value that is not a string are errors; so is an empty map.
Result<BoneMap> parseBoneMapJson(const std::string& text, const std::string& source, const BoneMapSide& from,
                                 const BoneMapSide& to, const InputLimits& limits = {});
Result<BoneMap> loadBoneMapFile(const std::string& path, const BoneMapSide& from, const BoneMapSide& to,
                                const InputLimits& limits = {});

// The map as a file would hold it, joint names on both sides, in target joint order.
nlohmann::ordered_json boneMapJson(const BoneMap& map, const Skeleton& source, const Skeleton& target);

}  // namespace kinema
