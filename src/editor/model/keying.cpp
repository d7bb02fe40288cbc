#include "editor/model/keying.h"

#include <algorithm>
#include <cmath>

#include "editor/model/document.h"
#include "editor/model/edit_labels.h"

namespace kinema {

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
