#include "retarget/humanoid_bones.h"

namespace kinema {

namespace {

const char* const kNames[kHumanoidBoneCount] = {
    "Hips", "Spine", "Chest", "UpperChest", "Neck", "Head",
    "LeftShoulder", "LeftUpperArm", "LeftLowerArm", "LeftHand",
    "RightShoulder", "RightUpperArm", "RightLowerArm", "RightHand",
    "LeftUpperLeg", "LeftLowerLeg", "LeftFoot", "LeftToes",
    "RightUpperLeg", "RightLowerLeg", "RightFoot", "RightToes",
    "LeftThumbProximal", "LeftThumbIntermediate", "LeftThumbDistal",
    "LeftIndexProximal", "LeftIndexIntermediate", "LeftIndexDistal",
    "LeftMiddleProximal", "LeftMiddleIntermediate", "LeftMiddleDistal",
    "LeftRingProximal", "LeftRingIntermediate", "LeftRingDistal",
    "LeftLittleProximal", "LeftLittleIntermediate", "LeftLittleDistal",
    "RightThumbProximal", "RightThumbIntermediate", "RightThumbDistal",
    "RightIndexProximal", "RightIndexIntermediate", "RightIndexDistal",
    "RightMiddleProximal", "RightMiddleIntermediate", "RightMiddleDistal",
    "RightRingProximal", "RightRingIntermediate", "RightRingDistal",
    "RightLittleProximal", "RightLittleIntermediate", "RightLittleDistal",
};

}  // namespace

const char* toString(HumanoidBone bone) { return kNames[index(bone)]; }

std::optional<HumanoidBone> humanoidBoneFromString(const std::string& name) {
  for (int i = 0; i < kHumanoidBoneCount; ++i)
    if (name == kNames[i]) return humanoidBone(i);
  return std::nullopt;
}

bool isRequired(HumanoidBone bone) {
  switch (bone) {
    case HumanoidBone::Hips: case HumanoidBone::Spine: case HumanoidBone::Head:
    case HumanoidBone::LeftUpperArm: case HumanoidBone::LeftLowerArm: case HumanoidBone::LeftHand:
    case HumanoidBone::RightUpperArm: case HumanoidBone::RightLowerArm: case HumanoidBone::RightHand:
    case HumanoidBone::LeftUpperLeg: case HumanoidBone::LeftLowerLeg: case HumanoidBone::LeftFoot:
    case HumanoidBone::RightUpperLeg: case HumanoidBone::RightLowerLeg: case HumanoidBone::RightFoot:
      return true;
    default:
      return false;
  }
}

}  // namespace kinema
