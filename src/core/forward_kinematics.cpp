#include "core/forward_kinematics.h"

#include <algorithm>

namespace kinema {

std::string LocalToWorldJob::validate() const {
  if (count < 0) return "negative joint count";
  if (count > 0 && (!parents || !local || !world)) return "missing parents, local or world array";
  if (subtreeRoot < -1 || subtreeRoot >= count)
    return "sub-tree root " + std::to_string(subtreeRoot) + " is not a joint";
  for (int i = 0; i < count; ++i)
    if (parents[i] < -1 || parents[i] >= i)
      return "joint " + std::to_string(i) + " has parent " + std::to_string(parents[i]) +
             " (parents must come first)";
  return {};
}

bool LocalToWorldJob::run() const {
  if (!validate().empty()) return false;
  if (subtreeRoot < 0) {
    for (int i = 0; i < count; ++i) {
      const int p = parents[i];
      world[i] = multiplyAffine(p < 0 ? root : world[p], local[i].toMatrix());
    }
    return true;
  }
  // Descendants of subtreeRoot are exactly the later joints whose parent is marked.
  std::vector<char> inSubtree(static_cast<size_t>(count - subtreeRoot), 0);
  const int s = subtreeRoot;
  inSubtree[0] = 1;
  world[s] = multiplyAffine(parents[s] < 0 ? root : world[parents[s]], local[s].toMatrix());
  for (int i = s + 1; i < count; ++i) {
    const int p = parents[i];
    if (p < s || !inSubtree[p - s]) continue;
    inSubtree[i - s] = 1;
    world[i] = multiplyAffine(world[p], local[i].toMatrix());
  }
  return true;
}

void computeWorld(const Skeleton& skeleton, const Pose& pose, std::vector<glm::mat4>& world) {
  // A pose that does not fit the skeleton yields transforms only for the joints it covers.
  const int count = std::min(skeleton.size(), pose.size());
  world.resize(static_cast<size_t>(count));
  LocalToWorldJob job;
  job.parents = skeleton.parents.data();
  job.local = pose.local.data();
  job.world = world.data();
  job.count = count;
  job.run();
}

std::vector<glm::mat4> computeWorld(const Skeleton& skeleton, const Pose& pose) {
  std::vector<glm::mat4> world;
  computeWorld(skeleton, pose, world);
  return world;
}

void updateSubtree(const Skeleton& skeleton, const Pose& pose, int joint,
                   std::vector<glm::mat4>& world) {
  LocalToWorldJob job;
  job.parents = skeleton.parents.data();
  job.local = pose.local.data();
  job.world = world.data();
  job.count = std::min({skeleton.size(), pose.size(), static_cast<int>(world.size())});
  job.subtreeRoot = joint;
  job.run();
}

}  // namespace kinema
