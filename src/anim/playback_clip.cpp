#include "anim/playback_clip.h"

#include <algorithm>
#include <cstring>
#include <functional>
#include <string_view>
#include <unordered_map>

#include "core/rotation.h"

namespace kinema {

namespace {

// Linear or Step when every segment of the channel interpolates that way (the last key's
// own setting starts no segment); Bezier otherwise, meaning "not for a grid".
Interpolation uniformInterpolation(const Channel& ch) {
  if (ch.keys.empty()) return ch.interpolation;
  if (ch.keys.size() != ch.times.size()) return Interpolation::Bezier;
  const Interpolation first = ch.keys[0].interpolation;
  for (int k = 1; k + 1 < ch.keyCount(); ++k)
    if (ch.keys[k].interpolation != first) return Interpolation::Bezier;
  return first;
}

bool suitsGrid(const Channel& ch) {
  // Modified channels are sampled one by one through their stack (sampleModifiedChannel).
  if (ch.keyCount() < 2 || ch.values.size() != ch.times.size() || !ch.modifiers.empty()) return false;
  if (ch.target != ChannelTarget::Translation && ch.target != ChannelTarget::Scale &&
      ch.target != ChannelTarget::Rotation)
    return false;
  const Interpolation i = uniformInterpolation(ch);
  return i == Interpolation::Linear || i == Interpolation::Step;
}

// The key as sampling reads it: rotations normalised (only when measurably off unit
// length, as sampleChannel does), the rest as stored.
glm::vec4 sampledKey(const Channel& ch, int k) {
  const glm::vec4& v = ch.values[k];
  if (ch.target != ChannelTarget::Rotation) return v;
  const float len2 = v.x * v.x + v.y * v.y + v.z * v.z + v.w * v.w;
  if (std::abs(len2 - 1.0f) < 1e-6f) return v;
  const glm::quat q = safeNormalize(glm::quat(v.w, v.x, v.y, v.z));
  return {q.x, q.y, q.z, q.w};
}

size_t hashTimes(const std::vector<float>& times) {
  return std::hash<std::string_view>()(
      std::string_view(reinterpret_cast<const char*>(times.data()), times.size() * sizeof(float)));
}

PlaybackGrid makeGrid(const Clip& clip, const std::vector<int>& members) {
  PlaybackGrid g;
  g.times = clip.channels[members[0]].times;
  std::vector<int> kinds[3];  // translation, scale, rotation: channel indices
  for (int c : members) {
    const ChannelTarget t = clip.channels[c].target;
    kinds[t == ChannelTarget::Translation ? 0 : t == ChannelTarget::Scale ? 1 : 2].push_back(c);
  }
  // Joint order within a kind: the pose is written front to back.
  for (auto& kind : kinds)
    std::stable_sort(kind.begin(), kind.end(),
                     [&](int a, int b) { return clip.channels[a].joint < clip.channels[b].joint; });
  g.translationBlocks = static_cast<int>(kinds[0].size() + 3) / 4;
  g.scaleBlocks = static_cast<int>(kinds[1].size() + 3) / 4;
  g.rotationBlocks = static_cast<int>(kinds[2].size() + 3) / 4;
  g.rowFloats = 12 * (g.translationBlocks + g.scaleBlocks) + 16 * g.rotationBlocks;
  // Lanes in row order; a block's unused lanes repeat its first channel.
  std::vector<int> lanes;
  std::vector<int> components;  // per block
  for (int kind = 0; kind < 3; ++kind) {
    const std::vector<int>& list = kinds[kind];
    for (size_t b = 0; b < list.size(); b += 4) {
      for (size_t l = 0; l < 4; ++l) lanes.push_back(list[b + l < list.size() ? b + l : b]);
      components.push_back(kind == 2 ? 4 : 3);
    }
  }
  for (int c : lanes) {
    g.joints.push_back(clip.channels[c].joint);
    g.linear.push_back(uniformInterpolation(clip.channels[c]) == Interpolation::Linear ? 1.0f : 0.0f);
  }
  for (size_t b = 0; b < components.size(); ++b)
    g.blockHasStep.push_back(std::min({g.linear[4 * b], g.linear[4 * b + 1], g.linear[4 * b + 2], g.linear[4 * b + 3]}) == 0.0f);
  const int n = g.keyCount();
  g.rows.resize(static_cast<size_t>(n) * g.rowFloats);
  for (int k = 0; k < n; ++k) {
    float* row = g.rows.data() + static_cast<size_t>(k) * g.rowFloats;
    for (size_t b = 0; b < components.size(); ++b) {
      for (int l = 0; l < 4; ++l) {
        const glm::vec4 v = sampledKey(clip.channels[lanes[4 * b + l]], k);
        for (int i = 0; i < components[b]; ++i) row[4 * i + l] = v[i];
      }
      row += 4 * components[b];
    }
  }
  return g;
}

}  // namespace

PlaybackClip PlaybackClip::build(const Clip& clip, int jointCount) {
  PlaybackClip p;
  p.jointCount = std::max(0, jointCount);
  // The channel that wins each (joint, part): translation, rotation (or Euler), scale.
  std::vector<int> winner(static_cast<size_t>(p.jointCount) * 3, -1);
  for (size_t c = 0; c < clip.channels.size(); ++c) {
    const Channel& ch = clip.channels[c];
    if (ch.target == ChannelTarget::Scalar || ch.joint < 0 || ch.joint >= p.jointCount || ch.keyCount() == 0)
      continue;
    const int part = ch.target == ChannelTarget::Translation ? 0 : ch.target == ChannelTarget::Scale ? 2 : 1;
    winner[static_cast<size_t>(ch.joint) * 3 + part] = static_cast<int>(c);
  }
  // Grid candidates grouped by identical key times.
  std::vector<std::vector<int>> groups;
  std::unordered_map<size_t, std::vector<int>> groupsByHash;
  std::vector<int> others;
  for (int c : winner) {
    if (c < 0) continue;
    const Channel& ch = clip.channels[c];
    if (!suitsGrid(ch)) {
      others.push_back(c);
      continue;
    }
    std::vector<int>& candidates = groupsByHash[hashTimes(ch.times)];
    int group = -1;
    for (int g : candidates)
      if (clip.channels[groups[g][0]].times == ch.times) group = g;
    if (group < 0) {
      group = static_cast<int>(groups.size());
      groups.emplace_back();
      candidates.push_back(group);
    }
    groups[group].push_back(c);
  }
  for (const std::vector<int>& members : groups) {
    if (static_cast<int>(members.size()) < kMinGridTracks) {
      others.insert(others.end(), members.begin(), members.end());
      continue;
    }
    p.grids.push_back(makeGrid(clip, members));
  }
  std::sort(others.begin(), others.end());
  for (int c : others) p.channels.push_back(clip.channels[c]);
  return p;
}

int PlaybackClip::trackCount() const {
  int n = static_cast<int>(channels.size());
  for (const PlaybackGrid& g : grids)
    for (int b = 0; b < g.blockCount(); ++b) {
      // Unused lanes repeat the block's first track.
      int distinct = 1;
      for (int l = 1; l < 4; ++l) distinct += g.joints[4 * b + l] != g.joints[4 * b] ? 1 : 0;
      n += distinct;
    }
  return n;
}

}  // namespace kinema
