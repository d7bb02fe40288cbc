// Mirror-partner names as Blender's "flip names" finds them; expected values by hand.
#include <gtest/gtest.h>

#include "editor/model/mirror_names.h"

namespace kinema {
namespace KINEMA_UNITY_ID {

TEST(MirrorNames, SideMarkersFlip) {
  const std::pair<const char*, const char*> cases[] = {
      {"Hand.L", "Hand.R"},         {"Hand.R", "Hand.L"},           {"hand_l", "hand_r"},
      {"hand-r", "hand-l"},         {"hand r", "hand l"},           {"L_Hand", "R_Hand"},
      {"r.hand", "l.hand"},         {"LeftHand", "RightHand"},      {"RightFoot", "LeftFoot"},
      {"hand_left", "hand_right"},  {"HAND_RIGHT", "HAND_LEFT"},    {"leftArm", "rightArm"},
      {"Hand.L.001", "Hand.R.001"}, {"UpperArm.L", "UpperArm.R"},
  };
  for (const auto& [in, out] : cases) EXPECT_EQ(mirroredJointName(in), out) << in;
}

TEST(MirrorNames, CentreJointsHaveNoPartner) {
  for (const char* name : {"Spine", "Hips", "L", "Ball", "Collar", "Head.001", "HandL", "Lhand", ""})
    EXPECT_EQ(mirroredJointName(name), "") << name;
}

TEST(MirrorNames, FlippingTwiceGivesTheNameBack) {
  for (const char* name : {"Hand.L", "l_foot", "LeftArm", "arm_RIGHT", "Toe.R.012"})
    EXPECT_EQ(mirroredJointName(mirroredJointName(name)), name);
}

}  // namespace
}  // namespace kinema
