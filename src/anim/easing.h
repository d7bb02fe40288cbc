#pragma once
#include "anim/clip.h"

namespace kinema {

// Robert Penner's easing equations as Blender uses them: u in [0, 1] -> eased fraction,
// 0 at 0 and 1 at 1. Back overshoots by Blender's default 1.70158; Elastic uses Blender's
// defaults (amplitude 1, period 0.3 for In/Out and 0.45 for InOut); Bounce has four bounces.
float ease(EasingFunction function, EasingMode mode, float u);

}  // namespace kinema
