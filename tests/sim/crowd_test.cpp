// Crowds of animated characters: the playback rate follows the ground speed, members face
// their velocity, the clip's own drift is taken out, separation holds in a 500-member crowd,
// runs are deterministic per seed, and a baked member clip replays the run.
#include <gtest/gtest.h>

#include <cmath>

#include <glm/gtc/quaternion.hpp>

#include "sim/crowd.h"
#include "bake/crowd_scene.h"
#include "test_support.h"

namespace kinema {
namespace KINEMA_UNITY_ID {

constexpr double kDt = 1.0 / 30.0;

// A two-joint character whose 1-second clip walks along +Z at 1.5 m/s: the root's
// translation goes (0, 1, 0) -> (0, 1, 1.5) while the leg swings about X.
Scene walker() {
  Scene s;
  s.skeleton.addJoint("hips", -1, Transform::fromTranslation({0, 1, 0}));
  s.skeleton.addJoint("leg", 0, Transform::fromTranslation({0, -0.5f, 0}));
  Clip c;
  c.name = "walk";
  c.frameTime = kDt;
  c.channels.emplace_back(0, ChannelTarget::Translation, Interpolation::Linear, std::vector<float>{0.0f, 1.0f},
                          std::vector<glm::vec4>{{0, 1, 0, 0}, {0, 1, 1.5f, 0}});
  const glm::quat a = glm::angleAxis(0.4f, glm::vec3(1, 0, 0)), b = glm::angleAxis(-0.4f, glm::vec3(1, 0, 0));
  c.channels.emplace_back(1, ChannelTarget::Rotation, Interpolation::Linear, std::vector<float>{0.0f, 1.0f},
                          std::vector<glm::vec4>{{a.x, a.y, a.z, a.w}, {b.x, b.y, b.z, b.w}});
  s.clips.push_back(c);
  return s;
}

TEST(Crowd, TheClipsDriftIsItsNaturalSpeedAndFacing) {
  const Scene s = walker();
  const CrowdClipMotion m = analyseCrowdClip(s.skeleton, s.clips[0], CrowdSettings{});
  // Both joints move 1.5 m along +Z in 1 s: the centroid too.
  EXPECT_VEC3_NEAR(m.drift, glm::vec3(0, 0, 1.5f), 1e-5f);
  EXPECT_NEAR(m.naturalSpeed, 1.5f, 1e-5f);
  EXPECT_NEAR(m.forwardYaw, 0.0f, 1e-6f);  // atan2(0, 1.5)
  EXPECT_FLOAT_EQ(m.duration, 1.0f);
  CrowdSettings fixed;
  fixed.strideSpeed = 3.0f;  // a set stride speed wins over the measured one
  EXPECT_FLOAT_EQ(analyseCrowdClip(s.skeleton, s.clips[0], fixed).naturalSpeed, 3.0f);
}

TEST(Crowd, AMemberWalkingStraightAtTheNaturalSpeedPlaysAtRateOne) {
  const Scene s = walker();
  CrowdSettings c;
  c.members = 1;
  c.boids.cruiseSpeed = 1.5f;  // = the natural speed: no goal impulse (cruise - speed = 0), no neighbours
  const CrowdClipMotion m = analyseCrowdClip(s.skeleton, s.clips[0], c);
  Result<CrowdRun> run = runCrowd(c, m, kDt, 61);
  ASSERT_TRUE(run) << run.error();
  const CrowdMemberState& first = run->at(0, 0);
  EXPECT_NEAR(glm::length(first.velocity), 1.5f, 1e-5f);
  for (long long f = 1; f < 61; ++f) {
    const CrowdMemberState& now = run->at(f, 0);
    // A straight line at constant velocity...
    EXPECT_VEC3_NEAR(now.velocity, first.velocity, 1e-4f);
    EXPECT_VEC3_NEAR(now.position, first.position + first.velocity * static_cast<float>(f * kDt), 1e-3f);
    // ...and the clip advances by dt a frame (rate 1), wrapping at its 1 s duration.
    const double expected = std::fmod(first.clipTime + static_cast<double>(f) * kDt, 1.0);
    const double got = now.clipTime;
    EXPECT_NEAR(std::min(std::abs(got - expected), 1.0 - std::abs(got - expected)), 0.0, 1e-4) << f;
    // Heading: atan2 of the velocity.
    EXPECT_NEAR(now.yaw, std::atan2(now.velocity.x, now.velocity.z), 1e-6f);
  }
  // Half the stride speed: the same ground speed is twice the clip's rate.
  EXPECT_NEAR(advanceCrowdClipTime(0.2, kDt, 1.5f, m), 0.2 + kDt, 1e-9);
  CrowdClipMotion slow = m;
  slow.naturalSpeed = 0.75f;
  EXPECT_NEAR(advanceCrowdClipTime(0.2, kDt, 1.5f, slow), 0.2 + 2 * kDt, 1e-9);
  EXPECT_NEAR(advanceCrowdClipTime(0.99, 0.02, 1.5f, m), 0.01, 1e-9);  // wraps into [0, 1)
}

TEST(Crowd, TheMemberFacesItsVelocityAndItsClipDriftIsTakenOut) {
  const Scene s = walker();
  const CrowdClipMotion m = analyseCrowdClip(s.skeleton, s.clips[0], CrowdSettings{});
  CrowdMemberState st;
  st.position = glm::vec3(5, 0, -2);
  st.velocity = glm::vec3(1, 0, 1);
  st.yaw = std::atan2(1.0f, 1.0f);  // 45 degrees: facing +X+Z
  st.clipTime = 0.5;
  Pose pose;
  crowdMemberPose(s.skeleton, s.clips[0], m, st, pose);
  // Clip at 0.5 s: hips at (0, 1, 0.75); minus the drift 1.5 * 0.5 along Z = (0, 1, 0); the
  // yaw turn leaves (0, 1, 0) alone; plus the position.
  EXPECT_VEC3_NEAR(pose.local[0].translation, glm::vec3(5, 1, -2), 1e-5f);
  // The character's forward (+Z, its walking direction) turned to the velocity.
  EXPECT_VEC3_NEAR(pose.local[0].rotation * glm::vec3(0, 0, 1), glm::normalize(st.velocity), 1e-5f);
  // The leg keeps the clip's swing (halfway: the identity).
  EXPECT_NEAR(std::abs(glm::dot(pose.local[1].rotation, glm::quat(1, 0, 0, 0))), 1.0f, 1e-5f);
}

float closestPair(const CrowdRun& run, long long f) {
  float best = 1e30f;
  for (int i = 0; i < run.members; ++i)
    for (int j = i + 1; j < run.members; ++j)
      best = std::min(best, glm::distance(run.at(f, i).position, run.at(f, j).position));
  return best;
}

TEST(Crowd, FiveHundredMembersNeverComeCloserThanTheSeparationDistance) {
  const Scene s = walker();
  CrowdSettings c;
  c.members = 500;
  c.seed = 7;  // the default weights and neighbourhood, no goal: the flock roams at the cruise speed
  const CrowdClipMotion m = analyseCrowdClip(s.skeleton, s.clips[0], c);
  Result<CrowdRun> run = runCrowd(c, m, kDt, 240);
  ASSERT_TRUE(run) << run.error();
  for (long long f = 0; f < 240; f += 4) ASSERT_GE(closestPair(run.value(), f), c.boids.separationDistance) << "frame " << f;
  for (const CrowdMemberState& st : run->states) ASSERT_NEAR(st.position.y, 0.0f, 1e-6f);  // on the ground
}

TEST(Crowd, RunsAreDeterministicPerSeed) {
  const Scene s = walker();
  CrowdSettings c;
  c.members = 40;
  const CrowdClipMotion m = analyseCrowdClip(s.skeleton, s.clips[0], c);
  Result<CrowdRun> a = runCrowd(c, m, kDt, 30), b = runCrowd(c, m, kDt, 30);
  c.seed = 2;
  Result<CrowdRun> other = runCrowd(c, m, kDt, 30);
  ASSERT_TRUE(a && b && other);
  bool same = true, differs = false;
  for (size_t i = 0; i < a->states.size(); ++i) {
    same = same && a->states[i].position == b->states[i].position && a->states[i].clipTime == b->states[i].clipTime;
    differs = differs || a->states[i].position != other->states[i].position;
  }
  EXPECT_TRUE(same);
  EXPECT_TRUE(differs);
}

TEST(Crowd, ABakedMemberClipReplaysTheRun) {
  const Scene s = walker();
  CrowdSettings c;
  c.members = 12;
  c.boids.boxes.push_back({glm::vec3(2, -1, 2), glm::vec3(4, 1, 4)});
  Result<CrowdBake> bake = bakeCrowd(c, s, 5, 40);
  ASSERT_TRUE(bake) << bake.error();
  ASSERT_EQ(bake->clips.size(), 12u);
  EXPECT_EQ(bake->clips[7].name, "crowd_0007");
  const Clip& clip = bake->clips[7];
  EXPECT_EQ(clip.validate(s.skeleton), "");
  for (long long f : {5LL, 17LL, 40LL}) {
    Pose pose = Pose::rest(s.skeleton);
    sampleClip(clip, ownFrameGrid(clip).frameToTime(f), pose);
    const CrowdMemberState& st = bake->run.at(f, 7);
    // The hips stand 1 m above the member's place (the walker's drift-free root).
    EXPECT_VEC3_NEAR(pose.local[0].translation, st.position + glm::vec3(0, 1, 0), 1e-4f);
    EXPECT_VEC3_NEAR(pose.local[0].rotation * glm::vec3(0, 0, 1),
                     glm::vec3(std::sin(st.yaw), 0, std::cos(st.yaw)), 1e-4f);
  }
  // As many characters: member 3's joints are "crowd_0003/<joint>", its keys on them.
  Scene many;
  appendCrowdCharacters(many, c, s, bake.value());
  ASSERT_EQ(many.skeleton.size(), 24);
  EXPECT_EQ(many.skeleton.names[6], "crowd_0003/hips");
  EXPECT_EQ(many.skeleton.parents[7], 6);
  EXPECT_EQ(many.skeleton.validate(), "");
  ASSERT_EQ(many.clips.size(), 1u);
  EXPECT_EQ(many.clips[0].validate(many.skeleton), "");
  EXPECT_EQ(many.clips[0].channels.size(), 12u * bake->clips[0].channels.size());
}

}  // namespace
}  // namespace kinema
