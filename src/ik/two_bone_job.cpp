// TwoBoneIkJob: validation here, the geometry in two_bone_job_core.h (shared with
// solveTwoBone, which runs it inline).
#include "ik/two_bone_job.h"

#include <cmath>

#include "ik/two_bone_job_core.h"

namespace kinema {

using ik_detail::nearlyUnit;

std::string TwoBoneIkJob::validate() const {
  if (!startCorrection || !midCorrection) return "two-bone job: startCorrection and midCorrection must be set";
  if (!isFinite(startPosition) || !isFinite(midPosition) || !isFinite(endPosition))
    return "two-bone job: joint positions are not finite";
  if (!isFinite(target)) return "two-bone job: target is not finite";
  if (!isFinite(pole)) return "two-bone job: pole is not finite";
  if (!isFinite(startRotation) || !nearlyUnit(startRotation) || !isFinite(midRotation) || !nearlyUnit(midRotation))
    return "two-bone job: joint rotations must be unit quaternions";
  if (!std::isfinite(twistAngle)) return "two-bone job: twist angle is not finite";
  if (!(weight >= 0.0f && weight <= 1.0f)) return "two-bone job: weight must lie in [0, 1]";
  if (!(soften >= 0.0f && soften <= 1.0f)) return "two-bone job: soften must lie in [0, 1]";
  return "";
}

bool TwoBoneIkJob::run() const {
  if (!validate().empty()) return false;
  runUnchecked();
  return true;
}

void TwoBoneIkJob::runUnchecked() const { ik_detail::runTwoBoneJob(*this); }

}  // namespace kinema
