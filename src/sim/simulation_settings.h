#pragma once
#include <string>
#include <vector>

#include "sim/crowd_settings.h"
#include "sim/particle_system.h"
#include "sim/ragdoll_settings.h"
#include "sim/spring_bones.h"

namespace kinema {

// Everything a file says about simulating it (the .kinema "simulation" key): its dynamic
// chains (spring bones) and its ragdolls. `kinema simulate` and the editor's Bake read it.
struct SimulationSettings {
  std::vector<SpringBoneChain> springChains;
  std::vector<RagdollSettings> ragdolls;
  std::vector<CrowdSettings> crowds;  // flocks of animated characters (sim/crowd.h)
  std::vector<ParticleSystemSettings> particles;  // played, not baked (sim/particle_system.h)

  bool empty() const { return springChains.empty() && ragdolls.empty() && crowds.empty() && particles.empty(); }
  // Parts a bake turns into joint keys (particles are played, not baked; crowds have Bake Crowd).
  bool hasBakedParts() const { return !springChains.empty() || !ragdolls.empty(); }
  // Empty when every part fits `skeleton` and no joint is driven by two parts; otherwise
  // one sentence naming the first problem.
  std::string validate(const Skeleton& skeleton) const;
};

}  // namespace kinema
