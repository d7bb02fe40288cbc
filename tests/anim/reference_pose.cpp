#include "anim/reference_pose.h"

#include <algorithm>
#include <cmath>

#include "anim/sampling.h"

namespace kinema::test {

Pose referencePose(const Clip& clip, const Pose& base, float time) {
  Pose pose = base;
  for (const Channel& ch : clip.channels) {
    if (ch.target == ChannelTarget::Scalar || ch.joint < 0 || ch.joint >= pose.size() || ch.times.empty()) continue;
    const glm::vec4 v = sampleChannelReference(ch, time);
    Transform& t = pose.local[ch.joint];
    switch (ch.target) {
      case ChannelTarget::Translation: t.translation = glm::vec3(v); break;
      case ChannelTarget::Scale: t.scale = glm::vec3(v); break;
      case ChannelTarget::Rotation: t.rotation = glm::quat(v.w, v.x, v.y, v.z); break;
      case ChannelTarget::Euler: t.rotation = eulerToQuat(glm::vec3(v), ch.eulerOrder); break;
      case ChannelTarget::Scalar: break;
    }
  }
  return pose;
}

float maxPoseDifference(const Pose& a, const Pose& b) {
  float d = 0.0f;
  for (int j = 0; j < a.size(); ++j) {
    const Transform &x = a.local[j], &y = b.local[j];
    for (int i = 0; i < 3; ++i) {
      d = std::max(d, std::abs(x.translation[i] - y.translation[i]));
      d = std::max(d, std::abs(x.scale[i] - y.scale[i]));
    }
    for (int i = 0; i < 4; ++i) d = std::max(d, std::abs(x.rotation[i] - y.rotation[i]));
  }
  return d;
}

}  // namespace kinema::test
