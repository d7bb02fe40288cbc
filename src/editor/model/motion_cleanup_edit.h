#pragma once
// Animation > Clean Up Motion…: foot locking over the clip's contacts and key reduction on
// one clip as one undo step, with the figures the panel shows before and after. The
// computation is MotionCleanupJob (retarget/motion_cleanup.h), the one `kinema retarget
// --fix-feet --reduce` runs. No GL, no window.
#include <string>

#include "retarget/motion_cleanup.h"

namespace kinema {

class Document;

// The panel's settings, in the units a user types: file units and degrees.
struct CleanUpOptions {
  bool lockFeet = true;
  int blendFrames = 4;             // frames the lock fades in and out over (>= 0)
  bool reduce = true;
  float positionTolerance = 0.01f; // file units (> 0): largest change of any joint's position
  float rotationDegrees = 1.0f;    // degrees (> 0): largest change of a reduced rotation
};

// What the last Clean Up did (the panel's before/after figure).
struct CleanUpResult {
  std::string clipName;
  CleanUpOptions options;
  MotionCleanupReport report;  // maxAngleError in radians, as the job reports it
};

// Cleans clip `clip` with the document skeleton's humanoid legs and the clip's contacts:
// one undo step "Clean up motion NAME" (the clip's channels replaced; its contacts and bone
// map kept). Locking needs contacts (detect them first); "" or why nothing changed.
std::string cleanUpMotionEdit(Document& doc, int clip, const CleanUpOptions& options, CleanUpResult* result = nullptr);

}  // namespace kinema
