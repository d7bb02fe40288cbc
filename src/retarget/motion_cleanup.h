#pragma once
// Clean Up for a retargeted (or any key-per-frame) clip on a humanoid: foot locking over the
// clip's contacts, then key reduction, with the figures `kinema retarget --json` reports and
// the editor's Clean Up panel shows (foot skate before and after, key counts before and
// after, the largest reduction error). The one computation both front ends run.
#include <string>
#include <vector>

#include "anim/clip.h"
#include "retarget/foot_contacts.h"
#include "retarget/key_reduction.h"

namespace kinema {

// The legs of `skeleton` by its humanoid reading: "" when both legs are there with a length,
// else why not. `zeroLength` tells the two failures apart (legs missing, or legs whose hip,
// knee and ankle coincide in the rest pose).
std::string humanoidLegs(const Skeleton& skeleton, const HumanoidMap& humanoid, LegJoints out[2],
                         bool* zeroLength = nullptr);
// The lowest ankle or toe height (world Y, file units) of the rest pose: the floor foot
// locking keeps feet above.
float restFootFloor(const Skeleton& skeleton, const LegJoints legs[2]);
// FootContactJob with the default settings on every frame of `clip`.
std::string detectFootContacts(const Skeleton& skeleton, const Clip& clip, const LegJoints legs[2], FootContacts& out);

struct MotionCleanupSettings {
  bool lockFeet = true;   // FootLockJob over the contacts, floor at restFootFloor
  int blendFrames = 4;    // FootLockJob::blendFrames
  bool reduce = true;     // KeyReductionJob
  KeyReductionSettings reduction;
};

struct MotionCleanupReport {
  float skateBefore = 0.0f, skateAfter = 0.0f;  // footSkate: leg lengths per contact frame
  int contactFrames = 0;                        // over both feet
  // Key counts over every channel before and after (equal without reduce) and the largest
  // errors reduction left (file units, radians; 0 without reduce).
  KeyReductionReport keys;
};

struct MotionCleanupJob {
  const Skeleton* skeleton = nullptr;
  const Clip* clip = nullptr;
  LegJoints legs[2];  // valid legs (humanoidLegs)
  const FootContacts* contacts = nullptr;  // the clip's (FootContacts in frames of its grid)
  MotionCleanupSettings settings;
  Clip* output = nullptr;                  // written: the cleaned clip (contacts and map kept)
  MotionCleanupReport* report = nullptr;   // optional

  std::string validate() const;
  bool run() const;  // false (nothing written) when validate() fails
};

}  // namespace kinema
