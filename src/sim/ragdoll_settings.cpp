#include "sim/ragdoll_settings.h"

#include <cmath>

namespace kinema {

std::string RagdollSettings::validate(const Skeleton& s) const {
  const std::string who = "ragdoll '" + name + "': ";
  if (root < 0 || root >= s.size()) return who + "root joint " + std::to_string(root) + " is not in the skeleton";
  if (startFrame < 0 || startFrame > 1000000000LL) return who + "start frame must be 0 to 1,000,000,000";
  if (!std::isfinite(mass) || !(mass > 0.0f)) return who + "mass must be a finite number above 0";
  if (!isFinite(gravity)) return who + "gravity is not finite";
  if (!std::isfinite(groundHeight)) return who + "ground height is not finite";
  if (!std::isfinite(friction) || friction < 0.0f) return who + "friction must be a finite number >= 0";
  if (!(restitution >= 0.0f && restitution <= 1.0f)) return who + "restitution must be 0 to 1";
  if (!(damping >= 0.0f && damping <= 1.0f)) return who + "damping must be 0 to 1";
  return "";
}

bool RagdollSettings::operator==(const RagdollSettings& o) const {
  return name == o.name && root == o.root && startFrame == o.startFrame && mass == o.mass && gravity == o.gravity &&
         groundHeight == o.groundHeight && friction == o.friction && restitution == o.restitution && damping == o.damping;
}

}  // namespace kinema
