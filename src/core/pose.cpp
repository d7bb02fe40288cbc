#include "core/pose.h"

namespace kinema {

std::string Pose::validate(const Skeleton& skeleton) const {
  if (local.size() != skeleton.parents.size())
    return "pose has " + std::to_string(local.size()) + " transforms for " +
           std::to_string(skeleton.parents.size()) + " joints";
  for (size_t i = 0; i < local.size(); ++i)
    if (!local[i].isFinite())
      return "pose transform of joint " + std::to_string(i) + " '" + skeleton.names[i] +
             "' is not finite";
  return {};
}

}  // namespace kinema
