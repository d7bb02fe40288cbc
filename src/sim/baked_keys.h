#pragma once
// After a bake (a key per frame on each simulated joint), the key reduction of
// retarget/key_reduction.h thins those channels alone, so the result edits like hand keys.
#include <string>
#include <vector>

#include "anim/clip.h"
#include "retarget/key_reduction.h"

namespace kinema {

// Tolerances that scale with the character: 1/1000 of its rest size (the diagonal of the box
// around its joints, file units) for positions and half a degree for rotations.
KeyReductionSettings bakedKeyTolerances(const Skeleton& skeleton);

// Reduces the linear rotation and translation channels of `joints` in `clip` (each joint's
// world position stays within the tolerance at every frame); every other channel is kept
// as it was. Returns "" or what went wrong. `report` counts the keys of those channels.
std::string reduceBakedKeys(const Skeleton& skeleton, Clip& clip, const std::vector<int>& joints,
                            const KeyReductionSettings& settings, KeyReductionReport* report = nullptr);

}  // namespace kinema
