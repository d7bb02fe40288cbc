#include "editor/model/channel_modifier_edits.h"

#include <algorithm>

#include "anim/channel_modifiers.h"
#include "core/forward_kinematics.h"
#include "editor/model/edit_labels.h"

namespace kinema {

std::vector<int> modifierTargetChannels(const Clip& clip, const JointSelection& selection,
                                        const CurveEditorState& state) {
  const std::vector<int> shown = shownChannels(clip, selection);
  std::vector<int> out;
  for (const CurveKeyRef& k : state.selected)
    if (std::find(shown.begin(), shown.end(), k.channel) != shown.end()) out.push_back(k.channel);
  if (out.empty()) return shown;
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
  return out;
}

ChannelModifier defaultChannelModifier(ChannelModifierKind kind, const Channel& channel, const Skeleton& skeleton) {
  const bool angles = channel.target == ChannelTarget::Rotation || channel.target == ChannelTarget::Euler;
  const float size = angles ? 0.1f : 0.05f;
  ChannelModifier m;
  m.kind = kind;
  if (channel.target == ChannelTarget::Scalar) m.components = 0x1;
  m.noise.strength = size;
  m.noise.scale = 0.5f;
  m.noise.octaves = 2;
  m.noise.seed = static_cast<uint32_t>(std::max(channel.joint, 0));
  m.wave.amplitude = size;
  m.wave.omega = 6.283185307f;
  if (channel.joint >= 0 && channel.joint < skeleton.size())
    m.wave.position = glm::vec3(computeWorld(skeleton, Pose::rest(skeleton))[channel.joint][3]);
  return m;
}

namespace {
const char* kindLabel(ChannelModifierKind kind) {
  switch (kind) {
    case ChannelModifierKind::Noise: return "Noise";
    case ChannelModifierKind::Cycles: return "Cycles";
    case ChannelModifierKind::Wave: return "Wave";
  }
  return "";
}
}  // namespace

std::string addChannelModifierEdit(Document& doc, int clipIndex, const std::vector<int>& channels,
                                   ChannelModifierKind kind) {
  const std::string label = std::string("Add ") + kindLabel(kind) + " Modifier";
  if (channels.empty()) return label + ": select a joint with animated channels (or keys in the curve editor) first";
  return doc.edit(label + " to " + countPhrase(channels.size(), "channel"), [&](DocumentEdit& e) -> std::string {
    if (clipIndex < 0 || clipIndex >= static_cast<int>(e.clips.size())) return label + ": no clip to edit";
    Clip& clip = e.clips[clipIndex];
    for (int c : channels) {
      if (c < 0 || c >= static_cast<int>(clip.channels.size())) return label + ": channel " + std::to_string(c) + " is not in the clip";
      Channel& ch = clip.channels[c];
      if (kind == ChannelModifierKind::Cycles)
        for (const ChannelModifier& m : ch.modifiers)
          if (m.kind == ChannelModifierKind::Cycles)
            return label + ": channel " + std::to_string(c) + " already has a Cycles modifier (a channel takes one)";
      ch.modifiers.push_back(defaultChannelModifier(kind, ch, e.skeleton));
    }
    return std::string();
  });
}

}  // namespace kinema
