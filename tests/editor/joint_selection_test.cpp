// Selection rules (Blender pose mode): click replaces, Shift-click toggles, box modes, and
// the one rule that keeps the active joint among the selected (joint_selection.h).
#include <gtest/gtest.h>

#include <random>

#include "editor/model/joint_selection.h"

namespace kinema {
namespace KINEMA_UNITY_ID {

using V = std::vector<int>;

TEST(JointSelection, ClickReplacesAndShiftClickToggles) {
  JointSelection s;
  s.click(3);
  EXPECT_EQ(s.joints(), V{3});
  EXPECT_EQ(s.active(), 3);
  s.shiftClick(1);
  EXPECT_EQ(s.joints(), (V{1, 3}));
  EXPECT_EQ(s.active(), 1);
  s.shiftClick(3);  // selected but not active: becomes active, stays selected
  EXPECT_EQ(s.joints(), (V{1, 3}));
  EXPECT_EQ(s.active(), 3);
  s.shiftClick(3);  // the active one again: deselected; the one left selected becomes active
  EXPECT_EQ(s.joints(), V{1});
  EXPECT_EQ(s.active(), 1);
  s.click(5);
  EXPECT_EQ(s.joints(), V{5});
  s.click(-1);
  EXPECT_TRUE(s.empty());
}

TEST(JointSelection, AllNoneAndBox) {
  JointSelection s;
  s.click(2);
  s.selectAll(4);
  EXPECT_EQ(s.joints(), (V{0, 1, 2, 3}));
  EXPECT_EQ(s.active(), 2);
  s.box({1, 3}, BoxSelectMode::Subtract);
  EXPECT_EQ(s.joints(), (V{0, 2}));
  s.box({5, 1}, BoxSelectMode::Extend);
  EXPECT_EQ(s.joints(), (V{0, 1, 2, 5}));
  s.box({4, 4}, BoxSelectMode::Replace);
  EXPECT_EQ(s.joints(), V{4});
  EXPECT_EQ(s.active(), 4);  // the active joint was outside the new box: the box's joint
  EXPECT_TRUE(s.isSelected(4));
  EXPECT_FALSE(s.isSelected(2));
  s.clear();
  EXPECT_TRUE(s.empty());
  EXPECT_EQ(s.active(), -1);
}

// Regression (issue 17): a box select or select all left no active joint, so the status bar
// and the properties panel said "nothing selected" while R rotated the box's joints. The
// old code returned -1 for every active() below except the first.
TEST(JointSelection, BoxAndSelectAllAlwaysLeaveAnActiveJoint) {
  JointSelection s;
  s.box({7, 3, 5}, BoxSelectMode::Replace);  // nothing active before: the box's joint nearest the root
  EXPECT_EQ(s.joints(), (V{3, 5, 7}));
  EXPECT_EQ(s.active(), 3);
  s.click(5);
  s.box({2, 9}, BoxSelectMode::Extend);  // the active joint is still selected: kept
  EXPECT_EQ(s.active(), 5);
  s.box({5, 6}, BoxSelectMode::Replace);  // still inside the new box: kept
  EXPECT_EQ(s.active(), 5);
  s.box({8, 6}, BoxSelectMode::Replace);  // outside it: the new box's joint nearest the root
  EXPECT_EQ(s.joints(), (V{6, 8}));
  EXPECT_EQ(s.active(), 6);
  s.box({6}, BoxSelectMode::Subtract);  // the active one subtracted: the one left
  EXPECT_EQ(s.joints(), V{8});
  EXPECT_EQ(s.active(), 8);
  s.box({8}, BoxSelectMode::Subtract);  // nothing left: nothing active
  EXPECT_TRUE(s.empty());
  EXPECT_EQ(s.active(), -1);
  s.selectAll(4);  // A with nothing active: the root
  EXPECT_EQ(s.joints(), (V{0, 1, 2, 3}));
  EXPECT_EQ(s.active(), 0);
  s.click(2);
  s.selectAll(4);  // A keeps the active joint
  EXPECT_EQ(s.active(), 2);
  s.click(9);
  s.selectAll(4);  // an active joint beyond the skeleton is not kept
  EXPECT_EQ(s.active(), 0);
}

TEST(JointSelection, TheActiveJointIsSelectedWhenAndOnlyWhenSomethingIs) {
  // Random operations keep the invariant: active() is one of joints(), or -1 when empty.
  std::mt19937 rng(17);
  JointSelection s;
  for (int step = 0; step < 2000; ++step) {
    const int joint = static_cast<int>(rng() % 12) - 1;
    switch (rng() % 5) {
      case 0: s.click(joint); break;
      case 1: s.shiftClick(joint); break;
      case 2: s.selectAll(static_cast<int>(rng() % 12)); break;
      case 3: s.clear(); break;
      default: {
        V box;
        for (int k = static_cast<int>(rng() % 4); k > 0; --k) box.push_back(static_cast<int>(rng() % 12));
        s.box(box, static_cast<BoxSelectMode>(rng() % 3));
      }
    }
    if (s.empty()) {
      ASSERT_EQ(s.active(), -1) << "step " << step;
    } else {
      ASSERT_TRUE(s.isSelected(s.active())) << "step " << step;
    }
  }
}

}  // namespace
}  // namespace kinema
