#pragma once
#include "anim/clip.h"

namespace kinema {

// What newly inserted keys carry (Blender: Edit > Preferences > Animation > F-Curves).
// Default: Bezier with auto-clamped handles, Blender's default, for rotations too (their
// quaternion components, as Blender's); rotations get rotationInterpolation() of the choice.
struct KeyPreferences {
  Interpolation interpolation = Interpolation::Bezier;
  HandleType handles = HandleType::AutoClamped;
  bool locRotOnly = false;  // key translation + rotation only (else also scale where it differs from rest)
};

// Auto-key (the timeline's record button): while enabled, every posing edit and drag keys
// the joints whose local transform it changed at the document's playhead (its time in its
// clip, created as "Action" when the scene has none), in the same undo step as the edit.
struct AutoKeySettings {
  bool enabled = false;
  KeyPreferences preferences;
};

}  // namespace kinema
