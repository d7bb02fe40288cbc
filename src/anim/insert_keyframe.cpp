#include "anim/insert_keyframe.h"
#include "core/math.h"

#include <algorithm>
#include <cmath>

namespace kinema {

namespace {


Channel* findChannel(Clip& clip, int joint, ChannelTarget target) {
  for (Channel& c : clip.channels)
    if (c.joint == joint && c.target == target) return &c;
  return nullptr;
}

// New channels' keys: Bezier with auto-clamped handles (KeySettings' default), rotations too.
KeySettings defaultKeySettings() {
  KeySettings s;
  s.interpolation = Interpolation::Bezier;
  return s;
}

void key(Clip& clip, int joint, ChannelTarget target, float time, glm::vec4 value,
         const std::optional<KeySettings>& settings = std::nullopt) {
  Channel* ch = findChannel(clip, joint, target);
  if (!ch) {
    Channel c;
    c.joint = joint;
    c.target = target;
    c.interpolation = settings ? settings->interpolation : defaultKeySettings().interpolation;
    clip.channels.push_back(c);
    ch = &clip.channels.back();
  }
  if (ch->keyCount() > 0) {
    // The neighbour before the new key (or after it, when it becomes the first).
    const auto it = std::lower_bound(ch->times.begin(), ch->times.end(), time);
    const int k = static_cast<int>(it - ch->times.begin());
    const glm::vec4& ref = ch->values[k > 0 ? k - 1 : 0];
    if (target == ChannelTarget::Rotation && glm::dot(value, ref) < 0.0f) value = -value;
    if (target == ChannelTarget::Euler)
      for (int i = 0; i < 3; ++i) value[i] -= kTwoPi * std::round((value[i] - ref[i]) / kTwoPi);
  }
  if (settings) insertKey(*ch, time, value, *settings);
  else insertKey(*ch, time, value);
}

}  // namespace

std::string InsertKeyframeJob::validate(const Skeleton& skeleton, const Pose& pose) const {
  if (!std::isfinite(time)) return "the key time is not a finite number";
  const std::string bad = pose.validate(skeleton);
  if (!bad.empty()) return bad;
  for (int j : joints)
    if (j < 0 || j >= skeleton.size()) return "joint " + std::to_string(j) + " does not exist";
  return {};
}

int insertKeyframe(Clip& clip, const InsertKeyframeJob& job, const Pose& pose) {
  int written = 0;
  for (int j : job.joints) {
    if (j < 0 || j >= pose.size()) continue;
    const Transform& t = pose.local[j];
    if (job.translation) {
      key(clip, j, ChannelTarget::Translation, job.time, glm::vec4(t.translation, 0.0f), job.settings);
      ++written;
    }
    if (job.rotation) {
      // A joint keyed as Euler angles stays Euler.
      if (Channel* e = findChannel(clip, j, ChannelTarget::Euler)) {
        key(clip, j, ChannelTarget::Euler, job.time, glm::vec4(quatToEuler(t.rotation, e->eulerOrder), 0.0f),
            job.settings);
      } else {
        const glm::quat q = glm::normalize(t.rotation);
        key(clip, j, ChannelTarget::Rotation, job.time, glm::vec4(q.x, q.y, q.z, q.w), job.rotationSettings);
      }
      ++written;
    }
    if (job.scale) {
      key(clip, j, ChannelTarget::Scale, job.time, glm::vec4(t.scale, 0.0f), job.settings);
      ++written;
    }
  }
  return written;
}

}  // namespace kinema
