// Fuzzes the .kinema reader; whatever it accepts must save and read back identically.
#include <cstdint>
#include <cstdlib>
#include <string>

#include "core/forward_kinematics.h"
#include "io/kinema_file.h"
#include "evaluation/scene_deformation.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  kinema::Result<kinema::Scene> r = kinema::parseKinemaJson(text, "fuzz.kinema");
  if (!r.ok()) {
    if (r.error().find('\n') != std::string::npos || r.error().rfind("fuzz.kinema:", 0) != 0) std::abort();
    return 0;
  }
  if (!r->skeleton.validate().empty()) std::abort();
  const std::string saved = kinema::toKinemaJson(r.value());
  kinema::Result<kinema::Scene> back = kinema::parseKinemaJson(saved, "fuzz.kinema");
  if (!back.ok()) std::abort();
  if (kinema::toKinemaJson(back.value()) != saved) std::abort();  // round trip is exact
  kinema::Pose pose = kinema::Pose::rest(r->skeleton);
  for (const kinema::Clip& clip : r->clips) kinema::sampleClip(clip, clip.duration() * 0.5f, pose);
  // Skinning and morph targets on whatever loaded: may refuse, must not crash.
  const std::vector<glm::mat4> world = kinema::computeWorld(r->skeleton, pose);
  const std::vector<std::vector<float>> morph = kinema::sampleMorphWeights(r.value(), r->clips.empty() ? -1 : 0, 0.5);
  std::vector<kinema::DeformedPrimitive> deformed;
  kinema::SceneDeformationJob job;
  job.scene = &r.value();
  job.world = &world;
  job.morphWeights = &morph;
  job.out = &deformed;
  (void)job.run();
  return 0;
}
