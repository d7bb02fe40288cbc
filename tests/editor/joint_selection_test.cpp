// Selection rules (Blender pose mode): click replaces, Shift-click toggles, box modes.
#include <gtest/gtest.h>

#include "editor/model/joint_selection.h"

namespace kinema {
namespace {

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
  s.shiftClick(3);  // the active one again: deselected
  EXPECT_EQ(s.joints(), V{1});
  EXPECT_EQ(s.active(), -1);
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
  EXPECT_EQ(s.active(), -1);  // the active joint was outside the new box
  EXPECT_TRUE(s.isSelected(4));
  EXPECT_FALSE(s.isSelected(2));
  s.clear();
  EXPECT_TRUE(s.empty());
  EXPECT_EQ(s.active(), -1);
}

}  // namespace
}  // namespace kinema
