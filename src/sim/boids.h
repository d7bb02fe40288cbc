#pragma once
#include <string>
#include <vector>

#include "core/math.h"

namespace kinema {

// A flock of boids (Reynolds 1987; the seed's chapter 003, 16.7). Each member balances
// several impulses, each a desired acceleration, and a fixed acceleration budget is handed
// out to them in priority order: obstacle avoidance, separation, alignment, cohesion, goal
// (or cruising speed). Once the budget is spent the lower impulses get nothing, so avoiding
// a collision is never cancelled out by the wish to stay with the flock, the failure of
// simply averaging the impulses (kept as AccelerationAllocation::Average, for comparison).
// Model space, metres, seconds; Y is up.

enum class AccelerationAllocation { Priority, Average };
enum class NeighbourSearch { Grid, Naive };  // uniform spatial hash grid, or all pairs (O(n^2))

// The impulses, highest priority first.
enum class BoidImpulse { Avoidance = 0, Separation, Alignment, Cohesion, Goal };
constexpr int kBoidImpulseCount = 5;
const char* toString(BoidImpulse impulse);

struct BoidSphere {
  glm::vec3 centre{0.0f};
  float radius = 1.0f;  // > 0
};
struct BoidBox {  // axis-aligned
  glm::vec3 min{-0.5f}, max{0.5f};
};

struct BoidsSettings {
  float separationDistance = 1.0f;   // metres: members push apart harder as they come closer than twice this
  float neighbourRadius = 4.0f;      // metres: how far a member sees (> 0)
  float fieldOfViewDegrees = 270.0f; // (0, 360]: alignment and cohesion see only ahead; separation all round
  float separationWeight = 1.5f;     // multiples of maxAcceleration at the separation distance
  float alignmentWeight = 1.0f;      // per second: (mean neighbour velocity - own) * weight
  float cohesionWeight = 0.5f;       // per second squared: (neighbour centroid - own position) * weight
  float avoidanceWeight = 2.0f;      // multiples of maxAcceleration at an obstacle's surface
  float avoidanceDistance = 2.0f;    // metres from an obstacle's surface where its repulsion starts
  float goalWeight = 1.0f;           // per second: (desired velocity - own) * weight
  float maxSpeed = 4.0f;             // metres per second (> 0)
  float cruiseSpeed = 2.0f;          // speed kept without a goal (m/s, <= maxSpeed)
  float maxAcceleration = 20.0f;     // the budget, m/s^2 (> 0)
  bool hasGoal = false;
  glm::vec3 goal{0.0f};              // seek this point at maxSpeed when hasGoal
  bool planar = false;               // ground crowds: accelerations and velocities keep y = 0
  AccelerationAllocation allocation = AccelerationAllocation::Priority;
  NeighbourSearch search = NeighbourSearch::Grid;
  std::vector<BoidSphere> spheres;
  std::vector<BoidBox> boxes;

  std::string validate() const;
};

// Hands `budget` (m/s^2) to `impulses` (desired accelerations, highest priority first):
// Priority gives each in turn all it asks while the budget lasts, the first it cannot fully
// serve the rest of the budget along its own direction, the others nothing; Average takes
// the mean of the non-zero impulses, shortened to the budget. `granted` (same count) gets
// each impulse's share; the sum is the acceleration.
glm::vec3 allocateAcceleration(const glm::vec3* impulses, int count, float budget, AccelerationAllocation mode,
                               glm::vec3* granted);

// What one member felt in the last step (for teaching figures and the editor's debug vectors).
struct BoidDebug {
  glm::vec3 desired[kBoidImpulseCount];  // each impulse's desired acceleration
  glm::vec3 granted[kBoidImpulseCount];  // what the allocation gave it
  glm::vec3 acceleration{0.0f};
  int neighbours = 0;
};

// One explicit step (semi-implicit Euler: v += a dt, clamped to maxSpeed; p += v dt) of the
// whole flock. Reads positions/velocities, writes the outputs (which may not alias the inputs).
struct BoidsStepJob {
  const BoidsSettings* settings = nullptr;
  const std::vector<glm::vec3>* positions = nullptr;
  const std::vector<glm::vec3>* velocities = nullptr;
  float dt = 1.0f / 30.0f;  // seconds, (0, 1]
  int debugBoid = -1;       // >= 0: fill `debug` for this member

  std::vector<glm::vec3> outPositions, outVelocities;
  BoidDebug debug;

  std::string validate() const;
  bool run();

 private:
  // The grid's buffers, kept between runs only to avoid reallocating (results never depend on them).
  std::vector<int> cellStart_, cellEntries_;
  std::vector<uint32_t> cellOf_;
  std::vector<int> candidates_;
};

}  // namespace kinema
