#include "editor/model/outliner_rows.h"

#include <gtest/gtest.h>

namespace kinema::test {
namespace KINEMA_UNITY_ID {

// root ─ spine ─ arm.L ─ hand.L
//            └─ arm.R ─ hand.R
//   └─ leg.L
Skeleton tree() {
  Skeleton s;
  const int root = s.addJoint("root", -1, Transform{});
  const int spine = s.addJoint("spine", root, Transform{});
  const int armL = s.addJoint("arm.L", spine, Transform{});
  s.addJoint("hand.L", armL, Transform{});
  const int armR = s.addJoint("arm.R", spine, Transform{});
  s.addJoint("Hand.R", armR, Transform{});
  s.addJoint("leg.L", root, Transform{});
  return s;
}

std::vector<int> joints(const std::vector<OutlinerRow>& rows) {
  std::vector<int> out;
  for (const OutlinerRow& r : rows) out.push_back(r.joint);
  return out;
}

TEST(OutlinerRows, NoSearchListsEveryJointWithItsDepth) {
  const std::vector<OutlinerRow> rows = outlinerRows(tree(), "", {});
  EXPECT_EQ(joints(rows), (std::vector<int>{0, 1, 2, 3, 4, 5, 6}));
  const std::vector<int> depths{0, 1, 2, 3, 2, 3, 1};
  for (size_t i = 0; i < rows.size(); ++i) EXPECT_EQ(rows[i].depth, depths[i]) << i;
  EXPECT_TRUE(rows[0].hasChildren);
  EXPECT_FALSE(rows[3].hasChildren);
  EXPECT_FALSE(rows[6].hasChildren);
}

TEST(OutlinerRows, SearchKeepsMatchesAndTheirAncestorsOnly) {
  // "hand" matches hand.L and Hand.R (case-insensitive); their ancestors come along but
  // are not marked as matches; leg.L is not an ancestor of a match and goes.
  const std::vector<OutlinerRow> rows = outlinerRows(tree(), "HAND", {});
  EXPECT_EQ(joints(rows), (std::vector<int>{0, 1, 2, 3, 4, 5}));
  for (const OutlinerRow& r : rows) EXPECT_EQ(r.matches, r.joint == 3 || r.joint == 5) << r.joint;
  EXPECT_EQ(joints(outlinerRows(tree(), ".L", {})), (std::vector<int>{0, 1, 2, 3, 6}));
  EXPECT_TRUE(outlinerRows(tree(), "nothing", {}).empty());
}

TEST(OutlinerRows, CollapsedJointHidesItsDescendantsButNotWhileSearching) {
  std::vector<bool> collapsed(7, false);
  collapsed[1] = true;  // spine
  EXPECT_EQ(joints(outlinerRows(tree(), "", collapsed)), (std::vector<int>{0, 1, 6}));
  collapsed[0] = true;
  EXPECT_EQ(joints(outlinerRows(tree(), "", collapsed)), (std::vector<int>{0}));
  // A search result must stay reachable even under a collapsed joint.
  EXPECT_EQ(joints(outlinerRows(tree(), "hand.r", collapsed)), (std::vector<int>{0, 1, 4, 5}));
  // A shorter collapsed array than the skeleton is fine.
  EXPECT_EQ(joints(outlinerRows(tree(), "", std::vector<bool>{false, true})), (std::vector<int>{0, 1, 6}));
}

TEST(OutlinerRows, RowsAreDepthFirstWhateverTheSkeletonOrder) {
  // Breadth-first joint order (as BVH-free files may list it): a, b, a1, b1, a2.
  Skeleton s;
  const int a = s.addJoint("a", -1, Transform{});
  const int b = s.addJoint("b", -1, Transform{});
  const int a1 = s.addJoint("a1", a, Transform{});
  s.addJoint("b1", b, Transform{});
  s.addJoint("a2", a1, Transform{});
  EXPECT_EQ(joints(outlinerRows(s, "", {})), (std::vector<int>{0, 2, 4, 1, 3}));
  std::vector<int> depths;
  for (const OutlinerRow& r : outlinerRows(s, "", {})) depths.push_back(r.depth);
  EXPECT_EQ(depths, (std::vector<int>{0, 1, 2, 0, 1}));
  EXPECT_EQ(joints(outlinerRows(s, "2", {})), (std::vector<int>{0, 2, 4}));
}

TEST(OutlinerRows, ContainsIgnoringCase) {
  EXPECT_TRUE(containsIgnoringCase("LeftForeArm", "forearm"));
  EXPECT_TRUE(containsIgnoringCase("abc", ""));
  EXPECT_FALSE(containsIgnoringCase("", "a"));
  EXPECT_FALSE(containsIgnoringCase("arm", "arms"));
}

}  // namespace
}  // namespace kinema::test
