#include "anim/clip_keying.h"

#include <algorithm>
#include <cstring>

#include "anim/insert_keyframe.h"

namespace kinema {

namespace {

bool hasChannel(const Clip& clip, int joint, ChannelTarget target) {
  for (const Channel& c : clip.channels)
    if (c.joint == joint && c.target == target) return true;
  return false;
}

bool contains(const std::vector<int>& joints, int j) { return std::find(joints.begin(), joints.end(), j) != joints.end(); }

}  // namespace

Interpolation rotationInterpolation(Interpolation preferred) {
  switch (preferred) {
    case Interpolation::Step:
    case Interpolation::Linear:
    case Interpolation::Nlerp:
    case Interpolation::Squad:
    case Interpolation::Hermite:
    case Interpolation::Bezier:
    case Interpolation::Ease: return preferred;
    case Interpolation::CatmullRom:
    case Interpolation::TCB: return Interpolation::Squad;
  }
  return Interpolation::Squad;
}

KeySettings keySettingsFor(const KeyPreferences& preferences, ChannelTarget target) {
  KeySettings s;
  Interpolation i = preferences.interpolation;
  if (target == ChannelTarget::Rotation) i = rotationInterpolation(i);
  else if (i == Interpolation::Nlerp || i == Interpolation::Squad) i = Interpolation::Linear;  // rotations only
  s.interpolation = i;
  s.leftHandleType = s.rightHandleType = preferences.handles;
  return s;
}

Clip newActionClip(const FrameGrid& grid) {
  Clip c;
  c.name = kNewClipName;  // no rate of its own: it counts at the document's
  c.hasRange = true;
  c.rangeStart = grid.frameToTime(kNewClipStartFrame);
  c.rangeEnd = grid.frameToTime(kNewClipEndFrame);
  return c;
}

int keyJoints(std::vector<Clip>& clips, int& clip, const Skeleton& skeleton, const Pose& pose,
              const std::vector<int>& joints, float time, const KeyPreferences& preferences,
              const FrameGrid& newClipGrid) {
  if (joints.empty()) return 0;
  if (clip < 0 || clip >= static_cast<int>(clips.size())) {
    clips.push_back(newActionClip(newClipGrid));
    clip = static_cast<int>(clips.size()) - 1;
  }
  Clip& c = clips[clip];
  InsertKeyframeJob job;
  job.time = time;
  job.settings = keySettingsFor(preferences, ChannelTarget::Translation);
  job.rotationSettings = keySettingsFor(preferences, ChannelTarget::Rotation);
  job.scale = false;
  int written = 0;
  for (int j : joints) {
    if (j < 0 || j >= pose.size() || j >= skeleton.size()) continue;
    job.joints = {j};
    const bool scaled = std::memcmp(&pose.local[j].scale, &skeleton.rest[j].scale, sizeof(glm::vec3)) != 0;
    job.scale = !preferences.locRotOnly && (scaled || hasChannel(c, j, ChannelTarget::Scale));
    written += insertKeyframe(c, job, pose);
  }
  return written;
}

int deleteJointKeys(Clip& clip, const std::vector<int>& joints, float time) {
  int deleted = 0;
  for (Channel& ch : clip.channels) {
    if (!contains(joints, ch.joint)) continue;
    for (int k = findKey(ch, time); k >= 0; k = findKey(ch, time)) {
      deleteKey(ch, k);
      ++deleted;
    }
  }
  // A channel left without keys animates nothing: drop it (Blender deletes empty F-curves).
  clip.channels.erase(std::remove_if(clip.channels.begin(), clip.channels.end(),
                                     [](const Channel& ch) { return ch.times.empty(); }),
                      clip.channels.end());
  return deleted;
}

std::vector<float> jointKeyTimes(const Clip& clip, const std::vector<int>& joints) {
  std::vector<float> times;
  for (const Channel& ch : clip.channels)
    if (contains(joints, ch.joint)) times.insert(times.end(), ch.times.begin(), ch.times.end());
  std::sort(times.begin(), times.end());
  times.erase(std::unique(times.begin(), times.end()), times.end());
  return times;
}

}  // namespace kinema
