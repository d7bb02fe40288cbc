#pragma once
// Foot locking: during a contact the ankle stays (horizontally) where the contact began,
// through Kinema's two-bone IK on hip, knee and ankle, blended in and out; no ankle or toe
// goes below the floor. Only the three leg joints' rotations change.
#include <string>
#include <vector>

#include "anim/clip.h"
#include "retarget/foot_contacts.h"

namespace kinema {

struct FootLockJob {
  const Skeleton* skeleton = nullptr;
  const Clip* clip = nullptr;  // sampled at its frames (clipFrameCount)
  LegJoints legs[2];
  const std::vector<ContactInterval>* contacts[2] = {nullptr, nullptr};
  // Frames over which the lock fades in before a contact and out after it (>= 0).
  int blendFrames = 4;
  // World height (Y, file units) no ankle or toe joint may go below.
  float floorHeight = 0.0f;

  // Written: the clip with the upper leg, lower leg and foot rotation channels of both legs
  // replaced by one Linear key per frame; every other channel is copied unchanged. The foot
  // keeps its world rotation from the input (IK moves the leg, not the foot's angle).
  Clip* output = nullptr;

  std::string validate() const;
  bool run() const;
};

}  // namespace kinema
