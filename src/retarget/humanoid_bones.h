#pragma once
// The canonical humanoid bone set every bone map goes through (Unity's Humanoid and Godot's
// SkeletonProfileHumanoid are the references; the names are Unity's).
#include <array>
#include <optional>
#include <string>

namespace kinema {

enum class HumanoidBone {
  Hips, Spine, Chest, UpperChest, Neck, Head,
  LeftShoulder, LeftUpperArm, LeftLowerArm, LeftHand,
  RightShoulder, RightUpperArm, RightLowerArm, RightHand,
  LeftUpperLeg, LeftLowerLeg, LeftFoot, LeftToes,
  RightUpperLeg, RightLowerLeg, RightFoot, RightToes,
  // Fingers, three segments each (proximal, intermediate, distal), left then right.
  LeftThumbProximal, LeftThumbIntermediate, LeftThumbDistal,
  LeftIndexProximal, LeftIndexIntermediate, LeftIndexDistal,
  LeftMiddleProximal, LeftMiddleIntermediate, LeftMiddleDistal,
  LeftRingProximal, LeftRingIntermediate, LeftRingDistal,
  LeftLittleProximal, LeftLittleIntermediate, LeftLittleDistal,
  RightThumbProximal, RightThumbIntermediate, RightThumbDistal,
  RightIndexProximal, RightIndexIntermediate, RightIndexDistal,
  RightMiddleProximal, RightMiddleIntermediate, RightMiddleDistal,
  RightRingProximal, RightRingIntermediate, RightRingDistal,
  RightLittleProximal, RightLittleIntermediate, RightLittleDistal,
};

constexpr int kHumanoidBoneCount = static_cast<int>(HumanoidBone::RightLittleDistal) + 1;
// Bones before this one are the body; from it on, fingers.
constexpr HumanoidBone kFirstFingerBone = HumanoidBone::LeftThumbProximal;

inline int index(HumanoidBone b) { return static_cast<int>(b); }
inline HumanoidBone humanoidBone(int i) { return static_cast<HumanoidBone>(i); }
inline bool isFinger(HumanoidBone b) { return index(b) >= index(kFirstFingerBone); }

// "LeftUpperArm", ...; and back (exact spelling).
const char* toString(HumanoidBone bone);
std::optional<HumanoidBone> humanoidBoneFromString(const std::string& name);

// A humanoid reading of one skeleton: the joint index of each canonical bone, -1 where the
// skeleton has none. A canonical bone's joint is the joint the bone turns about (the
// upper arm's is at the shoulder).
struct HumanoidMap {
  std::array<int, kHumanoidBoneCount> joint;
  HumanoidMap() { joint.fill(-1); }
  int operator[](HumanoidBone b) const { return joint[index(b)]; }
  int& operator[](HumanoidBone b) { return joint[index(b)]; }
  bool has(HumanoidBone b) const { return joint[index(b)] >= 0; }
};

// The bones a skeleton must have to count as a humanoid: hips, spine, head, and per side
// upper arm, lower arm, hand, upper leg, lower leg and foot (Unity's required set).
bool isRequired(HumanoidBone bone);

}  // namespace kinema
