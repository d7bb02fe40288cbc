// Ray picking against the octahedra and spheres SkeletonDrawJob produces, and box select.
// Skeleton: a vertical chain of joints at (0,0,0), (0,2,0), (0,4,0) with identity rotations.
// Bones have length 2, so makeOctahedralBone's waist corners (+-0.1, 0.1, +-0.1) become
// (+-0.2, 0.2, +-0.2) and the front face (the one between the two +z corners and the tail)
// sits at z = 0.2 (2 - y) / 1.8 for y in [0.2, 2]. Joint radius: a tenth of the shortest bone
// (0.2) clamped to 0.025 * size, with size the box's half diagonal (2) taken up to the next
// power of 1.25 (2.44140625): 0.06103515625.
#include "editor/viewport/box_select.h"
#include "editor/viewport/picking.h"
#include "editor/viewport/viewport_controller.h"
#include "editor/viewport_test_views.h"
#include "test_support.h"

namespace kinema::test {
namespace KINEMA_UNITY_ID {

struct Chain {
  std::vector<int> parents{-1, 0, 1};
  std::vector<glm::mat4> world;
  SkeletonDrawList list;
  Chain() {
    for (float y : {0.0f, 2.0f, 4.0f}) {
      glm::mat4 m(1.0f);
      m[3] = glm::vec4(0, y, 0, 1);
      world.push_back(m);
    }
    SkeletonDrawJob job;
    job.parents = &parents;
    job.world = &world;
    EXPECT_TRUE(job.run(list));
  }
};

TEST(Picking, RayTriangleAndRaySphereDistances) {
  const PickRay down{{0, 0, 5}, {0, 0, -1}};
  const glm::vec3 a(-1, -1, 0), b(1, -1, 0), c(0, 1, 0);
  EXPECT_NEAR(rayTriangleDistance(down, a, b, c), 5.0f, 1e-6f);
  EXPECT_NEAR(rayTriangleDistance(down, a, c, b), 5.0f, 1e-6f);  // either winding
  EXPECT_LT(rayTriangleDistance({{2, 2, 5}, {0, 0, -1}}, a, b, c), 0.0f);   // beside it
  EXPECT_LT(rayTriangleDistance({{0, 0, -5}, {0, 0, -1}}, a, b, c), 0.0f);  // behind the origin
  EXPECT_NEAR(raySphereDistance(down, {0, 0, 0}, 1.0f), 4.0f, 1e-6f);
  // Off-centre by 0.6: the surface is sqrt(1 - 0.36) = 0.8 in front of the centre.
  EXPECT_NEAR(raySphereDistance({{0.6f, 0, 5}, {0, 0, -1}}, {0, 0, 0}, 1.0f), 4.2f, 1e-5f);
  EXPECT_LT(raySphereDistance({{1.1f, 0, 5}, {0, 0, -1}}, {0, 0, 0}, 1.0f), 0.0f);
}

TEST(Picking, DrawListRecordsEachBonesJoints) {
  Chain c;
  ASSERT_EQ(c.list.boneParents, (std::vector<int>{0, 1}));
  ASSERT_EQ(c.list.boneChildren, (std::vector<int>{1, 2}));
  // A tenth of the 2 m bones (0.2) capped at 0.025 x the skeleton's size: its bounds radius 2
  // taken up to a power of 1.25 (1.25^4 = 2.44140625), so 0.06103515625.
  EXPECT_NEAR(glm::length(glm::vec3(c.list.jointMatrices[0][0])), 0.06103515625f, 1e-6f);
}

TEST(Picking, ClickOnABoneSelectsItsHeadJoint) {
  Chain c;
  const ViewportView ortho = handView(true);
  // Pixel (100, 90) is world (0, 1); the front face is at z = 0.2 * 1 / 1.8, the ray starts at z = 9.9.
  const SkeletonPick pick = pickSkeletonAt(c.list, ortho, {100, 90});
  EXPECT_EQ(pick.joint, 0);
  EXPECT_EQ(pick.boneChild, 1);
  EXPECT_NEAR(pick.distance, 9.9f - 0.2f / 1.8f, 1e-4f);
  // Upper bone, y = 3: head joint 1.
  const SkeletonPick upper = pickSkeletonAt(c.list, ortho, {100, 70});
  EXPECT_EQ(upper.joint, 1);
  EXPECT_EQ(upper.boneChild, 2);
  // Perspective: the same bone under the pixel of (0, 1, 0).
  const SkeletonPick persp = pickSkeletonAt(c.list, handView(false), {100, 90});
  EXPECT_EQ(persp.joint, 0);
  EXPECT_EQ(persp.boneChild, 1);
  EXPECT_LT(persp.distance, std::sqrt(101.0f));  // in front of the bone's axis
}

TEST(Picking, JointSphereWinsOverTheBonesMeetingThere) {
  Chain c;
  // Pixel (100, 80) is joint 1 at (0, 2, 0): its sphere's front is at z = 0.0610 (radius above).
  const SkeletonPick pick = pickSkeleton(c.list, handView(true).rayThrough({100, 80}));
  EXPECT_EQ(pick.joint, 1);
  EXPECT_EQ(pick.boneChild, -1);
  EXPECT_NEAR(pick.distance, 9.9f - 0.06103515625f, 1e-4f);
}

TEST(Picking, MissFallsBackToTheNearestJointOnScreen) {
  Chain c;
  const ViewportView ortho = handView(true);
  // (104, 64) is world (0.4, 3.6): beside the bone (half-width 0.2 * 0.4 / 1.8 there) and the
  // sphere (radius 0.061); joint 2 projects to (100, 60), sqrt(32) = 5.7 px away.
  EXPECT_FALSE(pickSkeleton(c.list, ortho.rayThrough({104, 64})).hit());
  const SkeletonPick near = pickSkeletonAt(c.list, ortho, {104, 64}, 8.0f);
  EXPECT_EQ(near.joint, 2);
  EXPECT_EQ(near.boneChild, -1);
  EXPECT_FALSE(pickSkeletonAt(c.list, ortho, {104, 64}, 5.0f).hit());
  // (104, 70): 10.8 px from joints 1 and 2, nothing within 8.
  EXPECT_FALSE(pickSkeletonAt(c.list, ortho, {104, 70}, 8.0f).hit());
}

TEST(BoxSelect, EitherDragDirectionSelectsTheSameJoints) {
  Chain c;
  for (bool ortho : {false, true}) {
    const ViewportView v = handView(ortho);
    // Joints project to (100, 100), (100, 80), (100, 60) in both modes (all at depth 10).
    EXPECT_EQ(boxSelectJoints(c.world, v, {90, 55}, {110, 85}), (std::vector<int>{1, 2}));
    EXPECT_EQ(boxSelectJoints(c.world, v, {110, 85}, {90, 55}), (std::vector<int>{1, 2}));
    EXPECT_EQ(boxSelectJoints(c.world, v, {110, 55}, {90, 85}), (std::vector<int>{1, 2}));
    EXPECT_EQ(boxSelectJoints(c.world, v, {0, 0}, {200, 200}), (std::vector<int>{0, 1, 2}));
    EXPECT_TRUE(boxSelectJoints(c.world, v, {0, 0}, {50, 50}).empty());
  }
}

TEST(BoxSelect, JointsBehindTheCameraAreNeverSelected) {
  // Perspective: (0, -1.5, 15) is 5 behind the eye; the naive divide by w = -5 would put it at
  // pixel (100, 100 - 100 * 0.3) = (100, 70), inside the box.
  glm::mat4 behind(1.0f);
  behind[3] = glm::vec4(0, -1.5f, 15, 1);
  EXPECT_TRUE(boxSelectJoints({behind}, handView(false), {90, 55}, {110, 85}).empty());
  // Orthographic: (0, 3, 15) would land on pixel (100, 70) but lies behind the eye (z = 10).
  behind[3] = glm::vec4(0, 3, 15, 1);
  EXPECT_TRUE(boxSelectJoints({behind}, handView(true), {90, 55}, {110, 85}).empty());
  behind[3] = glm::vec4(0, 3, 5, 1);  // in front: selected
  EXPECT_EQ(boxSelectJoints({behind}, handView(true), {90, 55}, {110, 85}), (std::vector<int>{0}));
}

}  // namespace
}  // namespace kinema::test
