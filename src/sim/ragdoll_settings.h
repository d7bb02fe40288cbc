#pragma once
#include <string>
#include <vector>

#include "core/math.h"
#include "core/skeleton.h"

namespace kinema {

// A ragdoll as the user sets it up (saved in the .kinema file's "simulation"): the joint
// `root` and everything below it become rigid bodies at frame `startFrame` of the clip being
// simulated and fall from the animated pose and its velocity there. Bullet-free: the
// simulation itself is sim/ragdoll.h (library kinema_ragdoll).
struct RagdollSettings {
  std::string name;
  int root = 0;                  // joint index; the ragdoll is this joint's subtree
  long long startFrame = 0;      // clip frame (Clip::frameToTime) the physics takes over at, >= 0
  float mass = 70.0f;            // kg, > 0: shared among the bodies by volume
  glm::vec3 gravity{0.0f, -9.81f, 0.0f};  // file units / s^2, world space
  float groundHeight = 0.0f;     // world Y of the ground plane (file units)
  float friction = 0.8f;         // Coulomb friction with the ground, >= 0
  float restitution = 0.0f;      // bounce, 0..1
  float damping = 0.1f;          // fraction of linear and angular velocity lost per second, 0..1

  // Empty when usable on `skeleton`; otherwise one sentence naming the problem.
  std::string validate(const Skeleton& skeleton) const;
  bool operator==(const RagdollSettings& o) const;
};

}  // namespace kinema
