// Spring bones (issue 23): with the parent still a displaced chain settles back to its
// animated direction; under gravity alone it hangs straight down, and against a stiffness the
// one-bone equilibrium satisfies tan(theta) = g / (k L) (tangential forces balance); bone
// lengths hold, tails stay out of colliders, the same input gives the same bits, and a baked
// clip replays the simulation.
#include "sim/spring_bones.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>

#include "anim/sampling.h"
#include "core/forward_kinematics.h"
#include "test_support.h"

namespace kinema {
namespace KINEMA_UNITY_ID {

constexpr float kDegrees = 57.29578f;

// root (still) -> a -> b -> c, each 0.5 m further along `dir`.
Skeleton straightChain(const glm::vec3& dir) {
  Skeleton s;
  s.addJoint("root", -1, Transform{});
  s.addJoint("a", 0, Transform::fromTranslation(dir * 0.5f));
  s.addJoint("b", 1, Transform::fromTranslation(dir * 0.5f));
  s.addJoint("c", 2, Transform::fromTranslation(dir * 0.5f));
  return s;
}

float angleBetween(const glm::vec3& u, const glm::vec3& v) {
  return std::acos(std::clamp(glm::dot(glm::normalize(u), glm::normalize(v)), -1.0f, 1.0f)) * kDegrees;
}

SpringBoneJob jobFor(const Skeleton& s, const std::vector<SpringBoneChain>& chains, Pose& pose, SpringBoneState& state,
                     float dt) {
  SpringBoneJob job;
  job.skeleton = &s;
  job.chains = &chains;
  job.dt = dt;
  job.pose = &pose;
  job.state = &state;
  return job;
}

// Runs `seconds` of steps on the rest pose; returns the world matrices of the last pose.
std::vector<glm::mat4> simulate(const Skeleton& s, const std::vector<SpringBoneChain>& chains, SpringBoneState& state,
                                float seconds, float dt = 1.0f / 60.0f) {
  Pose pose = Pose::rest(s);
  SpringBoneJob job = jobFor(s, chains, pose, state, dt);
  EXPECT_EQ(job.validate(), "");
  const int steps = static_cast<int>(std::lround(seconds / dt));
  for (int i = 0; i < steps; ++i) {
    pose = Pose::rest(s);
    EXPECT_TRUE(job.run());
  }
  return computeWorld(s, pose);
}

TEST(SpringBones, ADisplacedChainSettlesToItsRestDirectionWithoutGravity) {
  const Skeleton s = straightChain({0, 1, 0});
  SpringBoneChain chain;
  chain.name = "tail";
  chain.joints = {1, 2};
  std::vector<SpringBoneChain> chains = {chain};
  SpringBoneState state;
  simulate(s, chains, state, 1.0f / 60.0f);  // starts at rest
  // Throw both tails sideways (same bone lengths), then let go.
  state.tails[0][0] = glm::vec3(0.0f, 0.5f, 0.0f) + 0.5f * glm::normalize(glm::vec3(1, 1, 0));
  state.tails[0][1] = state.tails[0][0] + 0.5f * glm::normalize(glm::vec3(1, 0.3f, 0));
  state.previousTails = state.tails;
  const std::vector<glm::mat4> w = simulate(s, chains, state, 5.0f);
  EXPECT_LT(angleBetween(glm::vec3(w[2][3] - w[1][3]), {0, 1, 0}), 0.5f);
  EXPECT_LT(angleBetween(glm::vec3(w[3][3] - w[2][3]), {0, 1, 0}), 0.5f);
}

TEST(SpringBones, HangsDownUnderGravityAndBalancesAStiffness) {
  const Skeleton s = straightChain({1, 0, 0});  // horizontal
  SpringBoneChain chain;
  chain.joints = {1, 2};
  chain.stiffness = 0.0f;
  chain.gravity = {0.0f, -9.81f, 0.0f};
  SpringBoneState state;
  std::vector<glm::mat4> w = simulate(s, {chain}, state, 8.0f);
  EXPECT_LT(angleBetween(glm::vec3(w[2][3] - w[1][3]), {0, -1, 0}), 1.0f);
  EXPECT_LT(angleBetween(glm::vec3(w[3][3] - w[2][3]), {0, -1, 0}), 1.0f);
  // One bone of length L = 0.5 with stiffness k: tan(theta) = g / (k L) below the horizontal.
  for (float k : {10.0f, 40.0f, 200.0f}) {
    SpringBoneChain one;
    one.joints = {2};  // b's bone to c, hanging from a (still)
    one.stiffness = k;
    one.gravity = {0.0f, -9.81f, 0.0f};
    SpringBoneState st;
    w = simulate(s, {one}, st, 10.0f);
    const glm::vec3 bone(w[3][3] - w[2][3]);
    const float theta = std::atan2(-bone.y, bone.x) * kDegrees;
    EXPECT_NEAR(theta, std::atan(9.81f / (k * 0.5f)) * kDegrees, 0.2f) << "k=" << k;
    EXPECT_NEAR(glm::length(bone), 0.5f, 1e-5f);
  }
}

TEST(SpringBones, LagsBehindAMovingParentKeepsLengthsAndStaysOutOfColliders) {
  Skeleton s = straightChain({0, 1, 0});
  SpringBoneChain chain;
  chain.joints = {1, 2, 3};
  chain.stiffness = 30.0f;
  chain.damping = 2.0f;
  SpringCollider wall;
  wall.joint = -1;
  wall.a = {-0.35f, 0.9f, -1.0f};
  wall.b = {-0.35f, 0.9f, 1.0f};
  wall.radius = 0.1f;
  chain.colliders = {wall};
  const std::vector<SpringBoneChain> chains = {chain};
  Pose pose = Pose::rest(s);
  SpringBoneState state;
  SpringBoneJob job = jobFor(s, chains, pose, state, 1.0f / 30.0f);
  float largestLag = 0.0f;
  for (int f = 0; f < 90; ++f) {
    pose = Pose::rest(s);
    const float rootX = 1.5f * std::max(0, f - 10) / 30.0f;  // from frame 10 the root walks right at 1.5 m/s
    pose.local[0].translation.x = rootX;
    ASSERT_TRUE(job.run());
    const std::vector<glm::mat4> w = computeWorld(s, pose);
    for (int j = 1; j <= 3; ++j)
      EXPECT_NEAR(glm::length(glm::vec3(w[j][3] - w[j - 1][3])), 0.5f, 1e-4f) << "frame " << f;
    // The tails (b, c, and c's continued bone) never inside the capsule plus their radius.
    for (const glm::vec3& t : state.tails[0]) {
      const float dx = t.x + 0.35f, dy = t.y - 0.9f;  // the wall's axis runs along z
      EXPECT_GE(std::sqrt(dx * dx + dy * dy), 0.1f + chain.radius - 1e-4f) << "frame " << f;
    }
    if (f > 10) largestLag = std::max(largestLag, rootX - w[3][3].x);  // the tip trails the root
  }
  EXPECT_GT(largestLag, 0.05f);
}

TEST(SpringBones, TheSameInputGivesTheSameBitsAndABakedClipReplaysIt) {
  Skeleton s = straightChain({0, 1, 0});
  Clip clip;
  clip.name = "sway";
  clip.frameTime = 1.0 / 24.0;
  Channel root(0, ChannelTarget::Translation, Interpolation::Linear, {0.0f, 1.0f, 2.0f},
               {{0, 0, 0, 0}, {0.6f, 0, 0, 0}, {-0.3f, 0.2f, 0, 0}});
  clip.channels.push_back(root);
  SpringBoneChain chain;
  chain.name = "tail";
  chain.joints = {1, 2};
  chain.gravity = {0, -9.81f, 0};
  chain.stiffness = 60.0f;
  const Result<Clip> a = bakeSpringBones(s, clip, {chain}, 0, 48);
  const Result<Clip> b = bakeSpringBones(s, clip, {chain}, 0, 48);
  ASSERT_TRUE(a.ok()) << a.error();
  ASSERT_EQ(a->channels.size(), 3u);  // the root's translation, then a and b
  for (size_t c = 1; c < 3; ++c) {
    ASSERT_EQ(a->channels[c].keyCount(), 49);
    EXPECT_EQ(std::memcmp(a->channels[c].values.data(), b->channels[c].values.data(),
                          a->channels[c].values.size() * sizeof(glm::vec4)),
              0);
  }
  EXPECT_EQ(a->validate(s), "");
  // Replaying: the baked clip sampled at each frame gives the job's pose at that frame.
  SpringBoneState state;
  Pose pose = Pose::rest(s);
  const std::vector<SpringBoneChain> chains = {chain};
  SpringBoneJob job = jobFor(s, chains, pose, state, 1.0f / 24.0f);
  for (int f = 0; f <= 48; ++f) {
    pose = Pose::rest(s);
    sampleClip(clip, ownFrameGrid(clip).frameToTime(f), pose);
    ASSERT_TRUE(job.run());
    Pose replay = Pose::rest(s);
    sampleClip(a.value(), ownFrameGrid(a.value()).frameToTime(f), replay);
    for (int j : {1, 2}) EXPECT_SAME_ROTATION(replay.local[j].rotation, pose.local[j].rotation, 1e-6f);
  }
  // The swinging differs from the animation (the chain was not animated at all).
  Pose mid = Pose::rest(s);
  sampleClip(a.value(), ownFrameGrid(a.value()).frameToTime(30), mid);
  EXPECT_LT(std::abs(glm::dot(mid.local[1].rotation, glm::quat(1, 0, 0, 0))), 0.9999f);
}

// A bar under a hanging bone: the tail rests on it instead of hanging straight down.
TEST(SpringBones, TailsRestOnACollider) {
  const Skeleton s = straightChain({1, 0, 0});
  SpringBoneChain chain;
  chain.joints = {2};  // b's bone, 0.5 m from (1, 0, 0) to c
  chain.stiffness = 0.0f;
  chain.gravity = {0.0f, -9.81f, 0.0f};
  chain.radius = 0.02f;
  SpringCollider bar;
  bar.a = {1.05f, -0.45f, -1.0f};  // along z, just right of straight below b: the bone, falling
                                  // from the horizontal on the right, comes to rest on its right side
  bar.b = {1.05f, -0.45f, 1.0f};
  bar.radius = 0.1f;
  chain.colliders = {bar};
  const std::vector<SpringBoneChain> chains = {chain};
  Pose pose = Pose::rest(s);
  SpringBoneState state;
  SpringBoneJob job = jobFor(s, chains, pose, state, 1.0f / 60.0f);
  for (int f = 0; f < 300; ++f) {
    pose = Pose::rest(s);
    ASSERT_TRUE(job.run());
    const glm::vec3 t = state.tails[0][0];
    EXPECT_GE(std::hypot(t.x - 1.05f, t.y + 0.45f), 0.12f - 1e-4f) << "frame " << f;
  }
  // It came to rest touching the bar, not hanging straight down.
  const glm::vec3 t = state.tails[0][0];
  EXPECT_NEAR(std::hypot(t.x - 1.05f, t.y + 0.45f), 0.12f, 2e-3f);
  EXPECT_GT(t.x, 1.05f);
  EXPECT_GT(angleBetween(t - glm::vec3(1, 0, 0), {0, -1, 0}), 5.0f);
}

TEST(SpringBones, RefusesBadChains) {
  const Skeleton s = straightChain({0, 1, 0});
  SpringBoneChain c;
  c.name = "x";
  EXPECT_NE(c.validate(s).find("no joints"), std::string::npos);
  c.joints = {1, 3};
  EXPECT_NE(c.validate(s).find("not a child"), std::string::npos);
  c.joints = {1, 9};
  EXPECT_NE(c.validate(s).find("not in the skeleton"), std::string::npos);
  c.joints = {1};
  c.damping = -1.0f;
  EXPECT_NE(c.validate(s).find("damping"), std::string::npos);
  EXPECT_FALSE(bakeSpringBones(s, Clip{}, {c}, 0, 10).ok());
  c.damping = 1.0f;
  EXPECT_FALSE(bakeSpringBones(s, Clip{}, {c}, 5, 1).ok());
}

}  // namespace
}  // namespace kinema
