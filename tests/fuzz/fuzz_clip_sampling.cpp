// Fuzzes clip sampling with arbitrary numbers (NaN, Inf, denormals, huge values) as key
// times, values and sample times: sampling must never crash, and with finite keys and a
// finite time it must give finite, unit rotations.
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <vector>

#include "anim/clip.h"

namespace {
float take(const std::uint8_t*& p, const std::uint8_t* end) {
  float f = 0.0f;
  if (end - p >= 4) {
    std::memcpy(&f, p, 4);
    p += 4;
  }
  return f;
}
}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, size_t size) {
  if (size < 2) return 0;
  const std::uint8_t* p = data + 2;
  const std::uint8_t* end = data + size;
  kinema::Skeleton skeleton;
  skeleton.addJoint("a", -1, kinema::Transform::identity());
  kinema::Channel ch;
  ch.joint = 0;
  ch.target = static_cast<kinema::ChannelTarget>(data[0] % 3);
  ch.interpolation = static_cast<kinema::Interpolation>(data[1] % 2);
  const int keys = 1 + static_cast<int>((size - 2) / 20 % 16);
  for (int k = 0; k < keys && end - p >= 20; ++k) {
    ch.times.push_back(take(p, end));
    ch.values.emplace_back(take(p, end), take(p, end), take(p, end), take(p, end));
  }
  const float time = take(p, end);
  if (ch.times.empty()) return 0;
  kinema::Clip clip;
  clip.channels.push_back(ch);
  const bool valid = clip.validate(skeleton).empty();
  kinema::Pose pose = kinema::Pose::rest(skeleton);
  kinema::sampleClip(clip, time, pose);  // must not crash, valid or not
  if (valid && std::isfinite(time)) {
    const kinema::Transform& t = pose.local[0];
    bool huge = false;  // lerp of values near FLT_MAX may overflow; that is float, not a bug
    for (const glm::vec4& v : ch.values)
      huge = huge || std::abs(v.x) > 1e37f || std::abs(v.y) > 1e37f || std::abs(v.z) > 1e37f;
    if (!huge && !t.isFinite()) std::abort();
    if (std::abs(glm::length(t.rotation) - 1.0f) > 1e-3f) std::abort();
  }
  return 0;
}
