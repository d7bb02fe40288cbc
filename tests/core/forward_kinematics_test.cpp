#include "test_support.h"

#include <cmath>
#include <cstring>
#include <functional>
#include <random>
#include <string>
#include <vector>

#include <glm/gtc/matrix_transform.hpp>

#include "core/forward_kinematics.h"

namespace kinema {
namespace KINEMA_UNITY_ID {

glm::vec3 position(const glm::mat4& m) { return glm::vec3(m[3]); }

glm::quat normalized(float w, float x, float y, float z) {
  return glm::normalize(glm::quat(w, x, y, z));
}

// The textbook chain: P0 (root) -> P1 -> P2 -> P3, bones along +x with lengths l01, l12, l23.
Skeleton threeBoneChain(const glm::vec3& p0, float l01, float l12, float l23) {
  Skeleton s;
  s.addJoint("P0", -1, Transform::fromTranslation(p0));
  s.addJoint("P1", 0, Transform::fromTranslation({l01, 0, 0}));
  s.addJoint("P2", 1, Transform::fromTranslation({l12, 0, 0}));
  s.addJoint("P3", 2, Transform::fromTranslation({l23, 0, 0}));
  return s;
}

// ---------------------------------------------------------------------------------------
// (a) The three-bone chain.

TEST(ThreeBoneChain, QuarterTurnsDerivedByHand) {
  // Lengths 1, 2, 1.5; P0 at the origin. Local rotations:
  //   q0 = 90 deg about Z, q1 = -90 deg about Z, q2 = 90 deg about Y, q3 = identity.
  // Global rotations (q_i = q_{i-1} q_i^local):
  //   q0 = Rz(90);  q1 = Rz(90) Rz(-90) = I;  q2 = I Ry(90) = Ry(90);  q3 = Ry(90).
  // Positions (p_i = p_{i-1} + q_{i-1} l^init q_{i-1}*):
  //   p0 = (0, 0, 0)
  //   p1 = p0 + Rz(90) (1, 0, 0)   = (0, 1, 0)          [Rz(90): x -> y]
  //   p2 = p1 + I (2, 0, 0)        = (2, 1, 0)
  //   p3 = p2 + Ry(90) (1.5, 0, 0) = (2, 1, 0) + (0, 0, -1.5) = (2, 1, -1.5)
  //                                                      [Ry(90): x -> -z]
  const Skeleton s = threeBoneChain({0, 0, 0}, 1.0f, 2.0f, 1.5f);
  ASSERT_EQ(s.validate(), "");
  Pose pose = Pose::rest(s);
  const float h = static_cast<float>(std::sqrt(0.5));
  pose.local[0].rotation = glm::quat(h, 0, 0, h);   // +90 about Z
  pose.local[1].rotation = glm::quat(h, 0, 0, -h);  // -90 about Z
  pose.local[2].rotation = glm::quat(h, 0, h, 0);   // +90 about Y
  const std::vector<glm::mat4> w = computeWorld(s, pose);
  ASSERT_EQ(w.size(), 4u);
  EXPECT_VEC3_NEAR(position(w[0]), glm::vec3(0, 0, 0), 1e-6f);
  EXPECT_VEC3_NEAR(position(w[1]), glm::vec3(0, 1, 0), 1e-6f);
  EXPECT_VEC3_NEAR(position(w[2]), glm::vec3(2, 1, 0), 1e-6f);
  EXPECT_VEC3_NEAR(position(w[3]), glm::vec3(2, 1, -1.5f), 1e-6f);
  // Global orientations, read off the matrix columns (images of the local axes).
  // q1 = I: the axes of P1 are the world axes.
  EXPECT_VEC3_NEAR(glm::vec3(w[1][0]), glm::vec3(1, 0, 0), 1e-6f);
  EXPECT_VEC3_NEAR(glm::vec3(w[1][1]), glm::vec3(0, 1, 0), 1e-6f);
  // q0 = Rz(90): local x -> world y, local y -> world -x.
  EXPECT_VEC3_NEAR(glm::vec3(w[0][0]), glm::vec3(0, 1, 0), 1e-6f);
  EXPECT_VEC3_NEAR(glm::vec3(w[0][1]), glm::vec3(-1, 0, 0), 1e-6f);
  // q3 = Ry(90): local x -> world -z, local z -> world x.
  EXPECT_VEC3_NEAR(glm::vec3(w[3][0]), glm::vec3(0, 0, -1), 1e-6f);
  EXPECT_VEC3_NEAR(glm::vec3(w[3][2]), glm::vec3(1, 0, 0), 1e-6f);
}

TEST(ThreeBoneChain, NonAxisRotationsMatchIndependentScript) {
  // Expected values printed by tests/tools/three_bone_chain.py (plain-Python quaternion
  // arithmetic following the textbook recurrences; run it to regenerate).
  const Skeleton s = threeBoneChain({0.5f, -1.0f, 2.0f}, 1.0f, 2.0f, 1.5f);
  Pose pose = Pose::rest(s);
  pose.local[0].rotation = normalized(0.9f, 0.2f, -0.3f, 0.25f);
  pose.local[1].rotation = normalized(0.7f, -0.4f, 0.5f, 0.1f);
  pose.local[2].rotation = normalized(0.6f, 0.3f, 0.2f, -0.7f);
  pose.local[3].rotation = normalized(0.8f, 0.1f, 0.1f, 0.5f);
  const std::vector<glm::mat4> w = computeWorld(s, pose);
  const glm::vec3 p[4] = {{0.500000000f, -1.000000000f, 2.000000000f},
                          {1.195760599f, -0.670822943f, 2.638403990f},
                          {2.869433559f, 0.028856430f, 1.796223726f},
                          {3.351506578f, -1.389833333f, 1.866401780f}};
  const glm::quat q[4] = {{0.898877105f, 0.199750468f, -0.299625702f, 0.249688085f},
                          {0.874225739f, -0.392616350f, 0.125637232f, 0.256509348f},
                          {0.804838480f, -0.113692689f, 0.052880321f, -0.580097117f},
                          {0.985388354f, 0.077551660f, 0.127497368f, -0.082097218f}};
  for (int i = 0; i < 4; ++i) {
    EXPECT_VEC3_NEAR(position(w[i]), p[i], 2e-6f);
    // World rotation: the matrix's upper 3x3 is q_i's rotation matrix.
    const glm::mat3 r = glm::mat3_cast(q[i]);
    for (int c = 0; c < 3; ++c) EXPECT_VEC3_NEAR(glm::vec3(w[i][c]), r[c], 2e-6f);
  }
}

// ---------------------------------------------------------------------------------------
// Random skeletons and a naive recursive reference.

using test::randomRotation;

// 100 joints: mostly a long chain (`chainy`) or a bushy random tree, with a few extra roots.
Skeleton randomSkeleton(std::mt19937& rng, int n, bool chainy, bool unitScale) {
  std::uniform_real_distribution<float> u(0.0f, 1.0f), t(-1.0f, 1.0f), sc(0.8f, 1.25f);
  Skeleton s;
  for (int i = 0; i < n; ++i) {
    int parent = -1;
    if (i > 0 && u(rng) > 0.03f) {
      if (chainy && u(rng) < 0.95f)
        parent = i - 1;
      else
        parent = std::uniform_int_distribution<int>(0, i - 1)(rng);
    }
    Transform x;
    x.translation = {t(rng), t(rng), t(rng)};
    x.rotation = randomRotation(rng);
    if (!unitScale && u(rng) < 0.75f) x.scale = glm::vec3(sc(rng));
    s.addJoint("j" + std::to_string(i), parent, x);
  }
  return s;
}

// Reference: world(i) = world(parent) * T * R * S, recursively, in double precision, with
// glm::translate / glm::mat4_cast / glm::scale (no code shared with the library).
glm::dmat4 referenceWorld(const Skeleton& s, const Pose& pose, int i, const glm::dmat4& root) {
  const Transform& x = pose.local[i];
  const glm::dquat q(x.rotation.w, x.rotation.x, x.rotation.y, x.rotation.z);
  const glm::dmat4 local = glm::translate(glm::dmat4(1.0), glm::dvec3(x.translation)) *
                           glm::mat4_cast(q) * glm::scale(glm::dmat4(1.0), glm::dvec3(x.scale));
  const int p = s.parents[i];
  return (p < 0 ? root : referenceWorld(s, pose, p, root)) * local;
}

// Largest entry difference, relative to the size of the expected matrix (at least 1).
double relativeError(const glm::mat4& got, const glm::dmat4& want) {
  double diff = 0.0, size = 1.0;
  for (int c = 0; c < 4; ++c)
    for (int r = 0; r < 4; ++r) {
      diff = std::max(diff, std::abs(static_cast<double>(got[c][r]) - want[c][r]));
      size = std::max(size, std::abs(want[c][r]));
    }
  return diff / size;
}

glm::mat4 randomPlacement(std::mt19937& rng) {
  std::uniform_real_distribution<float> t(-5.0f, 5.0f), sc(0.5f, 2.0f);
  return glm::translate(glm::mat4(1.0f), glm::vec3(t(rng), t(rng), t(rng))) *
         glm::mat4_cast(randomRotation(rng)) * glm::scale(glm::mat4(1.0f), glm::vec3(sc(rng)));
}

TEST(ForwardKinematics, RandomSkeletonsMatchRecursiveReference) {
  std::mt19937 rng(2024);
  const int cases = test::propertyCases(200);
  for (int c = 0; c < cases; ++c) {
    const Skeleton s = randomSkeleton(rng, 100, c % 2 == 0, c % 5 == 0);
    ASSERT_EQ(s.validate(), "");
    Pose pose = Pose::rest(s);
    for (Transform& x : pose.local) x.rotation = randomRotation(rng);  // a posed skeleton
    // Half the cases through computeWorld (root = identity), half through the job with a
    // placement matrix.
    const bool placed = c % 2 == 1;
    const glm::mat4 root = placed ? randomPlacement(rng) : glm::mat4(1.0f);
    std::vector<glm::mat4> w;
    if (!placed) {
      w = computeWorld(s, pose);
    } else {
      w.assign(s.size(), glm::mat4(0.0f));
      LocalToWorldJob job;
      job.parents = s.parents.data();
      job.local = pose.local.data();
      job.world = w.data();
      job.count = s.size();
      job.root = root;
      ASSERT_TRUE(job.run()) << job.validate();
    }
    ASSERT_EQ(w.size(), 100u);
    for (int i = 0; i < s.size(); ++i) {
      const double err = relativeError(w[i], referenceWorld(s, pose, i, glm::dmat4(root)));
      ASSERT_LT(err, 1e-4) << "case " << c << " joint " << i;
      // Affine: bottom row stays (0, 0, 0, 1).
      ASSERT_EQ(w[i][0][3], 0.0f);
      ASSERT_EQ(w[i][3][3], 1.0f);
    }
  }
}

// ---------------------------------------------------------------------------------------
// (c) updateSubtree.

TEST(ForwardKinematics, UpdateSubtreeEqualsFullRecomputeAndLeavesOthersUntouched) {
  std::mt19937 rng(7);
  const int cases = test::propertyCases(200);
  for (int c = 0; c < cases; ++c) {
    const Skeleton s = randomSkeleton(rng, 100, c % 2 == 0, false);
    Pose pose = Pose::rest(s);
    std::vector<glm::mat4> world = computeWorld(s, pose);
    const int k = std::uniform_int_distribution<int>(0, s.size() - 1)(rng);
    pose.local[k].rotation = randomRotation(rng);
    const std::vector<glm::mat4> full = computeWorld(s, pose);
    // Joints outside the sub-tree that the update has no reason to read (not ancestors of
    // k) get a sentinel: it must survive bit for bit.
    const glm::mat4 sentinel(1234.5f);
    for (int j = 0; j < s.size(); ++j)
      if (!s.isInSubtree(j, k) && !s.isInSubtree(k, j)) world[j] = sentinel;
    const std::vector<glm::mat4> before = world;
    updateSubtree(s, pose, k, world);
    int inside = 0;
    for (int j = 0; j < s.size(); ++j) {
      if (s.isInSubtree(j, k)) {
        ++inside;
        for (int col = 0; col < 4; ++col)
          for (int row = 0; row < 4; ++row)
            EXPECT_NEAR(world[j][col][row], full[j][col][row], 1e-5f)
                << "case " << c << " joint " << j << " below " << k;
      } else {
        EXPECT_EQ(std::memcmp(&world[j], &before[j], sizeof(glm::mat4)), 0)
            << "case " << c << " joint " << j << " outside the sub-tree of " << k << " changed";
      }
    }
    EXPECT_GE(inside, 1);
    if (HasFailure()) return;
  }
}

TEST(ForwardKinematics, UpdateSubtreeOfARootAppliesTheRootPlacement) {
  // Forest: a (root) -> b, c (root) -> d. Update c's sub-tree with a placement matrix.
  Skeleton s;
  s.addJoint("a", -1, Transform::fromTranslation({1, 0, 0}));
  s.addJoint("b", 0, Transform::fromTranslation({0, 1, 0}));
  s.addJoint("c", -1, Transform::fromTranslation({0, 0, 2}));
  s.addJoint("d", 2, Transform::fromTranslation({0, 3, 0}));
  Pose pose = Pose::rest(s);
  std::vector<glm::mat4> w(4, glm::mat4(7.0f));
  LocalToWorldJob job;
  job.parents = s.parents.data();
  job.local = pose.local.data();
  job.world = w.data();
  job.count = 4;
  job.root = glm::translate(glm::mat4(1.0f), glm::vec3(10, 20, 30));
  job.subtreeRoot = 2;
  ASSERT_TRUE(job.run());
  EXPECT_VEC3_NEAR(position(w[2]), glm::vec3(10, 20, 32), 1e-6f);
  EXPECT_VEC3_NEAR(position(w[3]), glm::vec3(10, 23, 32), 1e-6f);
  EXPECT_EQ(w[0], glm::mat4(7.0f));
  EXPECT_EQ(w[1], glm::mat4(7.0f));
}

// ---------------------------------------------------------------------------------------
// (d) LocalToWorldJob::validate.

struct JobFixture {
  std::vector<int> parents{-1, 0, 1, 0};
  std::vector<Transform> local = std::vector<Transform>(4, Transform::fromTranslation({1, 0, 0}));
  std::vector<glm::mat4> world = std::vector<glm::mat4>(4, glm::mat4(3.0f));
  LocalToWorldJob job() {
    LocalToWorldJob j;
    j.parents = parents.data();
    j.local = local.data();
    j.world = world.data();
    j.count = 4;
    return j;
  }
  // run() must fail and leave world[] as it was.
  void expectRejected(const LocalToWorldJob& j, const std::string& what) {
    EXPECT_NE(j.validate(), "") << what;
    EXPECT_FALSE(j.run()) << what;
    for (const glm::mat4& m : world) EXPECT_EQ(m, glm::mat4(3.0f)) << what << " wrote world";
  }
};

TEST(LocalToWorldJob, ValidateAcceptsGoodInputs) {
  JobFixture f;
  EXPECT_EQ(f.job().validate(), "");
  LocalToWorldJob j = f.job();
  j.subtreeRoot = 3;
  EXPECT_EQ(j.validate(), "");
  // No joints: nothing to read, nothing to write.
  LocalToWorldJob empty;
  EXPECT_EQ(empty.validate(), "");
  EXPECT_TRUE(empty.run());
}

TEST(LocalToWorldJob, ValidateRejectsBadInputs) {
  {
    JobFixture f;
    LocalToWorldJob j = f.job();
    j.parents = nullptr;
    f.expectRejected(j, "null parents");
  }
  {
    JobFixture f;
    LocalToWorldJob j = f.job();
    j.local = nullptr;
    f.expectRejected(j, "null local");
  }
  {
    JobFixture f;
    LocalToWorldJob j = f.job();
    j.world = nullptr;
    EXPECT_NE(j.validate(), "");
    EXPECT_FALSE(j.run());
  }
  {
    JobFixture f;
    LocalToWorldJob j = f.job();
    j.count = -1;
    f.expectRejected(j, "negative count");
  }
  for (int bad : {-2, 4, 100}) {
    JobFixture f;
    LocalToWorldJob j = f.job();
    j.subtreeRoot = bad;
    f.expectRejected(j, "subtreeRoot " + std::to_string(bad));
  }
  for (int bad : {2, 3, 7, -2}) {  // joint 2's parent: itself, later, out of range, < -1
    JobFixture f;
    f.parents[2] = bad;
    f.expectRejected(f.job(), "parents[2] = " + std::to_string(bad));
  }
  {
    JobFixture f;
    f.parents[0] = 0;  // the root its own parent
    f.expectRejected(f.job(), "parents[0] = 0");
  }
}

// ---------------------------------------------------------------------------------------
// (e) The root placement matrix.

TEST(LocalToWorldJob, RootPlacementHandCase) {
  // Root joint at local (0,0,0), child at local (1,0,0). Placement: 90 degrees about Y,
  // then translate by (10,0,0): the child lands at (10,0,0) + Ry(90)(1,0,0) = (10,0,-1).
  // Scale 2 on top: (10,0,0) + 2 * (0,0,-1) = (10,0,-2).
  Skeleton s = threeBoneChain({0, 0, 0}, 1.0f, 1.0f, 1.0f);
  const Pose pose = Pose::rest(s);
  std::vector<glm::mat4> w(4);
  LocalToWorldJob job;
  job.parents = s.parents.data();
  job.local = pose.local.data();
  job.world = w.data();
  job.count = 4;
  const float h = static_cast<float>(std::sqrt(0.5));
  job.root = glm::translate(glm::mat4(1.0f), glm::vec3(10, 0, 0)) * glm::mat4_cast(glm::quat(h, 0, h, 0));
  ASSERT_TRUE(job.run());
  EXPECT_VEC3_NEAR(position(w[0]), glm::vec3(10, 0, 0), 1e-6f);
  EXPECT_VEC3_NEAR(position(w[1]), glm::vec3(10, 0, -1), 1e-6f);
  EXPECT_VEC3_NEAR(position(w[3]), glm::vec3(10, 0, -3), 1e-6f);
  job.root = job.root * glm::scale(glm::mat4(1.0f), glm::vec3(2.0f));
  ASSERT_TRUE(job.run());
  EXPECT_VEC3_NEAR(position(w[1]), glm::vec3(10, 0, -2), 1e-6f);
  EXPECT_VEC3_NEAR(position(w[3]), glm::vec3(10, 0, -6), 1e-5f);
}

TEST(LocalToWorldJob, RootPlacementPremultipliesEveryJoint) {
  std::mt19937 rng(3);
  for (int c = 0; c < 20; ++c) {
    const Skeleton s = randomSkeleton(rng, 100, c % 2 == 0, false);
    const Pose pose = Pose::rest(s);
    const std::vector<glm::mat4> unplaced = computeWorld(s, pose);
    const glm::mat4 root = randomPlacement(rng);
    std::vector<glm::mat4> w(s.size());
    LocalToWorldJob job;
    job.parents = s.parents.data();
    job.local = pose.local.data();
    job.world = w.data();
    job.count = s.size();
    job.root = root;
    ASSERT_TRUE(job.run());
    for (int i = 0; i < s.size(); ++i) {
      const glm::dmat4 want = glm::dmat4(root) * glm::dmat4(unplaced[i]);
      ASSERT_LT(relativeError(w[i], want), 1e-4) << "case " << c << " joint " << i;
    }
  }
}

// ---------------------------------------------------------------------------------------
// (f) Rotations never change bone lengths.

TEST(ForwardKinematics, RotatingJointsKeepsBoneLengths) {
  std::mt19937 rng(17);
  for (int c = 0; c < 50; ++c) {
    const Skeleton s = randomSkeleton(rng, 100, c % 2 == 0, true);
    Pose pose = Pose::rest(s);
    for (int pass = 0; pass < 2; ++pass) {
      const std::vector<glm::mat4> w = computeWorld(s, pose);
      for (int i = 0; i < s.size(); ++i) {
        const int p = s.parents[i];
        if (p < 0) continue;
        const float bone = glm::length(s.rest[i].translation);
        EXPECT_NEAR(glm::distance(position(w[i]), position(w[p])), bone, 2e-5f)
            << "case " << c << " joint " << i;
      }
      for (Transform& x : pose.local) x.rotation = randomRotation(rng);
    }
    if (HasFailure()) return;
  }
}

}  // namespace
}  // namespace kinema
