// Fuzzes the BVH reader and everything a loaded file flows into (skeleton, clip, FK).
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <string>

#include "core/forward_kinematics.h"
#include "io/bvh.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  kinema::Result<kinema::BvhData> r = kinema::parseBvh(text, "fuzz.bvh");
  if (!r.ok()) {
    // Errors are one line that names the file.
    if (r.error().find('\n') != std::string::npos || r.error().rfind("fuzz.bvh:", 0) != 0) std::abort();
    return 0;
  }
  const kinema::Skeleton skeleton = r->skeleton();
  if (!skeleton.validate().empty()) std::abort();  // the reader must only produce valid skeletons
  const kinema::Clip clip = r->clip();
  if (!clip.validate(skeleton).empty() && r->frameCount > 1 && r->frameTime > 1e-30) {
    // Times k * frameTime can collide only when frameTime is tiny; otherwise a bad clip is a bug.
    if (ownFrameGrid(clip).frameToTime(1) > ownFrameGrid(clip).frameToTime(0)) std::abort();
  }
  kinema::Pose pose = kinema::Pose::rest(skeleton);
  for (float t : {-1.0f, 0.0f, clip.duration() * 0.37f, clip.duration() + 1.0f}) {
    kinema::sampleClip(clip, t, pose);
    for (const kinema::Transform& x : pose.local)
      if (std::abs(glm::length(x.rotation) - 1.0f) > 1e-3f) std::abort();  // rotations stay unit
    (void)kinema::computeWorld(skeleton, pose);
  }
  return 0;
}
