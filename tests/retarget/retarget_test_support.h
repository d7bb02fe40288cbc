#pragma once
// Shared by the retargeting tests: a smooth made-up take on any skeleton, and world
// positions computed by plain forward kinematics (the tests' own reference).
#include <cmath>
#include <random>
#include <vector>

#include "anim/clip.h"
#include "core/forward_kinematics.h"
#include "core/rotation.h"
#include "retarget/retarget_clip.h"

namespace kinema::test {

// `frames` frames at 30 fps: every joint turns smoothly (a few sine waves, up to about
// `amplitude` radians about a random axis each) and the root walks forward along +Z at
// `speed` units per second while bobbing. Linear keys, one per frame.
inline Clip makeSmoothTake(const Skeleton& s, int frames, std::mt19937& rng, float amplitude = 0.5f,
                           float speed = 1.0f) {
  std::uniform_real_distribution<float> u(-1.0f, 1.0f);
  Clip clip;
  clip.name = "take";
  clip.frameTime = 1.0 / 30.0;
  for (int j = 0; j < s.size(); ++j) {
    const glm::vec3 axis = glm::normalize(glm::vec3(u(rng), u(rng), u(rng)) + glm::vec3(1e-3f));
    const float a = amplitude * (0.5f + 0.5f * std::abs(u(rng))), w = 2.0f + 3.0f * std::abs(u(rng)), ph = 3.0f * u(rng);
    Channel c(j, ChannelTarget::Rotation, Interpolation::Linear, {}, {});
    for (int f = 0; f < frames; ++f) {
      const float t = static_cast<float>(ownFrameGrid(clip).frameToTime(f));
      const glm::quat q = s.rest[j].rotation * axisAngle(axis, a * std::sin(w * t + ph));
      c.times.push_back(t);
      c.values.push_back(glm::vec4(q.x, q.y, q.z, q.w));
    }
    clip.channels.push_back(std::move(c));
  }
  Channel root(0, ChannelTarget::Translation, Interpolation::Linear, {}, {});
  for (int f = 0; f < frames; ++f) {
    const float t = static_cast<float>(ownFrameGrid(clip).frameToTime(f));
    root.times.push_back(t);
    root.values.push_back(glm::vec4(s.rest[0].translation + glm::vec3(0.1f * std::sin(3.0f * t), 0.05f * std::sin(6.0f * t), speed * t), 0.0f));
  }
  clip.channels.push_back(std::move(root));
  return clip;
}

// World matrices of every joint at frame f of the clip's frame grid.
inline std::vector<glm::mat4> worldAtFrame(const Skeleton& s, const Clip& clip, int f) {
  Pose pose = Pose::rest(s);
  sampleClip(clip, ownFrameGrid(clip).frameToTime(f), pose);
  return computeWorld(s, pose);
}

inline glm::vec3 positionOf(const glm::mat4& m) { return glm::vec3(m[3]); }

// Rest pose height: highest minus lowest joint (world Y).
inline float restHeight(const Skeleton& s) {
  const std::vector<glm::mat4> w = computeWorld(s, Pose::rest(s));
  float lo = w[0][3].y, hi = lo;
  for (const glm::mat4& m : w) lo = std::min(lo, m[3].y), hi = std::max(hi, m[3].y);
  return hi - lo;
}

}  // namespace kinema::test
