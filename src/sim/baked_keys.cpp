#include "sim/baked_keys.h"

#include <algorithm>

#include "core/forward_kinematics.h"

namespace kinema {

KeyReductionSettings bakedKeyTolerances(const Skeleton& s) {
  glm::vec3 lo(1e30f), hi(-1e30f);
  for (const glm::mat4& m : computeWorld(s, Pose::rest(s))) {
    lo = glm::min(lo, glm::vec3(m[3]));
    hi = glm::max(hi, glm::vec3(m[3]));
  }
  const float size = s.size() > 0 ? glm::length(hi - lo) : 0.0f;
  KeyReductionSettings settings;
  settings.positionTolerance = size > 0.0f ? 1e-3f * size : 1e-3f;
  settings.angleTolerance = 0.5f * 0.01745329252f;
  return settings;
}

std::string reduceBakedKeys(const Skeleton& s, Clip& clip, const std::vector<int>& joints,
                            const KeyReductionSettings& settings, KeyReductionReport* report) {
  auto baked = [&](const Channel& c) {
    return (c.target == ChannelTarget::Rotation || c.target == ChannelTarget::Translation) &&
           std::find(joints.begin(), joints.end(), c.joint) != joints.end();
  };
  // Only those channels go through the reduction: its world-space check needs no other
  // channel (a joint's error moves rigidly with its unbaked ancestors).
  Clip part = clip;
  part.channels.clear();
  for (const Channel& c : clip.channels)
    if (baked(c)) part.channels.push_back(c);
  Clip reduced;
  KeyReductionJob job;
  job.skeleton = &s;
  job.clip = &part;
  job.settings = settings;
  job.output = &reduced;
  job.report = report;
  if (std::string e = job.validate(); !e.empty()) return e;
  if (!job.run()) return "the key reduction failed";
  clip.channels.erase(std::remove_if(clip.channels.begin(), clip.channels.end(), baked), clip.channels.end());
  for (Channel& c : reduced.channels) clip.channels.push_back(std::move(c));
  return "";
}

}  // namespace kinema
