#pragma once
#include <string>

namespace kinema {

// The name of a joint's mirror partner, as Blender's "flip names" finds it: a side
// marker L/R (either case) as a suffix or prefix after/before a separator (. _ - space:
// "Hand.L", "hand_r", "L_Hand"), or Left/Right (left/right, LEFT/RIGHT) as a prefix or
// suffix ("LeftHand", "hand_right"). A trailing ".001"-style number is kept. Returns ""
// when the name has no side marker (a centre joint such as "Spine").
std::string mirroredJointName(const std::string& name);

}  // namespace kinema
