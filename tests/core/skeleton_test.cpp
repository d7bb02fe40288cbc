#include "test_support.h"

#include <cmath>
#include <limits>
#include <string>

#include "core/skeleton.h"

namespace kinema {
namespace KINEMA_UNITY_ID {

// hips
// ├── spine ── head
// └── leg.L ── foot.L
Skeleton smallTree() {
  Skeleton s;
  s.addJoint("hips", -1, Transform::fromTranslation({0, 1, 0}));
  s.addJoint("spine", 0, Transform::fromTranslation({0, 0.3f, 0}));
  s.addJoint("head", 1, Transform::fromTranslation({0, 0.4f, 0}));
  s.addJoint("leg.L", 0, Transform::fromTranslation({0.1f, -0.5f, 0}));
  s.addJoint("foot.L", 3, Transform::fromTranslation({0, -0.45f, 0}));
  return s;
}

// A skeleton from a parent list, names j0, j1, ... and identity rest transforms.
Skeleton fromParents(const std::vector<int>& parents) {
  Skeleton s;
  for (size_t i = 0; i < parents.size(); ++i) {
    s.names.push_back("j" + std::to_string(i));
    s.parents.push_back(parents[i]);
    s.rest.push_back(Transform::identity());
  }
  return s;
}

bool contains(const std::string& haystack, const std::string& needle) {
  return haystack.find(needle) != std::string::npos;
}

TEST(Skeleton, AddJointReturnsIndicesInOrder) {
  Skeleton s;
  EXPECT_TRUE(s.empty());
  EXPECT_EQ(s.addJoint("a", -1, Transform::identity()), 0);
  EXPECT_EQ(s.addJoint("b", 0, Transform::identity()), 1);
  EXPECT_EQ(s.addJoint("c", 0, Transform::identity()), 2);
  EXPECT_EQ(s.size(), 3);
  EXPECT_FALSE(s.empty());
  EXPECT_EQ(s.parents, (std::vector<int>{-1, 0, 0}));
}

TEST(SkeletonValidate, AcceptsTreesForestsAndEmpty) {
  EXPECT_EQ(smallTree().validate(), "");
  // A forest: two roots, the second root after joints of the first tree.
  EXPECT_EQ(fromParents({-1, 0, 1, -1, 3, 0}).validate(), "");
  // Every joint a root.
  EXPECT_EQ(fromParents({-1, -1, -1}).validate(), "");
  // One joint.
  EXPECT_EQ(fromParents({-1}).validate(), "");
  // Nothing at all.
  EXPECT_EQ(Skeleton{}.validate(), "");
}

TEST(SkeletonValidate, RejectsMismatchedArraySizes) {
  Skeleton s = smallTree();
  s.names.pop_back();
  EXPECT_NE(s.validate(), "");
  s = smallTree();
  s.rest.pop_back();
  EXPECT_NE(s.validate(), "");
  s = smallTree();
  s.parents.push_back(0);
  EXPECT_NE(s.validate(), "");
  EXPECT_TRUE(contains(s.validate(), "size")) << s.validate();
}

TEST(SkeletonValidate, RejectsEmptyAndDuplicateNames) {
  Skeleton s = smallTree();
  s.names[2] = "";
  EXPECT_TRUE(contains(s.validate(), "empty name")) << s.validate();
  s = smallTree();
  s.names[4] = "spine";
  const std::string msg = s.validate();
  EXPECT_TRUE(contains(msg, "spine")) << msg;
  EXPECT_TRUE(contains(msg, "same name")) << msg;
}

TEST(SkeletonValidate, RejectsParentIndexOutOfRange) {
  for (int bad : {-2, -100, 5, 6, 1000}) {
    Skeleton s = smallTree();
    s.parents[3] = bad;
    const std::string msg = s.validate();
    EXPECT_TRUE(contains(msg, std::to_string(bad))) << bad << ": " << msg;
    EXPECT_TRUE(contains(msg, "parent")) << bad << ": " << msg;
  }
  // The largest valid index (n - 1) is in range: leg.L <-> foot.L then point at each other,
  // which is reported as a cycle, not as an index out of range.
  Skeleton s = smallTree();
  s.parents[3] = 4;
  EXPECT_TRUE(contains(s.validate(), "cycle")) << s.validate();
  EXPECT_FALSE(contains(s.validate(), "outside")) << s.validate();
}

TEST(SkeletonValidate, RejectsAJointThatIsItsOwnParent) {
  Skeleton s = smallTree();
  s.parents[2] = 2;
  const std::string msg = s.validate();
  EXPECT_NE(msg, "");
  EXPECT_TRUE(contains(msg, "cycle")) << msg;
  s.parents[2] = 1;
  s.parents[0] = 0;  // the root, too
  EXPECT_TRUE(contains(s.validate(), "cycle")) << s.validate();
}

TEST(SkeletonValidate, RejectsAThreeCycle) {
  // j0 root; j1 -> j3 -> j2 -> j1 is a cycle of three joints cut off from the root.
  const Skeleton s = fromParents({-1, 3, 1, 2});
  const std::string msg = s.validate();
  EXPECT_TRUE(contains(msg, "cycle")) << msg;
  // Also a cycle that includes joint 0 (no root at all).
  EXPECT_TRUE(contains(fromParents({2, 0, 1}).validate(), "cycle"));
}

TEST(SkeletonValidate, ParentListedAfterChildIsAnOrderErrorNotACycle) {
  // j0's parent is j1, j1 is a root: a valid tree, but not sorted parent-first.
  const Skeleton s = fromParents({1, -1});
  const std::string msg = s.validate();
  EXPECT_NE(msg, "");
  EXPECT_FALSE(contains(msg, "cycle")) << msg;
  EXPECT_TRUE(contains(msg, "parent")) << msg;
  // Deeper: j0 -> j2 -> j1 (root), j3 -> j0.
  const std::string msg2 = fromParents({2, -1, 1, 0}).validate();
  EXPECT_NE(msg2, "");
  EXPECT_FALSE(contains(msg2, "cycle")) << msg2;
}

TEST(SkeletonValidate, RejectsNonFiniteRestTransforms) {
  const float nan = std::numeric_limits<float>::quiet_NaN();
  const float inf = std::numeric_limits<float>::infinity();
  for (int field = 0; field < 3; ++field) {
    for (float bad : {nan, inf, -inf}) {
      Skeleton s = smallTree();
      Transform& t = s.rest[3];
      if (field == 0) t.translation.y = bad;
      if (field == 1) t.rotation.z = bad;
      if (field == 2) t.scale.x = bad;
      const std::string msg = s.validate();
      EXPECT_TRUE(contains(msg, "non-finite")) << field << " " << bad << ": " << msg;
      EXPECT_TRUE(contains(msg, "leg.L")) << msg;
    }
  }
}

TEST(Skeleton, FindByName) {
  const Skeleton s = smallTree();
  EXPECT_EQ(s.find("hips"), 0);
  EXPECT_EQ(s.find("head"), 2);
  EXPECT_EQ(s.find("foot.L"), 4);
  EXPECT_EQ(s.find("foot.R"), -1);
  EXPECT_EQ(s.find(""), -1);
  EXPECT_EQ(s.find("Hips"), -1);  // case-sensitive
  EXPECT_EQ(Skeleton{}.find("hips"), -1);
}

TEST(Skeleton, IsInSubtree) {
  const Skeleton s = smallTree();  // hips(0) {spine(1) {head(2)}, leg.L(3) {foot.L(4)}}
  for (int j = 0; j < s.size(); ++j) {
    EXPECT_TRUE(s.isInSubtree(j, j)) << j;  // a joint is in its own subtree
    EXPECT_TRUE(s.isInSubtree(j, 0)) << j;  // everything is below the root
  }
  EXPECT_TRUE(s.isInSubtree(2, 1));
  EXPECT_TRUE(s.isInSubtree(4, 3));
  EXPECT_FALSE(s.isInSubtree(1, 2));  // parent is not below its child
  EXPECT_FALSE(s.isInSubtree(0, 1));
  EXPECT_FALSE(s.isInSubtree(4, 1));  // other branch
  EXPECT_FALSE(s.isInSubtree(2, 3));
  EXPECT_FALSE(s.isInSubtree(3, 4));
  // Forest: nothing crosses between trees.
  const Skeleton f = fromParents({-1, 0, -1, 2});
  EXPECT_TRUE(f.isInSubtree(3, 2));
  EXPECT_FALSE(f.isInSubtree(3, 0));
  EXPECT_FALSE(f.isInSubtree(1, 2));
}

}  // namespace
}  // namespace kinema
