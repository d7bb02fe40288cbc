// Boids: priority acceleration allocation (by hand), separation kept in a 500-member flock,
// obstacles, the field of view, and the grid finding the same neighbours as the naive search.
#include <gtest/gtest.h>

#include <cmath>

#include <nlohmann/json.hpp>

#include "io/image.h"
#include "sim/boids.h"
#include "core/random.h"
#include "test_support.h"

namespace kinema {
namespace KINEMA_UNITY_ID {

TEST(BoidsAllocation, PriorityGivesAvoidanceItsFullAccelerationWhenTheBudgetIsShort) {
  // Budget 10 m/s^2; avoidance asks 8 along x, separation 6 along y, alignment 5 along z.
  // By hand: avoidance gets all 8 (2 left), separation the remaining 2 along y, alignment 0.
  const glm::vec3 impulses[3] = {{8, 0, 0}, {0, 6, 0}, {0, 0, 5}};
  glm::vec3 granted[3];
  const glm::vec3 a = allocateAcceleration(impulses, 3, 10.0f, AccelerationAllocation::Priority, granted);
  EXPECT_VEC3_NEAR(granted[0], glm::vec3(8, 0, 0), 1e-6f);
  EXPECT_VEC3_NEAR(granted[1], glm::vec3(0, 2, 0), 1e-6f);
  EXPECT_VEC3_NEAR(granted[2], glm::vec3(0, 0, 0), 1e-6f);
  EXPECT_VEC3_NEAR(a, glm::vec3(8, 2, 0), 1e-6f);
  // The naive average: (8, 6, 5) / 3, length 11.18 / 3 = 3.73 < 10 so not shortened: avoidance
  // gets a third of what it asked.
  const glm::vec3 b = allocateAcceleration(impulses, 3, 10.0f, AccelerationAllocation::Average, granted);
  EXPECT_VEC3_NEAR(b, glm::vec3(8.0f / 3, 2.0f, 5.0f / 3), 1e-5f);
  EXPECT_VEC3_NEAR(granted[0], glm::vec3(8.0f / 3, 0, 0), 1e-5f);
  // Opposite impulses cancel in the average (the seed's "nowhere to go"), not under priority.
  const glm::vec3 opposite[2] = {{4, 0, 0}, {-4, 0, 0}};
  EXPECT_VEC3_NEAR(allocateAcceleration(opposite, 2, 5.0f, AccelerationAllocation::Average, granted), glm::vec3(0), 1e-6f);
  EXPECT_VEC3_NEAR(allocateAcceleration(opposite, 2, 5.0f, AccelerationAllocation::Priority, granted), glm::vec3(3, 0, 0), 1e-6f);
  // A budget above every request serves them all.
  EXPECT_VEC3_NEAR(allocateAcceleration(impulses, 3, 100.0f, AccelerationAllocation::Priority, granted), glm::vec3(8, 6, 5), 1e-6f);
}

struct Flock {
  std::vector<glm::vec3> p, v;
};

// n members on a jittered lattice 2.5 m apart (so they start farther apart than the separation
// distance), flying in random directions at the cruise speed.
Flock makeFlock(int n, uint64_t seed) {
  SplitMix64 r(seed);
  Flock f;
  const int side = static_cast<int>(std::ceil(std::cbrt(double(n))));
  for (int i = 0; i < n; ++i) {
    const glm::vec3 cell(i % side, (i / side) % side, i / (side * side));
    f.p.push_back(2.5f * cell + glm::vec3(r.uniform(-0.5, 0.5), r.uniform(-0.5, 0.5), r.uniform(-0.5, 0.5)));
    glm::vec3 d(static_cast<float>(r.normal()), static_cast<float>(r.normal()), static_cast<float>(r.normal()));
    f.v.push_back(2.0f * glm::normalize(d));
  }
  return f;
}

float closestPair(const std::vector<glm::vec3>& p) {
  float best = 1e30f;
  for (size_t i = 0; i < p.size(); ++i)
    for (size_t j = i + 1; j < p.size(); ++j) best = std::min(best, glm::distance(p[i], p[j]));
  return best;
}

TEST(Boids, FiveHundredMembersNeverComeCloserThanTheSeparationDistance) {
  const BoidsSettings settings;  // the defaults
  Flock f = makeFlock(500, 5);
  ASSERT_GT(closestPair(f.p), settings.separationDistance);
  BoidsStepJob step;
  step.settings = &settings;
  const int steps = test::propertyCases(300);  // 10 s at 30 steps per second locally
  float closest = 1e30f;
  for (int k = 0; k < steps; ++k) {
    step.positions = &f.p;
    step.velocities = &f.v;
    ASSERT_TRUE(step.run());
    f.p = step.outPositions;
    f.v = step.outVelocities;
    closest = std::min(closest, closestPair(f.p));
  }
  EXPECT_GE(closest, settings.separationDistance);
  // It is a flock: cohesion has drawn the members together (the lattice started 2.5 m apart).
  EXPECT_LT(closest, 2.0f);
}

TEST(Boids, GridFindsTheSameNeighboursAsTheNaiveSearch) {
  BoidsSettings grid;
  grid.spheres.push_back({glm::vec3(5, 5, 5), 2.0f});
  BoidsSettings naive = grid;
  naive.search = NeighbourSearch::Naive;
  Flock f = makeFlock(300, 9);
  for (glm::vec3& p : f.p) p *= 0.6f;  // crowded, many neighbours, some inside the separation range
  BoidsStepJob a, b;
  a.settings = &grid;
  b.settings = &naive;
  a.positions = b.positions = &f.p;
  a.velocities = b.velocities = &f.v;
  ASSERT_TRUE(a.run() && b.run());
  for (size_t i = 0; i < f.p.size(); ++i) {
    EXPECT_VEC3_NEAR(a.outVelocities[i], b.outVelocities[i], 1e-4f);
    EXPECT_VEC3_NEAR(a.outPositions[i], b.outPositions[i], 1e-5f);
  }
}

TEST(Boids, MembersFlyingAtObstaclesStayOutside) {
  BoidsSettings s;
  s.spheres.push_back({glm::vec3(0, 0, 10), 2.0f});
  s.boxes.push_back({glm::vec3(-12, -2, 8), glm::vec3(-8, 2, 12)});
  s.hasGoal = true;
  s.goal = glm::vec3(0, 0, 30);  // straight through the sphere
  Flock f;
  for (int i = 0; i < 40; ++i) {
    const float x = -11.0f + 0.6f * static_cast<float>(i % 20), y = (i / 20) * 1.5f - 0.75f;
    f.p.push_back({x, y, 0.0f});
    f.v.push_back({0, 0, 3});
  }
  BoidsStepJob step;
  step.settings = &s;
  for (int k = 0; k < 300; ++k) {
    step.positions = &f.p;
    step.velocities = &f.v;
    ASSERT_TRUE(step.run());
    f.p = step.outPositions;
    f.v = step.outVelocities;
    for (const glm::vec3& p : f.p) {
      EXPECT_GT(glm::distance(p, s.spheres[0].centre), s.spheres[0].radius) << "step " << k;
      const BoidBox& b = s.boxes[0];
      const bool inBox = p.x > b.min.x && p.x < b.max.x && p.y > b.min.y && p.y < b.max.y && p.z > b.min.z && p.z < b.max.z;
      EXPECT_FALSE(inBox) << "step " << k;
    }
  }
  for (const glm::vec3& p : f.p) EXPECT_GT(p.z, 15.0f);  // and they got past towards the goal
}

TEST(Boids, ALoneMemberAimedAtASphereStopsWhereAvoidanceMatchesTheGoal) {
  // On the axis the repulsion (avoidanceWeight * maxAcceleration * (1 - s / avoidanceDistance)
  // = 40 (1 - s / 2) at s metres from the surface) and the goal's pull at rest
  // (goalWeight * maxSpeed = 4) balance at s = 1.8: z = 10 - 2 - 1.8 = 6.2, and both are
  // granted in full (8 < the 20 m/s^2 budget).
  BoidsSettings s;
  s.spheres.push_back({glm::vec3(0, 0, 10), 2.0f});
  s.hasGoal = true;
  s.goal = glm::vec3(0, 0, 30);
  std::vector<glm::vec3> p = {{0, 0, 0}}, v = {{0, 0, 3}};
  BoidsStepJob step;
  step.settings = &s;
  step.debugBoid = 0;
  for (int k = 0; k < 600; ++k) {
    step.positions = &p;
    step.velocities = &v;
    ASSERT_TRUE(step.run());
    p = step.outPositions;
    v = step.outVelocities;
    EXPECT_LT(p[0].z, 8.0f);
  }
  EXPECT_NEAR(p[0].z, 6.2f, 0.01f);
  EXPECT_NEAR(glm::length(v[0]), 0.0f, 0.01f);
  EXPECT_VEC3_NEAR(step.debug.granted[0], step.debug.desired[0], 1e-6f);
  EXPECT_NEAR(step.debug.desired[0].z, -4.0f, 0.05f);
  EXPECT_NEAR(step.debug.granted[4].z, 4.0f, 0.05f);
}

TEST(Boids, FieldOfViewHidesMembersBehind) {
  BoidsSettings s;
  s.fieldOfViewDegrees = 180.0f;
  const std::vector<glm::vec3> p = {{0, 0, 0}, {0, 0, 3}, {0, 0, -3}}, v = {{0, 0, 1}, {1, 0, 0}, {-1, 0, 0}};
  BoidsStepJob step;
  step.settings = &s;
  step.positions = &p;
  step.velocities = &v;
  step.debugBoid = 0;
  ASSERT_TRUE(step.run());
  EXPECT_EQ(step.debug.neighbours, 1);  // the one ahead only
  // Alignment by hand: (mean seen velocity - own) * weight = ((1,0,0) - (0,0,1)) * 1.
  EXPECT_VEC3_NEAR(step.debug.desired[2], glm::vec3(1, 0, -1), 1e-6f);
  s.fieldOfViewDegrees = 360.0f;
  ASSERT_TRUE(step.run());
  EXPECT_EQ(step.debug.neighbours, 2);
}

}  // namespace
}  // namespace kinema

namespace kinema {
namespace KINEMA_UNITY_ID {

TEST(BoidsDemo, WritesBothModesAndPriorityKeepsMembersOutOfObstacles) {
  const std::string dir = test::makeTempDir();
  std::string out, err;
  ASSERT_EQ(test::runCommand(std::string(KINEMA_BINARY) + " demo boids --out " + dir + " --size 640x420", &out, &err), 0)
      << err;
  const nlohmann::json j = nlohmann::json::parse(test::readFile(dir + "/numbers.json"));
  EXPECT_EQ(j["priority"]["intrusion_steps"], 0);
  // The naive average lets avoidance be outvoted by the goal and the flock (this scene, its seed).
  EXPECT_GT(j["average"]["intrusion_steps"].get<int>(), 0);
  EXPECT_GT(j["priority"]["reached_goal"].get<int>(), 0);
  for (const char* f : {"priority.png", "average.png"}) {
    Result<Image> img = loadPng(dir + "/" + f);
    ASSERT_TRUE(img.ok()) << f;
    EXPECT_EQ(img->width, 640);
  }
}

}  // namespace
}  // namespace kinema
