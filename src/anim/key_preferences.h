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

}  // namespace kinema
