// Particle playback (issue 24): the state at a frame is the same however it is reached
// (straight from the start, forwards from a cached frame, back past a checkpoint), joint
// emitters emit where the joint stands at each frame, and changed inputs start again.
#include <gtest/gtest.h>

#include <glm/gtc/matrix_transform.hpp>

#include "sim/particle_system.h"

namespace kinema {
namespace KINEMA_UNITY_ID {

ParticleSystemSettings fountain() {
  ParticleSystemSettings s = defaultParticleSystem(-1, 1.8f);
  s.seed = 42;
  s.emitters[0].rate = {90.0f, 30.0f, RandomDistribution::Uniform};
  return s;
}

// The state after `frames` steps, by hand with the step job alone.
ParticleState byHand(const ParticleSystemSettings& s, double frameTime, long long frames) {
  ParticleState state;
  state.random = s.seed;
  ParticleStepJob job;
  job.emitters = &s.emitters;
  job.forces = &s.forces;
  job.dt = static_cast<float>(frameTime);
  job.maxParticles = static_cast<size_t>(s.maxParticles);
  job.state = &state;
  for (long long f = 0; f < frames; ++f) EXPECT_TRUE(job.run());
  return state;
}

void expectSame(const ParticleState& a, const ParticleState& b) {
  ASSERT_EQ(a.size(), b.size());
  EXPECT_EQ(a.random, b.random);
  EXPECT_EQ(a.emitted, b.emitted);
  for (int i = 0; i < a.size(); ++i) {
    EXPECT_EQ(a.positions[i], b.positions[i]) << i;
    EXPECT_EQ(a.velocities[i], b.velocities[i]) << i;
    EXPECT_EQ(a.ages[i], b.ages[i]) << i;
  }
}

TEST(ParticlePlayback, AFrameIsTheSameHoweverItIsReached) {
  const std::vector<ParticleSystemSettings> systems = {fountain()};
  ASSERT_EQ(systems[0].validate(Skeleton{}), "");
  const double dt = 1.0 / 30.0;
  ParticlePlayback playback;
  EXPECT_EQ(playback.at(systems, dt, 0, nullptr)[0].size(), 0) << "frame 0 is the empty start";
  const ParticleState at100 = playback.at(systems, dt, 100, nullptr)[0];
  EXPECT_EQ(playback.stepsRun(), 100);
  expectSame(at100, byHand(systems[0], dt, 100));
  EXPECT_GT(at100.size(), 50);
  EXPECT_GT(at100.emitted, static_cast<uint64_t>(at100.size())) << "some have died (lifetime 1.5 s)";
  // Forwards continues from the cache: one more step.
  expectSame(playback.at(systems, dt, 101, nullptr)[0], byHand(systems[0], dt, 101));
  EXPECT_EQ(playback.stepsRun(), 101);
  // Backwards restarts from the checkpoint at frame 32: eight steps to frame 40.
  expectSame(playback.at(systems, dt, 40, nullptr)[0], byHand(systems[0], dt, 40));
  EXPECT_EQ(playback.stepsRun(), 109);
  // A changed setting, frame time or input key starts again from frame 0.
  std::vector<ParticleSystemSettings> changed = systems;
  changed[0].forces.drag = 0.5f;
  expectSame(playback.at(changed, dt, 40, nullptr)[0], byHand(changed[0], dt, 40));
  EXPECT_EQ(playback.stepsRun(), 149);
  playback.at(changed, dt, 40, nullptr, 7);
  EXPECT_EQ(playback.stepsRun(), 189);
}

TEST(ParticlePlayback, AJointEmitterEmitsWhereTheJointStandsAtEachFrame) {
  Skeleton skeleton;
  skeleton.addJoint("root", -1, Transform{});
  skeleton.addJoint("hand", 0, Transform::fromTranslation({0, 1, 0}));
  ParticleSystemSettings s = defaultParticleSystem(1, 1.8f);
  ASSERT_EQ(s.validate(skeleton), "");
  s.emitters[0].rate = {30.0f, 0.0f, RandomDistribution::Uniform};  // one particle a frame at 30 fps
  s.emitters[0].speed = {0.0f, 0.0f, RandomDistribution::Uniform};
  s.emitters[0].lifetime = {100.0f, 0.0f, RandomDistribution::Uniform};
  s.emitters[0].position = {0.0f, 0.0f, 0.5f};  // in the joint's frame
  s.forces.gravity = glm::vec3(0.0f);
  std::vector<long long> asked;
  // The hand moves 0.1 along x per frame and turns 90° about y (its local z becomes world x).
  auto world = [&](long long frame, std::vector<glm::mat4>& out) {
    asked.push_back(frame);
    out.assign(2, glm::mat4(1.0f));
    out[1] = glm::translate(glm::mat4(1.0f), glm::vec3(0.1f * frame, 1.0f, 0.0f)) *
             glm::rotate(glm::mat4(1.0f), glm::radians(90.0f), glm::vec3(0, 1, 0));
  };
  ParticlePlayback playback;
  const ParticleState& state = playback.at({s}, 1.0 / 30.0, 5, world)[0];
  ASSERT_EQ(state.size(), 5);
  EXPECT_EQ(asked, (std::vector<long long>{1, 2, 3, 4, 5}));
  for (int i = 0; i < 5; ++i) {  // particle i was born at frame i + 1 and has not moved
    EXPECT_NEAR(state.positions[i].x, 0.1f * (i + 1) + 0.5f, 1e-5f) << i;
    EXPECT_NEAR(state.positions[i].y, 1.0f, 1e-5f) << i;
    EXPECT_NEAR(state.positions[i].z, 0.0f, 1e-5f) << i;
  }
}

TEST(ParticlePlayback, SettingsSayWhatIsWrong) {
  Skeleton skeleton;
  skeleton.addJoint("root", -1, Transform{});
  ParticleSystemSettings s = defaultParticleSystem(3, 1.8f);
  EXPECT_NE(s.validate(skeleton).find("a joint emitter needs a joint"), std::string::npos) << s.validate(skeleton);
  s = defaultParticleSystem(0, 1.8f);
  s.colour.a = 2.0f;
  EXPECT_NE(s.validate(skeleton).find("colour"), std::string::npos);
  s = defaultParticleSystem(0, 180.0f);  // centimetres: gravity in cm/s^2
  EXPECT_FLOAT_EQ(s.forces.gravity.y, -981.0f);
  EXPECT_EQ(s.validate(skeleton), "");
}

}  // namespace
}  // namespace kinema
