#include "editor/model/keying.h"

#include <algorithm>
#include <cmath>
#include <cstring>

#include "anim/insert_keyframe.h"
#include "editor/model/document.h"
#include "editor/model/edit_labels.h"

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

namespace {
// "frame 12" on the clip's frame grid (a first key makes a new action: its grid).
std::string keyTimePhrase(const Document& doc, int clip, float time) {
  const bool exists = clip >= 0 && clip < static_cast<int>(doc.scene().clips.size());
  return "frame " + std::to_string(std::llround(doc.scene().frameGrid(exists ? clip : -1).timeToFrame(time)));
}
}  // namespace

std::string insertKeys(Document& doc, int& clip, float time, const std::vector<int>& joints,
                       const KeyPreferences& preferences) {
  if (joints.empty()) return "select the joints to key first";
  if (!std::isfinite(time)) return "the key time is not a finite number";
  for (int j : joints)
    if (j < 0 || j >= doc.skeleton().size()) return "joint " + std::to_string(j) + " does not exist";
  int target = clip;
  const std::string error = doc.edit("Insert keys on " + jointsPhrase(doc.skeleton(), joints) + " at " +
                                         keyTimePhrase(doc, clip, time),
                                     [&](DocumentEdit& e) {
    const int clipsBefore = static_cast<int>(e.clips.size());
    keyJoints(e.clips, target, e.skeleton, e.pose, joints, time, preferences, documentFrameGrid(e.frameRate));
    if (static_cast<int>(e.clips.size()) > clipsBefore) e.activeClip = target;  // the new "Action" plays
    return std::string();
  });
  if (error.empty()) clip = target;
  return error;
}

std::string insertKeysOnAllJoints(Document& doc, int& clip, float time, const KeyPreferences& preferences) {
  std::vector<int> all(static_cast<size_t>(doc.skeleton().size()));
  for (size_t j = 0; j < all.size(); ++j) all[j] = static_cast<int>(j);
  return insertKeys(doc, clip, time, all, preferences);
}

std::string deleteKeys(Document& doc, int clip, float time, const std::vector<int>& joints) {
  if (joints.empty()) return "select the joints whose keys to delete first";
  if (clip < 0 || clip >= static_cast<int>(doc.scene().clips.size())) return "the scene has no clip to delete keys from";
  Clip trial = doc.scene().clips[clip];
  if (deleteJointKeys(trial, joints, time) == 0)
    return "no keys of the selected joints on this frame";
  return doc.edit("Delete keys of " + jointsPhrase(doc.skeleton(), joints) + " at " + keyTimePhrase(doc, clip, time),
                  [&](DocumentEdit& e) {
    deleteJointKeys(e.clips[clip], joints, time);
    return std::string();
  });
}

std::string keyScalarProperty(Document& doc, int& clip, int joint, const std::string& property, float time, float value,
                              const KeyPreferences& preferences, const std::string& label) {
  return keyScalarProperties(doc, clip, joint, {{property, value}}, time, preferences, label);
}

std::string keyScalarProperties(Document& doc, int& clip, int joint,
                                const std::vector<std::pair<std::string, float>>& values, float time,
                                const KeyPreferences& preferences, const std::string& label) {
  for (const auto& [property, value] : values)
    if (!std::isfinite(value)) return "the value to key is not a finite number";
  if (!std::isfinite(time)) return "the key time is not a finite number";
  if (joint < -1 || joint >= doc.skeleton().size()) return "joint " + std::to_string(joint) + " does not exist";
  int keyed = clip;
  const std::string error = doc.edit(label, [&](DocumentEdit& e) {
    if (keyed < 0 || keyed >= static_cast<int>(e.clips.size())) {
      e.clips.push_back(newActionClip(documentFrameGrid(e.frameRate)));
      keyed = static_cast<int>(e.clips.size()) - 1;
      e.activeClip = keyed;
    }
    Clip& c = e.clips[keyed];
    for (const auto& [property, value] : values) {
      Channel* channel = nullptr;
      for (Channel& ch : c.channels)
        if (ch.target == ChannelTarget::Scalar && ch.joint == joint && ch.property == property) channel = &ch;
      if (!channel) {
        Channel ch;
        ch.joint = joint;
        ch.target = ChannelTarget::Scalar;
        ch.property = property;
        c.channels.push_back(std::move(ch));
        channel = &c.channels.back();
      }
      insertKey(*channel, time, glm::vec4(value, 0.0f, 0.0f, 0.0f), keySettingsFor(preferences, ChannelTarget::Scalar));
    }
    return std::string();
  });
  if (error.empty()) clip = keyed;
  return error;
}

}  // namespace kinema
