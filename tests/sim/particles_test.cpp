// Particles: exact straight lines and parabolas, the ground bounce with its restitution,
// sphere collisions, emission counts, lifetimes, emitter shapes and determinism.
#include <gtest/gtest.h>

#include <cmath>

#include "sim/particles.h"
#include "test_support.h"

namespace kinema {
namespace KINEMA_UNITY_ID {

ParticleState oneParticle(glm::vec3 p, glm::vec3 v) {
  ParticleState s;
  s.positions = {p};
  s.velocities = {v};
  s.ages = {0.0f};
  s.lifetimes = {1e6f};
  s.emitterOf = {0};
  return s;
}

void steps(ParticleState& s, const ParticleForces& f, int n, float dt, const std::vector<ParticleEmitter>& emitters = {}) {
  ParticleStepJob job;
  job.emitters = &emitters;
  job.forces = &f;
  job.state = &s;
  job.dt = dt;
  for (int k = 0; k < n; ++k) ASSERT_TRUE(job.run());
}

TEST(Particles, WithoutForcesAParticleMovesInAStraightLine) {
  ParticleForces none;
  none.gravity = glm::vec3(0.0f);
  none.ground = false;
  ParticleState s = oneParticle({1, 2, 3}, {0.5f, -0.25f, 2.0f});
  for (int k = 1; k <= 90; ++k) {
    steps(s, none, 1, 1.0f / 30.0f);
    const float t = k / 30.0f;
    EXPECT_VEC3_NEAR(s.positions[0], glm::vec3(1, 2, 3) + t * glm::vec3(0.5f, -0.25f, 2.0f), 2e-5f);
    EXPECT_VEC3_NEAR(s.velocities[0], glm::vec3(0.5f, -0.25f, 2.0f), 1e-6f);
  }
}

TEST(Particles, UnderGravityOnTheExactParabolaWhateverTheStep) {
  ParticleForces f;
  f.ground = false;
  const glm::vec3 p0(0, 1, 0), v0(3, 8, -1), g(0, -9.81f, 0);
  for (float dt : {1.0f / 240.0f, 1.0f / 30.0f, 0.25f}) {
    ParticleState s = oneParticle(p0, v0);
    const int n = static_cast<int>(std::lround(2.0f / dt));
    steps(s, f, n, dt);
    const float t = n * dt;
    EXPECT_VEC3_NEAR(s.positions[0], p0 + v0 * t + 0.5f * g * t * t, 1e-4f);
    EXPECT_VEC3_NEAR(s.velocities[0], v0 + g * t, 1e-4f);
  }
}

TEST(Particles, BouncesOffTheGroundWithTheSetRestitution) {
  // Dropped from h = 2 m: it meets the ground at t1 = sqrt(2h/g) with speed sqrt(2gh) and
  // leaves with e times that, so afterwards y(t) = e v1 (t - t1) - g (t - t1)^2 / 2 until
  // the next contact at t1 + 2 e v1 / g, and it rises to e^2 h.
  const float h = 2.0f, g = 9.81f;
  for (float e : {0.3f, 0.6f, 0.9f}) {
    ParticleForces f;
    f.restitution = e;
    ParticleState s = oneParticle({0.5f, h, 0}, {0, 0, 0});
    const float t1 = std::sqrt(2 * h / g), v1 = std::sqrt(2 * g * h), t2 = t1 + 2 * e * v1 / g;
    const float dt = 1.0f / 60.0f;
    float highest = 0.0f;
    for (int k = 1; k * dt < t2 - dt; ++k) {
      steps(s, f, 1, dt);
      const float t = k * dt;
      const float expected = t < t1 ? h - 0.5f * g * t * t : e * v1 * (t - t1) - 0.5f * g * (t - t1) * (t - t1);
      EXPECT_NEAR(s.positions[0].y, expected, 1e-4f) << "e " << e << " t " << t;
      EXPECT_GE(s.positions[0].y, 0.0f);
      if (t > t1) highest = std::max(highest, s.positions[0].y);
    }
    EXPECT_NEAR(highest, e * e * h, 0.01f) << e;  // the sampled apex, within a frame's drop
  }
}

TEST(Particles, BouncesOffSpheresAndComesToRestOnTheGround) {
  ParticleForces f;
  f.restitution = 1.0f;
  f.gravity = glm::vec3(0.0f);
  f.ground = false;
  f.spheres.push_back({glm::vec3(0, 0, 0), 1.0f});
  // Head-on at 2 m/s from x = 3: meets the sphere at t = 1 and goes back the way it came.
  ParticleState s = oneParticle({3, 0, 0}, {-2, 0, 0});
  steps(s, f, 45, 1.0f / 30.0f);  // t = 1.5
  EXPECT_VEC3_NEAR(s.positions[0], glm::vec3(2, 0, 0), 1e-4f);
  EXPECT_VEC3_NEAR(s.velocities[0], glm::vec3(2, 0, 0), 1e-5f);
  // Restitution 0: it stays on the ground, never below it.
  ParticleForces ground;
  ground.restitution = 0.0f;
  ParticleState r = oneParticle({0, 1, 0}, {1, 0, 0});
  steps(r, ground, 90, 1.0f / 30.0f);
  EXPECT_NEAR(r.positions[0].y, 0.0f, 1e-5f);
  EXPECT_NEAR(r.velocities[0].y, 0.0f, 1e-5f);
  EXPECT_NEAR(r.velocities[0].x, 1.0f, 1e-5f);  // no friction: it slides on
}

TEST(Particles, EmissionRatesLifetimesConesAndDeterminism) {
  std::vector<ParticleEmitter> emitters(1);
  ParticleEmitter& e = emitters[0];
  e.rate = {120.0f, 0.0f};
  e.lifetime = {0.49f, 0.0f};
  e.speed = {3.0f, 0.0f};
  e.coneDegrees = 20.0f;
  e.direction = glm::vec3(1, 1, 0);
  ParticleForces f;
  f.gravity = glm::vec3(0.0f);
  ParticleState s;
  s.random = 7;
  steps(s, f, 30, 1.0f / 30.0f, emitters);  // one second
  // 4 per step; each lives 0.49 s, so those born in the last 15 steps (ages 0 .. 14/30 s) live: 60.
  EXPECT_EQ(s.size(), 60);
  const glm::vec3 axis = glm::normalize(e.direction);
  for (int i = 0; i < s.size(); ++i) {
    EXPECT_NEAR(glm::length(s.velocities[i]), 3.0f, 1e-5f);
    EXPECT_GE(glm::dot(glm::normalize(s.velocities[i]), axis), std::cos(glm::radians(20.0f)) - 1e-5f);
    EXPECT_LT(s.ages[i], 0.49f);
  }
  // The same seed gives the same particles; another seed others.
  ParticleState again, other;
  again.random = 7;
  other.random = 8;
  steps(again, f, 30, 1.0f / 30.0f, emitters);
  steps(other, f, 30, 1.0f / 30.0f, emitters);
  EXPECT_EQ(again.positions, s.positions);
  EXPECT_EQ(again.velocities, s.velocities);
  EXPECT_NE(other.velocities, s.velocities);
}

TEST(Particles, EmitterShapesPlaceParticlesWhereTheySay) {
  ParticleForces still;
  still.gravity = glm::vec3(0.0f);
  still.ground = false;
  std::vector<ParticleEmitter> emitters(3);
  emitters[0].shape = EmitterShape::Sphere;
  emitters[0].position = {5, 5, 5};
  emitters[0].radius = 0.5f;
  emitters[1].shape = EmitterShape::MeshSurface;  // the unit square in the XZ plane at y = 2
  emitters[1].surfacePositions = {{0, 2, 0}, {1, 2, 0}, {1, 2, 1}, {0, 2, 1}};
  emitters[1].surfaceIndices = {0, 2, 1, 0, 3, 2};  // normals +Y
  emitters[1].coneDegrees = 0.0f;
  emitters[2].shape = EmitterShape::Joint;
  emitters[2].joint = 0;
  emitters[2].position = {0, 1, 0};  // one metre along the joint's Y
  emitters[2].coneDegrees = 0.0f;
  const std::vector<glm::mat4> joints = {glm::translate(glm::mat4(1.0f), glm::vec3(-3, 0, 0)) *
                                         glm::mat4_cast(glm::angleAxis(glm::radians(90.0f), glm::vec3(0, 0, 1)))};
  for (ParticleEmitter& e : emitters) e.rate = {300.0f, 0.0f}, e.lifetime = {10.0f, 0.0f};
  ParticleState s;
  ParticleStepJob job;
  job.emitters = &emitters;
  job.forces = &still;
  job.jointWorld = &joints;
  job.state = &s;
  job.dt = 0.1f;
  ASSERT_TRUE(job.run());
  ASSERT_EQ(s.size(), 90);
  for (int i = 0; i < s.size(); ++i) {
    const glm::vec3 p = s.positions[i], v = glm::normalize(s.velocities[i]);
    switch (s.emitterOf[i]) {
      case 0: EXPECT_LE(glm::distance(p, glm::vec3(5)), 0.5f + 1e-6f); break;
      case 1:
        EXPECT_NEAR(p.y, 2.0f, 1e-6f);
        EXPECT_TRUE(p.x >= 0 && p.x <= 1 && p.z >= 0 && p.z <= 1);
        EXPECT_VEC3_NEAR(v, glm::vec3(0, 1, 0), 1e-5f);
        break;
      default:  // the joint turned 90 degrees about Z: its Y points along -X
        EXPECT_VEC3_NEAR(p, glm::vec3(-4, 0, 0), 1e-5f);
        EXPECT_VEC3_NEAR(v, glm::vec3(-1, 0, 0), 1e-5f);
    }
  }
  emitters[2].joint = 3;
  EXPECT_NE(job.validate(), "");
}

}  // namespace
}  // namespace kinema
