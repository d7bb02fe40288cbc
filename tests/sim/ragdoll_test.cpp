// Ragdolls in Bullet (issue 23): a body in free fall follows y0 + v0 t - g t^2 / 2 with the
// velocity the animation gave it; a character falling from its T-pose never leaves its
// joint limits by more than 2 degrees and lies still on the ground (no joint below it) after
// 3 s; thrown chains stay inside hinge, cone and Euler limits; the same input gives the same
// bits; a baked clip replays what was simulated.
#include "sim/ragdoll.h"

#include <gtest/gtest.h>

#include <cmath>

#include "anim/sampling.h"
#include "core/default_character.h"
#include "core/forward_kinematics.h"
#include "test_support.h"

namespace kinema {
namespace KINEMA_UNITY_ID {

constexpr float kDeg = 3.14159265f / 180.0f;

std::vector<RagdollBody> bodiesOf(const Skeleton& s, const Pose& pose, int root = 0, float mass = 70.0f) {
  std::vector<RagdollBody> bodies;
  RagdollBodiesJob job;
  job.skeleton = &s;
  job.pose = &pose;
  job.root = root;
  job.totalMass = mass;
  job.bodies = &bodies;
  EXPECT_EQ(job.validate(), "");
  EXPECT_TRUE(job.run());
  return bodies;
}

TEST(Ragdoll, BodiesCoverEveryBoneAndShareTheMass) {
  const Skeleton s = makeDefaultCharacter();
  const Pose rest = Pose::rest(s);
  const std::vector<RagdollBody> bodies = bodiesOf(s, rest, 0, 70.0f);
  int withChildren = 0;
  for (int j = 0; j < s.size(); ++j)
    for (int c = j + 1; c < s.size(); ++c)
      if (s.parents[c] == j) {
        ++withChildren;
        break;
      }
  EXPECT_EQ(static_cast<int>(bodies.size()), withChildren);
  float mass = 0.0f;
  for (const RagdollBody& b : bodies) {
    mass += b.mass;
    EXPECT_GT(b.radius, 0.0f);
    if (b.parentBody >= 0) {
      EXPECT_EQ(bodies[b.parentBody].joint, s.parents[b.joint]);
    }
  }
  EXPECT_NEAR(mass, 70.0f, 1e-3f);
}

TEST(Ragdoll, FallsFreelyWithTheAnimatedVelocity) {
  // One bone, 2 m above the ground, moving up at 1.5 m/s and sideways at 0.5 m/s when it starts.
  Skeleton s;
  s.addJoint("a", -1, Transform::fromTranslation({0, 2, 0}));
  s.addJoint("b", 0, Transform::fromTranslation({0.3f, 0, 0}));
  RagdollSettings settings;
  settings.damping = 0.0f;
  settings.gravity = {0.0f, -9.81f, 0.0f};
  const Pose pose = Pose::rest(s);
  Pose previous = pose;
  const float interval = 0.1f;
  previous.local[0].translation -= glm::vec3(0.05f, 0.15f, 0.0f);
  Result<std::unique_ptr<Ragdoll>> r =
      Ragdoll::create(s, settings, bodiesOf(s, pose), ragdollJointLimits(s, {}), pose, &previous, interval);
  ASSERT_TRUE(r) << r.error();
  Pose now = pose;
  const float dt = 1.0f / 30.0f;
  for (int f = 1; f <= 12; ++f) {
    r.value()->step(dt);
    r.value()->writePose(now);
    const float t = f * dt;
    // The body's centre follows the parabola; its joint rides rigidly with it (no spin).
    // Bullet integrates semi-implicitly (v first, then x with the new v) in steps of h, so
    // after n steps y = y0 + v0 t - g h^2 n (n + 1) / 2 = y0 + v0 t - g t (t + h) / 2.
    const float h = 1.0f / kRagdollStepsPerSecond;
    EXPECT_NEAR(now.local[0].translation.y, 2.0f + 1.5f * t - 0.5f * 9.81f * t * (t + h), 2e-4f) << t;
    EXPECT_NEAR(now.local[0].translation.x, 0.5f * t, 2e-4f) << t;
  }
  EXPECT_EQ(r.value()->stepsTaken(), 12 * 8);
}

// The default character dropped from 0.3 m above its stance, leaning, with a spin.
struct Fall {
  Skeleton s = makeDefaultCharacter();
  std::vector<JointLimit> limits = ragdollJointLimits(s, {});
  std::unique_ptr<Ragdoll> ragdoll;
  Pose pose = Pose::rest(s);
  Fall() {
    pose.local[0].translation.y += 0.3f;
    pose.local[0].rotation = glm::angleAxis(20.0f * kDeg, glm::vec3(1, 0, 0));
    Pose previous = pose;
    previous.local[0].rotation = glm::angleAxis(17.0f * kDeg, glm::vec3(1, 0.2f, 0));
    RagdollSettings settings;
    Result<std::unique_ptr<Ragdoll>> r = Ragdoll::create(s, settings, bodiesOf(s, pose), limits, pose, &previous, 1.0f / 30.0f);
    EXPECT_TRUE(r) << r.error();
    if (r) ragdoll = std::move(r.value());
  }
};

TEST(Ragdoll, ACharacterKeepsItsLimitsAndComesToRestOnTheGround) {
  Fall fall;
  ASSERT_TRUE(fall.ragdoll);
  float worst = 0.0f;
  int worstJoint = -1, worstFrame = -1;
  const float dt = 1.0f / 60.0f;
  for (int f = 0; f < 180; ++f) {
    fall.ragdoll->step(dt);
    fall.ragdoll->writePose(fall.pose);
    int joint = -1;
    const float excess = fall.ragdoll->largestLimitExcess(fall.pose, &joint);
    if (excess > worst) worst = excess, worstJoint = joint, worstFrame = f;
  }
  EXPECT_LT(worst, 2.0f * kDeg) << worst / kDeg << " degrees at " << (worstJoint >= 0 ? fall.s.names[worstJoint] : "")
                                << " frame " << worstFrame;
  // After 3 s: lying still, no joint below the ground (up to Bullet's contact slop, 4 mm).
  const std::vector<glm::mat4> world = computeWorld(fall.s, fall.pose);
  float lowest = 1e9f, highest = -1e9f;
  int lowestJoint = -1;
  for (int j = 0; j < fall.s.size(); ++j) {
    if (world[j][3].y < lowest) lowest = world[j][3].y, lowestJoint = j;
    highest = std::max(highest, world[j][3].y);
  }
  EXPECT_GT(lowest, -0.004f) << fall.s.names[lowestJoint];
  EXPECT_LT(highest, 0.6f) << "it fell over";
  EXPECT_LT(fall.ragdoll->largestSpeed(), 0.05f);
}

TEST(Ragdoll, ThrownChainsStayInsideHingeConeAndEulerLimits) {
  // root -> a -> b -> c -> d, 0.3 m bones along +X, each limited, thrown into a spin.
  Skeleton s;
  s.addJoint("root", -1, Transform::fromTranslation({0, 3, 0}));
  for (const char* name : {"a", "b", "c", "d"}) s.addJoint(name, s.size() - 1, Transform::fromTranslation({0.3f, 0, 0}));
  std::vector<JointLimit> limits(s.size());
  limits[1] = JointLimit::hinge({0, 0, 1}, -10.0f * kDeg, 60.0f * kDeg);
  limits[2] = JointLimit::cone({1, 0, 0}, 35.0f * kDeg, -10.0f * kDeg, 25.0f * kDeg);
  limits[3] = JointLimit::euler(EulerOrder::ZXY, {-20 * kDeg, -30 * kDeg, -15 * kDeg}, {20 * kDeg, 10 * kDeg, 45 * kDeg});
  const Pose pose = Pose::rest(s);
  // Each joint turning fast (600 degrees/s) about its own axis: into its limits.
  Pose previous = pose;
  previous.local[1].rotation = glm::angleAxis(-10.0f * kDeg, glm::vec3(0, 0, 1));
  previous.local[2].rotation = glm::angleAxis(-10.0f * kDeg, glm::normalize(glm::vec3(0.2f, 1, 0.3f)));
  previous.local[3].rotation = glm::angleAxis(10.0f * kDeg, glm::normalize(glm::vec3(0.5f, 0.2f, 1)));
  RagdollSettings settings;
  settings.damping = 0.0f;
  settings.groundHeight = -100.0f;  // out of reach
  Result<std::unique_ptr<Ragdoll>> r =
      Ragdoll::create(s, settings, bodiesOf(s, pose, 0, 10.0f), limits, pose, &previous, 1.0f / 60.0f);
  ASSERT_TRUE(r) << r.error();
  Pose now = pose;
  float worst = 0.0f, reached[4] = {0, 0, 0, 0};
  int worstJoint = -1;
  for (int f = 0; f < 60; ++f) {
    r.value()->step(1.0f / 60.0f);
    r.value()->writePose(now);
    int joint = -1;
    const float excess = r.value()->largestLimitExcess(now, &joint);
    if (excess > worst) worst = excess, worstJoint = joint;
    for (int j = 1; j <= 3; ++j) reached[j] = std::max(reached[j], 2.0f * std::acos(std::min(1.0f, std::abs(now.local[j].rotation.w))));
  }
  EXPECT_LT(worst, 2.0f * kDeg) << worst / kDeg << " degrees at joint " << worstJoint;
  // The joints did bend (the spin loaded them), so the limits were tested, not idle.
  for (int j = 1; j <= 3; ++j) EXPECT_GT(reached[j], 5.0f * kDeg) << s.names[j];
}

TEST(Ragdoll, SameInputSameBits) {
  Fall one, two;
  ASSERT_TRUE(one.ragdoll && two.ragdoll);
  for (int f = 0; f < 45; ++f) {
    one.ragdoll->step(1.0f / 24.0f);
    two.ragdoll->step(1.0f / 24.0f);
  }
  one.ragdoll->writePose(one.pose);
  two.ragdoll->writePose(two.pose);
  for (int j = 0; j < one.s.size(); ++j) {
    EXPECT_EQ(one.pose.local[j].rotation, two.pose.local[j].rotation);
    EXPECT_EQ(one.pose.local[j].translation, two.pose.local[j].translation);
  }
}

TEST(Ragdoll, ABakedClipReplaysTheSimulationFromItsStartFrame) {
  const Skeleton s = makeDefaultCharacter();
  // A clip that raises the hips over 40 frames at 30 fps.
  Clip clip;
  clip.frameTime = 1.0 / 30.0;
  clip.channels.emplace_back(0, ChannelTarget::Translation, Interpolation::Linear, std::vector<float>{0.0f, 40.0f / 30.0f},
                             std::vector<glm::vec4>{glm::vec4(s.rest[0].translation, 0), glm::vec4(s.rest[0].translation + glm::vec3(0, 0.5f, 0), 0)});
  RagdollSettings settings;
  settings.startFrame = 10;
  const std::vector<RagdollBody> bodies = bodiesOf(s, Pose::rest(s));
  const std::vector<JointLimit> limits = ragdollJointLimits(s, {});
  RagdollBakeReport report;
  Result<Clip> baked = bakeRagdoll(s, clip, settings, bodies, limits, 0, 60, &report);
  ASSERT_TRUE(baked) << baked.error();
  EXPECT_EQ(report.firstFrame, 10);
  EXPECT_EQ(report.lastFrame, 60);
  EXPECT_EQ(report.steps, 50 * 8);
  EXPECT_LT(report.largestLimitExcess, 2.0f * kDeg) << (report.worstJoint >= 0 ? s.names[report.worstJoint] : "");
  // Before the start frame: the animation. From it on: the same ragdoll run by hand.
  SamplingCache cache;
  for (int f : {0, 5, 9}) {
    Pose animated = Pose::rest(s), replay = Pose::rest(s);
    sampleClip(clip, ownFrameGrid(clip).frameToTime(f), animated, cache);
    sampleClip(baked.value(), ownFrameGrid(clip).frameToTime(f), replay, cache);
    EXPECT_VEC3_NEAR(replay.local[0].translation, animated.local[0].translation, 1e-6f);
  }
  Pose pose = Pose::rest(s), previous = Pose::rest(s);
  sampleClip(clip, ownFrameGrid(clip).frameToTime(10), pose, cache);
  sampleClip(clip, ownFrameGrid(clip).frameToTime(9), previous, cache);
  Result<std::unique_ptr<Ragdoll>> r = Ragdoll::create(s, settings, bodies, limits, pose, &previous, 1.0f / 30.0f);
  ASSERT_TRUE(r);
  for (int f = 11; f <= 60; ++f) r.value()->step(1.0f / 30.0f);
  Pose expected = Pose::rest(s), replay = Pose::rest(s);
  sampleClip(clip, ownFrameGrid(clip).frameToTime(60), expected, cache);
  r.value()->writePose(expected);
  sampleClip(baked.value(), ownFrameGrid(clip).frameToTime(60), replay, cache);
  for (const RagdollBody& b : bodies)
    EXPECT_LT(std::abs(glm::dot(replay.local[b.joint].rotation, expected.local[b.joint].rotation)), 1.0f + 1e-6f);
  for (const RagdollBody& b : bodies)
    EXPECT_GT(std::abs(glm::dot(replay.local[b.joint].rotation, expected.local[b.joint].rotation)), 1.0f - 1e-6f) << s.names[b.joint];
  EXPECT_VEC3_NEAR(replay.local[0].translation, expected.local[0].translation, 1e-5f);
}

TEST(Ragdoll, RefusesWhatItCannotBuild) {
  const Skeleton s = makeDefaultCharacter();
  RagdollSettings settings;
  settings.mass = -1.0f;
  const Pose pose = Pose::rest(s);
  Result<std::unique_ptr<Ragdoll>> r = Ragdoll::create(s, settings, bodiesOf(s, pose), ragdollJointLimits(s, {}), pose);
  ASSERT_FALSE(r);
  EXPECT_NE(r.error().find("mass"), std::string::npos);
  settings.mass = 70.0f;
  r = Ragdoll::create(s, settings, {}, ragdollJointLimits(s, {}), pose);
  ASSERT_FALSE(r);
  EXPECT_NE(r.error().find("no bones"), std::string::npos);
}

TEST(Ragdoll, DefaultHumanLimitsBendKneesBackAndElbowsForward) {
  const Skeleton s = makeDefaultCharacter();
  const std::vector<JointLimit> limits = ragdollJointLimits(s, {});
  const std::vector<glm::mat4> world = computeWorld(s, Pose::rest(s));
  // The character faces +Z (default_character.h). Bending to the middle of the range moves
  // the shin's end backwards (-Z) and the forearm's end forwards (+Z).
  auto bendEnd = [&](const char* name) {
    const int j = s.find(name);
    const JointLimit& l = limits.at(j);
    EXPECT_EQ(l.type, JointLimitType::Hinge) << name;
    int child = -1;
    for (int c = j + 1; c < s.size() && child < 0; ++c)
      if (s.parents[c] == j) child = c;
    Pose bent = Pose::rest(s);
    bent.local[j].rotation = s.rest[j].rotation * glm::angleAxis(0.5f * (l.minAngle + l.maxAngle), l.axis);
    return glm::vec3(computeWorld(s, bent)[child][3] - world[child][3]);
  };
  EXPECT_LT(bendEnd("LowerLeg.L").z, -0.1f);
  EXPECT_LT(bendEnd("LowerLeg.R").z, -0.1f);
  EXPECT_GT(bendEnd("LowerArm.L").z, 0.1f);
  EXPECT_GT(bendEnd("LowerArm.R").z, 0.1f);
  // A limit the rig stores wins over the default.
  IkRig rig;
  rig.setLimit(s.size(), s.find("LowerLeg.L"), JointLimit::cone({0, -1, 0}, 0.1f, 0.0f, 0.0f));
  EXPECT_EQ(ragdollJointLimits(s, rig)[s.find("LowerLeg.L")].type, JointLimitType::Cone);
}

}  // namespace
}  // namespace kinema
