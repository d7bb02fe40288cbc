#include "retarget/motion_cleanup.h"

#include <algorithm>
#include <cmath>

#include "core/forward_kinematics.h"
#include "retarget/foot_locking.h"

namespace kinema {

std::string humanoidLegs(const Skeleton& s, const HumanoidMap& humanoid, LegJoints out[2], bool* zeroLength) {
  if (zeroLength) *zeroLength = false;
  legsOf(humanoid, out);
  if (!out[0].valid(s.size()) || !out[1].valid(s.size())) return "its humanoid reading has no legs";
  if (!(restLegLength(s, out[0]) > 0.0f && restLegLength(s, out[1]) > 0.0f)) {
    if (zeroLength) *zeroLength = true;
    return "zero-length legs (hip, knee and ankle of a leg coincide in the rest pose)";
  }
  return {};
}

float restFootFloor(const Skeleton& s, const LegJoints legs[2]) {
  const std::vector<glm::mat4> w = computeWorld(s, Pose::rest(s));
  float lo = w[legs[0].foot][3].y;
  for (int side = 0; side < 2; ++side)
    for (int j : {legs[side].foot, legs[side].toes})
      if (j >= 0) lo = std::min(lo, w[j][3].y);
  return lo;
}

std::string detectFootContacts(const Skeleton& skeleton, const Clip& clip, const LegJoints legs[2], FootContacts& out) {
  FootContactJob job;
  job.skeleton = &skeleton;
  job.clip = &clip;
  job.legs[0] = legs[0];
  job.legs[1] = legs[1];
  FootContacts found;
  job.output[0] = &found.feet[0];
  job.output[1] = &found.feet[1];
  if (!job.run()) return job.validate();
  out = std::move(found);
  return {};
}

std::string MotionCleanupJob::validate() const {
  if (!skeleton || !clip || !contacts || !output) return "clean up: missing input or output";
  if (!hasOwnFrameRate(*clip)) return "clean up: the clip has no frame rate of its own";
  for (int side = 0; side < 2; ++side)
    if (!legs[side].valid(skeleton->size())) return "clean up: needs both legs of a humanoid";
  if (std::string bad = contacts->validate(); !bad.empty()) return "clean up: " + bad;
  if (settings.blendFrames < 0) return "clean up: blend frames must not be negative";
  const KeyReductionSettings& r = settings.reduction;
  if (settings.reduce && !(std::isfinite(r.positionTolerance) && r.positionTolerance > 0.0f &&
                           std::isfinite(r.angleTolerance) && r.angleTolerance > 0.0f))
    return "clean up: both reduction tolerances must be positive finite numbers";
  return {};
}

bool MotionCleanupJob::run() const {
  if (!validate().empty()) return false;
  const Skeleton& s = *skeleton;
  MotionCleanupReport rep;
  for (const std::vector<ContactInterval>& foot : contacts->feet)
    for (const ContactInterval& c : foot) rep.contactFrames += c.frames();
  rep.skateBefore = footSkate(s, *clip, legs, contacts->feet);
  rep.skateAfter = rep.skateBefore;
  Clip clip1 = *clip;
  if (settings.lockFeet) {
    FootLockJob lock;
    lock.skeleton = &s;
    lock.clip = clip;
    lock.legs[0] = legs[0];
    lock.legs[1] = legs[1];
    lock.contacts[0] = &contacts->feet[0];
    lock.contacts[1] = &contacts->feet[1];
    lock.blendFrames = settings.blendFrames;
    lock.floorHeight = restFootFloor(s, legs);
    lock.output = &clip1;
    if (!lock.run()) return false;
    rep.skateAfter = footSkate(s, clip1, legs, contacts->feet);
  }
  for (const Channel& c : clip1.channels) rep.keys.keysBefore += c.keyCount();
  rep.keys.keysAfter = rep.keys.keysBefore;
  if (settings.reduce) {
    Clip reduced;
    KeyReductionJob r;
    r.skeleton = &s;
    r.clip = &clip1;
    r.settings = settings.reduction;
    r.output = &reduced;
    r.report = &rep.keys;
    if (!r.run()) return false;
    clip1 = std::move(reduced);
  }
  *output = std::move(clip1);
  if (report) *report = rep;
  return true;
}

}  // namespace kinema
