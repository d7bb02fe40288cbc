#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include "core/math.h"

namespace kinema {

// A particle system (Reeves 1983; the seed's chapter 003, 16.7): emitters create particles
// with random lifetimes and velocities, old ones die, the rest move under gravity, wind and
// drag and bounce off the ground and spheres. Model space, metres, seconds; Y is up.
// Seeded and deterministic: one seed and one sequence of steps give the same particles on
// every build.

// A random value: uniform in [mean - spread, mean + spread], or normal with standard
// deviation `spread`; negative draws are clamped to 0 (speeds, lifetimes, rates).
enum class RandomDistribution { Uniform, Normal };
struct RandomRange {
  float mean = 1.0f;
  float spread = 0.0f;  // >= 0
  RandomDistribution distribution = RandomDistribution::Uniform;
};

enum class EmitterShape { Point, Sphere, MeshSurface, Joint };
const char* toString(EmitterShape shape);

struct ParticleEmitter {
  EmitterShape shape = EmitterShape::Point;
  glm::vec3 position{0.0f};    // Point: where; Sphere: the centre; Joint: offset in the joint's frame
  float radius = 0.5f;         // Sphere: particles start uniformly inside it (> 0)
  // MeshSurface: a triangle list (model space); particles start uniformly over its area and,
  // with alongNormal, leave along the triangle's normal instead of `direction`.
  std::vector<glm::vec3> surfacePositions;
  std::vector<uint32_t> surfaceIndices;
  bool alongNormal = true;
  int joint = -1;              // Joint: index into ParticleStepJob::jointWorld
  glm::vec3 direction{0, 1, 0};  // the velocity cone's axis (for Joint, in the joint's frame)
  float coneDegrees = 15.0f;   // half-angle of the cone, [0, 180]
  RandomRange speed{2.0f, 0.5f, RandomDistribution::Uniform};  // m/s
  RandomRange rate{100.0f, 0.0f, RandomDistribution::Uniform}; // particles per second, drawn each step
  RandomRange lifetime{2.0f, 0.5f, RandomDistribution::Uniform};  // seconds
};

struct ParticleSphere {
  glm::vec3 centre{0.0f};
  float radius = 1.0f;  // > 0
};

struct ParticleForces {
  glm::vec3 gravity{0.0f, -9.81f, 0.0f};  // m/s^2
  glm::vec3 wind{0.0f};                   // the air's velocity, m/s (felt through drag)
  float drag = 0.0f;                      // per second: dv/dt = gravity + drag (wind - v)
  bool ground = true;                     // a plane at y = groundHeight
  float groundHeight = 0.0f;
  float restitution = 0.5f;               // [0, 1]: normal speed kept by a bounce
  float friction = 0.0f;                  // [0, 1]: share of the tangential speed a bounce takes
  std::vector<ParticleSphere> spheres;    // particles bounce off their outside
  std::string validate() const;
};

// The particles (flat arrays, one entry per live particle, in birth order) and the
// generator's state: what one step hands the next.
struct ParticleState {
  std::vector<glm::vec3> positions, velocities;
  std::vector<float> ages, lifetimes;  // seconds
  std::vector<uint32_t> emitterOf;
  std::vector<float> emitCarry;        // per emitter: the fraction of a particle owed
  uint64_t random = 1;                 // the generator's state; set it to the seed to start
  double time = 0.0;
  uint64_t emitted = 0;                // particles born so far (alive or dead)
  int size() const { return static_cast<int>(positions.size()); }
};

// One step: ages every particle by dt and removes those past their lifetime, moves the rest
// along the exact solution of dv/dt = gravity + drag (wind - v) for dt (so no forces is a
// straight line and gravity alone an exact parabola, whatever dt), bouncing at the moment of
// each contact with the ground or a sphere (normal speed times restitution, tangential speed
// times 1 - friction); then emits each emitter's new particles at age 0 where it stands.
struct ParticleStepJob {
  const std::vector<ParticleEmitter>* emitters = nullptr;
  const ParticleForces* forces = nullptr;
  const std::vector<glm::mat4>* jointWorld = nullptr;  // model-space joint matrices (Joint emitters)
  float dt = 1.0f / 30.0f;                             // (0, 1] s
  size_t maxParticles = 1u << 22;                      // emission stops at this many
  ParticleState* state = nullptr;                      // read and written

  std::string validate() const;
  bool run();
};

}  // namespace kinema
