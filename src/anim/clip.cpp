#include "anim/clip.h"
#include "core/math.h"

#include <algorithm>
#include <cmath>

namespace kinema {

namespace {

template <typename E, size_t N>
bool lookUp(const std::string& s, E& out, const E (&all)[N]) {
  for (E e : all)
    if (s == toString(e)) {
      out = e;
      return true;
    }
  return false;
}

const ChannelTarget kTargets[] = {ChannelTarget::Translation, ChannelTarget::Rotation, ChannelTarget::Scale,
                                  ChannelTarget::Euler, ChannelTarget::Scalar};
const Interpolation kInterpolations[] = {Interpolation::Step,   Interpolation::Linear,     Interpolation::Hermite,
                                         Interpolation::CatmullRom, Interpolation::TCB, Interpolation::Bezier,
                                         Interpolation::Ease,   Interpolation::Nlerp,      Interpolation::Squad};
const EasingFunction kEasings[] = {EasingFunction::Sine,  EasingFunction::Quad, EasingFunction::Cubic,
                                   EasingFunction::Quart, EasingFunction::Quint, EasingFunction::Expo,
                                   EasingFunction::Circ,  EasingFunction::Back, EasingFunction::Bounce,
                                   EasingFunction::Elastic};
const EasingMode kModes[] = {EasingMode::In, EasingMode::Out, EasingMode::InOut};
const HandleType kHandles[] = {HandleType::Free, HandleType::Aligned, HandleType::Vector, HandleType::Auto,
                               HandleType::AutoClamped};

bool suits(Interpolation i, ChannelTarget target) {
  if (target == ChannelTarget::Rotation)
    return i == Interpolation::Step || i == Interpolation::Linear || i == Interpolation::Nlerp ||
           i == Interpolation::Squad || i == Interpolation::Hermite || i == Interpolation::Ease ||
           i == Interpolation::Bezier;
  return i != Interpolation::Nlerp && i != Interpolation::Squad;
}


}  // namespace

const char* toString(ChannelTarget target) {
  switch (target) {
    case ChannelTarget::Translation: return "translation";
    case ChannelTarget::Rotation: return "rotation";
    case ChannelTarget::Scale: return "scale";
    case ChannelTarget::Euler: return "euler";
    case ChannelTarget::Scalar: return "scalar";
  }
  return "rotation";
}

const char* toString(Interpolation interpolation) {
  switch (interpolation) {
    case Interpolation::Step: return "step";
    case Interpolation::Linear: return "linear";
    case Interpolation::Hermite: return "hermite";
    case Interpolation::CatmullRom: return "catmull-rom";
    case Interpolation::TCB: return "tcb";
    case Interpolation::Bezier: return "bezier";
    case Interpolation::Ease: return "ease";
    case Interpolation::Nlerp: return "nlerp";
    case Interpolation::Squad: return "squad";
  }
  return "linear";
}

const char* toString(EasingFunction easing) {
  switch (easing) {
    case EasingFunction::Sine: return "sine";
    case EasingFunction::Quad: return "quad";
    case EasingFunction::Cubic: return "cubic";
    case EasingFunction::Quart: return "quart";
    case EasingFunction::Quint: return "quint";
    case EasingFunction::Expo: return "expo";
    case EasingFunction::Circ: return "circ";
    case EasingFunction::Back: return "back";
    case EasingFunction::Bounce: return "bounce";
    case EasingFunction::Elastic: return "elastic";
  }
  return "sine";
}

const char* toString(EasingMode mode) {
  switch (mode) {
    case EasingMode::In: return "in";
    case EasingMode::Out: return "out";
    case EasingMode::InOut: return "in-out";
  }
  return "in-out";
}

const char* toString(HandleType type) {
  switch (type) {
    case HandleType::Free: return "free";
    case HandleType::Aligned: return "aligned";
    case HandleType::Vector: return "vector";
    case HandleType::Auto: return "auto";
    case HandleType::AutoClamped: return "auto-clamped";
  }
  return "auto-clamped";
}

bool fromString(const std::string& s, ChannelTarget& out) { return lookUp(s, out, kTargets); }
bool fromString(const std::string& s, Interpolation& out) { return lookUp(s, out, kInterpolations); }
bool fromString(const std::string& s, EasingFunction& out) { return lookUp(s, out, kEasings); }
bool fromString(const std::string& s, EasingMode& out) { return lookUp(s, out, kModes); }
bool fromString(const std::string& s, HandleType& out) { return lookUp(s, out, kHandles); }

bool KeySettings::operator==(const KeySettings& o) const {
  return interpolation == o.interpolation && easing == o.easing && easingMode == o.easingMode &&
         tension == o.tension && continuity == o.continuity && bias == o.bias && inTangent == o.inTangent &&
         outTangent == o.outTangent && leftHandleType == o.leftHandleType && rightHandleType == o.rightHandleType &&
         leftHandleTime == o.leftHandleTime && rightHandleTime == o.rightHandleTime &&
         leftHandleValue == o.leftHandleValue && rightHandleValue == o.rightHandleValue;
}

KeySettings Channel::settings(int k) const {
  if (!keys.empty()) return keys[k];
  KeySettings s;
  s.interpolation = interpolation;
  return s;
}

int Channel::valueSize() const {
  switch (target) {
    case ChannelTarget::Rotation: return 4;
    case ChannelTarget::Scalar: return 1;
    default: return 3;
  }
}

float Clip::duration() const {
  float d = 0.0f;
  for (const Channel& c : channels) d = std::max(d, c.endTime());
  return d;
}

std::string Clip::validate(const Skeleton& skeleton) const {
  if (hasRange && (!std::isfinite(rangeStart) || !std::isfinite(rangeEnd) || rangeStart > rangeEnd))
    return "the playback range must be two finite times, start <= end";
  if (std::string bad = contacts.validate(); !bad.empty()) return bad;
  if (std::string bad = sourceMap.validate(skeleton.size()); !bad.empty()) return bad;
  for (size_t c = 0; c < channels.size(); ++c) {
    const Channel& ch = channels[c];
    const std::string where = "channel " + std::to_string(c);
    const bool scalar = ch.target == ChannelTarget::Scalar;
    if ((ch.joint < 0 && !(scalar && ch.joint == -1)) || ch.joint >= skeleton.size())
      return where + " animates joint " + std::to_string(ch.joint) + ", which does not exist";
    if (ch.times.empty()) return where + " has no keys";
    if (std::string bad = validateModifierStack(ch.modifiers); !bad.empty()) return where + " " + bad;
    if (ch.times.size() != ch.values.size())
      return where + " has " + std::to_string(ch.times.size()) + " key times but " +
             std::to_string(ch.values.size()) + " values";
    if (!ch.keys.empty() && ch.keys.size() != ch.times.size())
      return where + " has " + std::to_string(ch.times.size()) + " key times but " +
             std::to_string(ch.keys.size()) + " key settings";
    if (ch.keys.empty() && !suits(ch.interpolation, ch.target))
      return where + ": " + toString(ch.interpolation) + " interpolation does not apply to " + toString(ch.target);
    for (size_t k = 0; k < ch.times.size(); ++k) {
      const std::string key = where + " key " + std::to_string(k);
      if (!std::isfinite(ch.times[k])) return key + " has a non-finite time";
      if (k > 0 && !(ch.times[k] > ch.times[k - 1])) return key + " time is not after the previous key";
      if (!isFinite(ch.values[k])) return key + " has a non-finite value";
      if (ch.keys.empty()) continue;
      const KeySettings& s = ch.keys[k];
      if (!suits(s.interpolation, ch.target))
        return key + ": " + toString(s.interpolation) + " interpolation does not apply to " + toString(ch.target);
      if (!std::isfinite(s.tension) || !std::isfinite(s.continuity) || !std::isfinite(s.bias) ||
          !isFinite(s.inTangent) || !isFinite(s.outTangent) || !std::isfinite(s.leftHandleTime) ||
          !std::isfinite(s.rightHandleTime) || !isFinite(s.leftHandleValue) || !isFinite(s.rightHandleValue))
        return key + " has a non-finite tangent, handle or TCB setting";
      if (s.leftHandleTime > 0 || s.rightHandleTime < 0)
        return key + " has a Bezier handle on the wrong side of the key (left must be <= 0, right >= 0 seconds)";
    }
  }
  return {};
}

int findKey(const Channel& ch, float time) {
  // The keys within the tolerance are next to where `time` would be inserted.
  const int at = static_cast<int>(std::lower_bound(ch.times.begin(), ch.times.end(), time) - ch.times.begin());
  int best = -1;
  for (int k : {at - 1, at})
    if (k >= 0 && k < ch.keyCount() && sameKeyTime(ch.times[k], time) &&
        (best < 0 || std::abs(ch.times[k] - time) < std::abs(ch.times[best] - time)))
      best = k;
  return best;
}

int insertKey(Channel& ch, float time, const glm::vec4& value) {
  if (const int existing = findKey(ch, time); existing >= 0) {
    ch.values[existing] = value;
    return existing;
  }
  const auto it = std::lower_bound(ch.times.begin(), ch.times.end(), time);
  const int k = static_cast<int>(it - ch.times.begin());
  // A new key takes the settings of the key before it (the segment it splits), or of the
  // key after it when it becomes the first key.
  return insertKey(ch, time, value, ch.times.empty() ? ch.settings(0) : ch.settings(k > 0 ? k - 1 : 0));
}

int insertKey(Channel& ch, float time, const glm::vec4& value, const KeySettings& settings) {
  const int existing = findKey(ch, time);
  const auto it = std::lower_bound(ch.times.begin(), ch.times.end(), time);
  const int k = existing >= 0 ? existing : static_cast<int>(it - ch.times.begin());
  // Materialise per-key settings once any key differs from the channel-wide default.
  KeySettings channelDefault;
  channelDefault.interpolation = ch.interpolation;
  if (ch.keys.empty() && settings != channelDefault) {
    ch.keys.assign(ch.times.size(), channelDefault);
    if (ch.times.empty()) ch.interpolation = settings.interpolation;
  }
  const bool perKey = !ch.keys.empty() || settings != channelDefault;
  if (existing >= 0) {
    ch.values[k] = value;
    if (perKey) ch.keys[k] = settings;
    return k;
  }
  ch.times.insert(ch.times.begin() + k, time);
  ch.values.insert(ch.values.begin() + k, value);
  if (perKey) ch.keys.insert(ch.keys.begin() + k, settings);
  return k;
}

int moveKey(Channel& ch, int key, float newTime) {
  if (key < 0 || key >= ch.keyCount()) return -1;
  const glm::vec4 value = ch.values[key];
  const KeySettings s = ch.settings(key);
  const bool hadKeys = !ch.keys.empty();
  deleteKey(ch, key);
  if (!hadKeys) {
    // Keep the channel compact: the settings were the channel-wide ones.
    if (const int existing = findKey(ch, newTime); existing >= 0) {
      ch.values[existing] = value;
      return existing;
    }
    const auto it = std::lower_bound(ch.times.begin(), ch.times.end(), newTime);
    const int k = static_cast<int>(it - ch.times.begin());
    ch.times.insert(ch.times.begin() + k, newTime);
    ch.values.insert(ch.values.begin() + k, value);
    return k;
  }
  if (ch.keys.empty() && !ch.times.empty()) ch.keys.assign(ch.times.size(), s);
  return insertKey(ch, newTime, value, s);
}

void deleteKey(Channel& ch, int key) {
  if (key < 0 || key >= ch.keyCount()) return;
  ch.times.erase(ch.times.begin() + key);
  ch.values.erase(ch.values.begin() + key);
  if (!ch.keys.empty()) ch.keys.erase(ch.keys.begin() + key);
}

void setBezierHandle(Channel& ch, int key, bool right, float timeOffset, const glm::vec4& valueOffset) {
  if (key < 0 || key >= ch.keyCount()) return;
  if (ch.keys.empty()) ch.keys.assign(ch.times.size(), ch.settings(0));
  KeySettings& s = ch.keys[key];
  HandleType& type = right ? s.rightHandleType : s.leftHandleType;
  HandleType& other = right ? s.leftHandleType : s.rightHandleType;
  if (type == HandleType::Auto || type == HandleType::AutoClamped) type = HandleType::Aligned;
  if (type == HandleType::Vector) type = HandleType::Free;
  // Blender: editing one handle of an auto pair makes both aligned.
  if (other == HandleType::Auto || other == HandleType::AutoClamped) other = HandleType::Aligned;
  (right ? s.rightHandleTime : s.leftHandleTime) = right ? std::max(0.0f, timeOffset) : std::min(0.0f, timeOffset);
  (right ? s.rightHandleValue : s.leftHandleValue) = valueOffset;
  if (type == HandleType::Aligned && other == HandleType::Aligned) {
    float& otherTime = right ? s.leftHandleTime : s.rightHandleTime;
    glm::vec4& otherValue = right ? s.leftHandleValue : s.rightHandleValue;
    if (otherTime == 0.0f) {
      // A handle with no time extent: give it the neighbour's third, as Blender's defaults.
      const int nb = right ? key - 1 : key + 1;
      otherTime = (nb >= 0 && nb < ch.keyCount()) ? (ch.times[nb] - ch.times[key]) / 3.0f : -timeOffset;
    }
    // Opposite direction, same slope: collinear through the key.
    if (timeOffset != 0.0f) otherValue = valueOffset * (otherTime / timeOffset);
  }
}

void unwrapEulerAngles(Channel& ch) {
  for (size_t k = 1; k < ch.values.size(); ++k)
    for (int i = 0; i < 3; ++i) {
      const float prev = ch.values[k - 1][i];
      float& a = ch.values[k][i];
      a -= kTwoPi * std::round((a - prev) / kTwoPi);
    }
}

}  // namespace kinema
