// The FK job fuses quaternion-to-matrix and the parent multiply for speed. These tests pin
// that it computes exactly (bit for bit) what the plain definition
// world[i] = multiplyAffine(world[parent], local[i].toMatrix()) gives, and that its
// sub-tree path and validation behave as documented.
#include <cstring>
#include <random>
#include <vector>

#include "core/forward_kinematics.h"
#include "test_support.h"

namespace kinema {
namespace KINEMA_UNITY_ID {

struct Random {
  std::mt19937 rng;
  explicit Random(uint32_t seed) : rng(seed) {}
  float real(float lo, float hi) { return std::uniform_real_distribution<float>(lo, hi)(rng); }
  int integer(int lo, int hi) { return std::uniform_int_distribution<int>(lo, hi)(rng); }
  Transform transform() {
    Transform t;
    t.translation = glm::vec3(real(-5, 5), real(-5, 5), real(-5, 5));
    t.rotation = glm::normalize(glm::quat(real(-1, 1), real(-1, 1), real(-1, 1), real(-1, 1)));
    t.scale = glm::vec3(real(-2, 2), real(0.1f, 3), real(0.5f, 1.5f));
    return t;
  }
};

Skeleton randomSkeleton(Random& r, int n) {
  Skeleton s;
  for (int i = 0; i < n; ++i)
    s.addJoint("j" + std::to_string(i), i == 0 ? -1 : r.integer(-1, i - 1), r.transform());
  return s;
}

// The definition, written without the job.
std::vector<glm::mat4> reference(const Skeleton& s, const Pose& pose, const glm::mat4& root) {
  std::vector<glm::mat4> world(static_cast<size_t>(s.size()));
  for (int i = 0; i < s.size(); ++i)
    world[i] = multiplyAffine(s.parents[i] < 0 ? root : world[s.parents[i]], pose.local[i].toMatrix());
  return world;
}

void expectBitIdentical(const std::vector<glm::mat4>& want, const std::vector<glm::mat4>& got) {
  ASSERT_EQ(want.size(), got.size());
  for (size_t i = 0; i < want.size(); ++i)
    EXPECT_EQ(std::memcmp(&want[i], &got[i], sizeof(glm::mat4)), 0) << "joint " << i;
}

TEST(ForwardKinematicsFused, MatchesTheUnfusedDefinitionBitForBit) {
  Random r(42);
  const int cases = test::propertyCases(200);
  for (int c = 0; c < cases; ++c) {
    const Skeleton s = randomSkeleton(r, r.integer(1, 80));
    Pose pose = Pose::rest(s);
    for (Transform& t : pose.local) t = r.transform();
    LocalToWorldJob job;
    std::vector<glm::mat4> world(static_cast<size_t>(s.size()));
    job.parents = s.parents.data();
    job.local = pose.local.data();
    job.world = world.data();
    job.count = s.size();
    job.root = c % 2 ? glm::mat4(1.0f) : multiplyAffine(glm::mat4(1.0f), r.transform().toMatrix());
    ASSERT_TRUE(job.run());
    expectBitIdentical(reference(s, pose, job.root), world);
    if (c % 2) expectBitIdentical(reference(s, pose, glm::mat4(1.0f)), computeWorld(s, pose));
    if (HasFailure()) break;
  }
}

TEST(ForwardKinematicsFused, HandComputedChain) {
  // Root at (1,2,3) turned 90 degrees about Z; child offset (1,0,0) scaled by 2 in the
  // root: the child lies at (1,2,3) + Rz(90) * (2*1, 0, 0) = (1, 4, 3).
  Skeleton s;
  Transform root = Transform::fromTranslation(glm::vec3(1, 2, 3));
  root.rotation = glm::quat(std::sqrt(0.5f), 0.0f, 0.0f, std::sqrt(0.5f));
  root.scale = glm::vec3(2.0f);
  s.addJoint("root", -1, root);
  s.addJoint("child", 0, Transform::fromTranslation(glm::vec3(1, 0, 0)));
  const std::vector<glm::mat4> w = computeWorld(s, Pose::rest(s));
  EXPECT_VEC3_NEAR(glm::vec3(w[1][3]), glm::vec3(1, 4, 3), 1e-5f);
  // The child's X axis is the root's: Rz(90) * 2 * X = (0, 2, 0).
  EXPECT_VEC3_NEAR(glm::vec3(w[1][0]), glm::vec3(0, 2, 0), 1e-5f);
  EXPECT_EQ(w[1][3].w, 1.0f);
  EXPECT_EQ(w[1][0].w, 0.0f);
}

TEST(ForwardKinematicsFused, SubtreeUpdateMatchesAFullRecomputeAndLeavesOthers) {
  Random r(9);
  for (int c = 0; c < 50; ++c) {
    // Large enough, some of the time, for the sub-tree marks to leave the small buffer.
    const Skeleton s = randomSkeleton(r, c % 5 == 0 ? r.integer(1100, 1500) : r.integer(1, 60));
    Pose pose = Pose::rest(s);
    std::vector<glm::mat4> world = computeWorld(s, pose);
    const int joint = r.integer(0, s.size() - 1);
    for (int i = 0; i < s.size(); ++i)
      if (s.isInSubtree(i, joint)) pose.local[i] = r.transform();
    // A sentinel outside the sub-tree (and not above it, where the job reads) must survive:
    // the job may only write the sub-tree.
    int outside = -1;
    for (int i = 0; i < s.size() && outside < 0; ++i)
      if (!s.isInSubtree(i, joint) && !s.isInSubtree(joint, i)) outside = i;
    if (outside >= 0) world[outside][0][0] = 12345.0f;
    std::vector<glm::mat4> want = reference(s, pose, glm::mat4(1.0f));
    if (outside >= 0) want[outside][0][0] = 12345.0f;
    updateSubtree(s, pose, joint, world);
    expectBitIdentical(want, world);
    if (HasFailure()) break;
  }
}

TEST(ForwardKinematicsFused, InvalidJobWritesNothing) {
  const int parents[3] = {-1, 0, 2};  // joint 2 is its own parent
  const Transform local[3];
  glm::mat4 world[3];
  for (glm::mat4& m : world) m = glm::mat4(7.0f);
  LocalToWorldJob job;
  job.parents = parents;
  job.local = local;
  job.world = world;
  job.count = 3;
  EXPECT_NE(job.validate().find("joint 2"), std::string::npos) << job.validate();
  EXPECT_FALSE(job.run());
  for (const glm::mat4& m : world) EXPECT_EQ(m, glm::mat4(7.0f));
  const int good[3] = {-1, 0, 0};
  job.parents = good;
  job.subtreeRoot = 3;
  EXPECT_NE(job.validate(), "");
  EXPECT_FALSE(job.run());
  job.subtreeRoot = -1;
  job.world = nullptr;
  EXPECT_NE(job.validate(), "");
  EXPECT_FALSE(job.run());
  job.count = 0;  // nothing to do: valid without arrays
  job.parents = nullptr;
  job.local = nullptr;
  EXPECT_EQ(job.validate(), "");
  EXPECT_TRUE(job.run());
}

}  // namespace
}  // namespace kinema
