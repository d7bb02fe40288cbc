#include "ik/pose_ik_target.h"

#include <cstring>

namespace kinema {

IkTarget PoseIkTarget::resolved(const Skeleton& skeleton) const {
  IkTarget t = target;
  if (chainLength > 0 && t.effector >= 0 && t.effector < skeleton.size()) {
    int root = t.effector;
    for (int k = 0; k < chainLength && skeleton.parents[root] >= 0; ++k) root = skeleton.parents[root];
    t.root = root;
  }
  return t;
}

std::string PoseIkTarget::validate(const Skeleton& skeleton) const {
  if (chainLength < 0) return "chain length " + std::to_string(chainLength) + " is negative";
  const IkTarget t = resolved(skeleton);
  std::string bad = t.validate(skeleton);
  if (bad.empty() && t.root == t.effector) bad = "the effector has no parent to move";
  return bad;
}

namespace {
bool same(float a, float b) { return std::memcmp(&a, &b, sizeof a) == 0; }
bool same(const glm::vec3& a, const glm::vec3& b) { return same(a.x, b.x) && same(a.y, b.y) && same(a.z, b.z); }
bool same(const glm::quat& a, const glm::quat& b) {
  return same(a.x, b.x) && same(a.y, b.y) && same(a.z, b.z) && same(a.w, b.w);
}
}  // namespace

bool sameBits(const PoseIkTarget& a, const PoseIkTarget& b) {
  const IkTarget &x = a.target, &y = b.target;
  return x.effector == y.effector && x.root == y.root && same(x.position, y.position) &&
         x.hasOrientation == y.hasOrientation && same(x.orientation, y.orientation) && same(x.weight, y.weight) &&
         x.mid == y.mid && x.hasPole == y.hasPole && same(x.pole, y.pole) && a.chainLength == b.chainLength &&
         a.solver == b.solver && a.active == b.active && a.pinned == b.pinned;
}

}  // namespace kinema
