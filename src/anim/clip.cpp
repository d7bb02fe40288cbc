#include "anim/clip.h"

#include <algorithm>
#include <cmath>

#include "core/rotation.h"

namespace kinema {

const char* toString(ChannelTarget target) {
  switch (target) {
    case ChannelTarget::Translation: return "translation";
    case ChannelTarget::Rotation: return "rotation";
    case ChannelTarget::Scale: return "scale";
  }
  return "rotation";
}

const char* toString(Interpolation interpolation) {
  switch (interpolation) {
    case Interpolation::Step: return "step";
    case Interpolation::Linear: return "linear";
  }
  return "linear";
}

float Clip::duration() const {
  float d = 0.0f;
  for (const Channel& c : channels) d = std::max(d, c.endTime());
  return d;
}

float Clip::frameToTime(long long frame) const {
  return static_cast<float>(static_cast<double>(frame) * frameTime);
}

std::string Clip::validate(const Skeleton& skeleton) const {
  for (size_t c = 0; c < channels.size(); ++c) {
    const Channel& ch = channels[c];
    const std::string where = "channel " + std::to_string(c);
    if (ch.joint < 0 || ch.joint >= skeleton.size())
      return where + " animates joint " + std::to_string(ch.joint) + ", which does not exist";
    if (ch.times.empty()) return where + " has no keys";
    if (ch.times.size() != ch.values.size())
      return where + " has " + std::to_string(ch.times.size()) + " key times but " +
             std::to_string(ch.values.size()) + " values";
    for (size_t k = 0; k < ch.times.size(); ++k) {
      if (!std::isfinite(ch.times[k])) return where + " key " + std::to_string(k) + " has a non-finite time";
      if (k > 0 && !(ch.times[k] > ch.times[k - 1]))
        return where + " key " + std::to_string(k) + " time is not after the previous key";
      const glm::vec4& v = ch.values[k];
      if (!std::isfinite(v.x) || !std::isfinite(v.y) || !std::isfinite(v.z) || !std::isfinite(v.w))
        return where + " key " + std::to_string(k) + " has a non-finite value";
    }
  }
  return {};
}

namespace {

glm::quat toQuat(const glm::vec4& v) { return safeNormalize(glm::quat(v.w, v.x, v.y, v.z)); }

void apply(const Channel& ch, const glm::vec4& v, Transform& t) {
  switch (ch.target) {
    case ChannelTarget::Translation: t.translation = glm::vec3(v); break;
    case ChannelTarget::Scale: t.scale = glm::vec3(v); break;
    case ChannelTarget::Rotation: t.rotation = toQuat(v); break;
  }
}

}  // namespace

void sampleClip(const Clip& clip, float time, Pose& pose) {
  for (const Channel& ch : clip.channels) {
    if (ch.joint < 0 || ch.joint >= pose.size() || ch.times.empty()) continue;
    Transform& t = pose.local[ch.joint];
    // First key whose time is after `time`; keys before it and at it are "reached".
    const auto it = std::upper_bound(ch.times.begin(), ch.times.end(), time);
    const size_t hi = static_cast<size_t>(it - ch.times.begin());
    if (hi == 0) {
      apply(ch, ch.values.front(), t);
      continue;
    }
    if (hi == ch.times.size()) {
      apply(ch, ch.values.back(), t);
      continue;
    }
    const size_t lo = hi - 1;
    if (ch.interpolation == Interpolation::Step || ch.times[lo] == time) {
      apply(ch, ch.values[lo], t);
      continue;
    }
    const float u = (time - ch.times[lo]) / (ch.times[hi] - ch.times[lo]);
    if (ch.target == ChannelTarget::Rotation) {
      t.rotation = safeNormalize(slerpShortest(toQuat(ch.values[lo]), toQuat(ch.values[hi]), u));
    } else {
      apply(ch, glm::mix(ch.values[lo], ch.values[hi], u), t);
    }
  }
}

}  // namespace kinema
