#pragma once
#include <vector>

#include "anim/clip.h"
#include "core/pose.h"
#include "core/skeleton.h"

namespace kinema {

// Which joints are not connected to their parent, as Blender decides for imported
// armatures: a joint whose translation is its own (animated, or moved in the pose) does
// not continue its parent's bone, so the viewport draws a thin dashed relationship line to
// it instead of a bone (a root at the origin with the hips a metre away, the hips carrying
// the walk). A joint that only rotates keeps its rest offset and is drawn as a bone.

// One flag per joint: 1 where the joint has a parent and either a Translation channel of
// `clip` (may be null) or the pose's translation leaves the rest offset by more than a
// thousandth of its length (float noise in exported files stays connected).
std::vector<char> looseJoints(const Skeleton& skeleton, const Clip* clip, const Pose& pose);

}  // namespace kinema
