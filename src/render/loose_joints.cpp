#include "render/loose_joints.h"

namespace kinema {

namespace {

bool strays(const glm::vec3& translation, const glm::vec3& rest) {
  const float tolerance = 1e-3f * glm::length(rest) + 1e-6f;
  return !(glm::length(translation - rest) <= tolerance);  // NaN strays too
}

}  // namespace

std::vector<char> looseJoints(const Skeleton& skeleton, const Clip* clip, const Pose& pose) {
  const int n = skeleton.size();
  std::vector<char> loose(static_cast<size_t>(n), 0);
  for (int j = 0; j < n && j < pose.size(); ++j)
    if (skeleton.parents[j] >= 0 && strays(pose.local[j].translation, skeleton.rest[j].translation)) loose[j] = 1;
  if (!clip) return loose;
  for (const Channel& ch : clip->channels) {
    if (ch.target != ChannelTarget::Translation || ch.joint < 0 || ch.joint >= n || loose[ch.joint]) continue;
    if (skeleton.parents[ch.joint] < 0) continue;
    const glm::vec3 rest = skeleton.rest[ch.joint].translation;
    for (const glm::vec4& v : ch.values)
      if (strays(glm::vec3(v), rest)) {
        loose[ch.joint] = 1;
        break;
      }
  }
  return loose;
}

}  // namespace kinema
