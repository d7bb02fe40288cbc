#include "sim/crowd_settings.h"

#include <cmath>

namespace kinema {

std::string CrowdSettings::validate() const {
  if (members < 1 || members > kCrowdMaxMembers) return "crowd '" + name + "': members must be 1 to 100000";
  if (clip < 0) return "crowd '" + name + "': the clip index must be >= 0";
  if (!(strideSpeed >= 0.0f) || !std::isfinite(strideSpeed)) return "crowd '" + name + "': the stride speed must be finite and >= 0";
  if (!std::isfinite(forwardDegrees)) return "crowd '" + name + "': the forward angle must be finite";
  if (!std::isfinite(spawnCentre.x) || !std::isfinite(spawnCentre.y) || !std::isfinite(spawnCentre.z))
    return "crowd '" + name + "': the spawn centre must be finite";
  if (debugMember < 0 || debugMember >= members) return "crowd '" + name + "': the debug member must be one of its members";
  if (std::string e = boids.validate(); !e.empty()) return "crowd '" + name + "': " + e;
  return "";
}

namespace {
bool sameBoids(const BoidsSettings& a, const BoidsSettings& b) {
  if (a.spheres.size() != b.spheres.size() || a.boxes.size() != b.boxes.size()) return false;
  for (size_t i = 0; i < a.spheres.size(); ++i)
    if (a.spheres[i].centre != b.spheres[i].centre || a.spheres[i].radius != b.spheres[i].radius) return false;
  for (size_t i = 0; i < a.boxes.size(); ++i)
    if (a.boxes[i].min != b.boxes[i].min || a.boxes[i].max != b.boxes[i].max) return false;
  return a.separationDistance == b.separationDistance && a.neighbourRadius == b.neighbourRadius &&
         a.fieldOfViewDegrees == b.fieldOfViewDegrees && a.separationWeight == b.separationWeight &&
         a.alignmentWeight == b.alignmentWeight && a.cohesionWeight == b.cohesionWeight &&
         a.avoidanceWeight == b.avoidanceWeight && a.avoidanceDistance == b.avoidanceDistance &&
         a.goalWeight == b.goalWeight && a.maxSpeed == b.maxSpeed && a.cruiseSpeed == b.cruiseSpeed &&
         a.maxAcceleration == b.maxAcceleration && a.hasGoal == b.hasGoal && a.goal == b.goal &&
         a.allocation == b.allocation;  // planar and search: a crowd always runs on the ground, with the grid
}
}  // namespace

bool CrowdSettings::operator==(const CrowdSettings& o) const {
  return name == o.name && character == o.character && clip == o.clip && members == o.members && seed == o.seed &&
         spawnCentre == o.spawnCentre && strideSpeed == o.strideSpeed && forwardDegrees == o.forwardDegrees &&
         debugMember == o.debugMember && sameBoids(boids, o.boids);
}

}  // namespace kinema
