// Clean Up as one undo step (motion_cleanup_edit.h).
#include "editor/model/motion_cleanup_edit.h"

#include <cmath>

#include "editor/model/document.h"
#include "retarget/bone_map.h"

namespace kinema {

std::string cleanUpMotionEdit(Document& doc, int clip, const CleanUpOptions& o, CleanUpResult* result) {
  if (clip < 0 || clip >= static_cast<int>(doc.scene().clips.size()))
    return "Clean up: the document has no clip (import or key a motion first)";
  if (!o.lockFeet && !o.reduce) return "Clean up: choose foot locking, key reduction or both";
  if (o.reduce && !(std::isfinite(o.positionTolerance) && o.positionTolerance > 0.0f && std::isfinite(o.rotationDegrees) &&
                    o.rotationDegrees > 0.0f))
    return "Clean up: both tolerances must be positive numbers";
  if (o.blendFrames < 0) return "Clean up: blend frames must not be negative";
  const Skeleton& s = doc.skeleton();
  const Clip& source = doc.scene().clips[clip];
  if (o.lockFeet && source.contacts.empty())
    return "Clean up: clip '" + source.name + "' has no foot contacts to lock (Animation > Foot Contacts > Detect)";
  const Result<HumanoidReading> human = findHumanoid(s);
  if (!human) return "Clean up: the skeleton is not a humanoid (" + human.error() + ")";
  MotionCleanupJob job;
  if (std::string bad = humanoidLegs(s, human->bones, job.legs); !bad.empty()) return "Clean up: " + bad;
  job.skeleton = &s;
  job.clip = &source;
  job.contacts = &source.contacts;
  job.settings.lockFeet = o.lockFeet;
  job.settings.blendFrames = o.blendFrames;
  job.settings.reduce = o.reduce;
  job.settings.reduction.positionTolerance = o.positionTolerance;
  job.settings.reduction.angleTolerance = o.rotationDegrees * 0.01745329251994329577f;
  Clip cleaned;
  MotionCleanupReport report;
  job.output = &cleaned;
  job.report = &report;
  if (!job.run()) return "Clean up: " + job.validate();
  const std::string name = source.name;
  const std::string error = doc.edit("Clean up motion " + name, [&](DocumentEdit& e) {
    e.clips[clip] = cleaned;
    return std::string();
  });
  if (error.empty() && result) *result = CleanUpResult{name, o, report};
  return error;
}

}  // namespace kinema
