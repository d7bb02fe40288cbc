#pragma once
#include <cstdint>
#include <string>

#include "sim/boids.h"

namespace kinema {

// One crowd saved in a .kinema file (simulation.crowds): a flock of boids whose members are
// instances of one animated character. Model space, metres, seconds; Y is up; the flock moves
// on the ground plane (boids.planar is set when the crowd runs).
struct CrowdSettings {
  CrowdSettings() { boids.planar = true; }
  std::string name = "crowd";
  // The character each member is an instance of: a file with a skeleton and a clip (.kinema,
  // .gltf, .glb, .bvh), relative to the .kinema file's folder; "" = the file's own character.
  std::string character;
  int clip = 0;             // which of the character's clips the members play (index)
  int members = 50;         // 1 .. kCrowdMaxMembers
  uint64_t seed = 1;        // the start layout, headings and clip phases follow from it alone
  glm::vec3 spawnCentre{0.0f};  // members start on a jittered square lattice around it
  // The ground speed (m/s) at which the clip plays at its own rate; 0 = measured from the
  // clip's root motion (a clip that walks in place then plays at rate 1 at the cruise speed).
  float strideSpeed = 0.0f;
  // The character's facing in its clip (degrees about +Y from +Z) when the clip walks in
  // place; a clip with root motion faces the way it moves.
  float forwardDegrees = 0.0f;
  int debugMember = 0;      // the member whose impulses the editor draws
  BoidsSettings boids;      // weights, neighbourhood, obstacles, goal, allocation

  // "" or one sentence naming the first bad value.
  std::string validate() const;
  bool operator==(const CrowdSettings& o) const;
  bool operator!=(const CrowdSettings& o) const { return !(*this == o); }
};

constexpr int kCrowdMaxMembers = 100000;

}  // namespace kinema
