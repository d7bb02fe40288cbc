// Fuzzes the glTF reader (.gltf text and .glb binary; tinygltf plus our own validation)
// and everything a loaded scene flows into (skeleton, clips, FK).
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <string>

#include "core/forward_kinematics.h"
#include "io/gltf_reader.h"
#include "evaluation/scene_deformation.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, size_t size) {
  const std::string bytes(reinterpret_cast<const char*>(data), size);
  // The name decides nothing (the GLB magic does); external URIs resolve under a folder
  // that does not exist.
  kinema::Result<kinema::Scene> r = kinema::parseGltf(bytes, "/nonexistent-fuzz-dir/fuzz.gltf");
  if (!r.ok()) {
    // Errors are one line that names the file.
    if (r.error().find('\n') != std::string::npos || r.error().rfind("/nonexistent-fuzz-dir/fuzz.gltf:", 0) != 0)
      std::abort();
    return 0;
  }
  const kinema::Scene& scene = r.value();
  if (!scene.skeleton.validate().empty()) std::abort();  // the reader must only produce valid skeletons
  if (scene.nodeOfJoint.size() != static_cast<size_t>(scene.skeleton.size())) std::abort();
  for (const kinema::Mesh& mesh : scene.meshes)
    for (const kinema::MeshPrimitive& p : mesh.primitives) {
      for (uint32_t i : p.indices)
        if (i >= static_cast<uint32_t>(p.vertexCount())) std::abort();  // indices stay in range
      if (p.skinned() && p.influenceWeights.size() != static_cast<size_t>(p.vertexCount()) * kinema::kMaxInfluences)
        std::abort();
    }
  kinema::Pose pose = kinema::Pose::rest(scene.skeleton);
  for (const kinema::Clip& clip : scene.clips) {
    if (!clip.validate(scene.skeleton).empty()) std::abort();
    for (float t : {-1.0f, 0.0f, clip.duration() * 0.37f, clip.duration() + 1.0f}) {
      kinema::sampleClip(clip, t, pose);
      for (const kinema::Transform& x : pose.local)
        if (std::abs(glm::length(x.rotation) - 1.0f) > 1e-3f) std::abort();  // rotations stay unit
      (void)kinema::computeWorld(scene.skeleton, pose);
    }
  }
  // Skinning and morph targets on whatever loaded (ASan/UBSan watch the indexing). A job
  // may refuse (non-finite matrices from huge numbers) but must not crash.
  const std::vector<glm::mat4> world = kinema::computeWorld(scene.skeleton, pose);
  const std::vector<std::vector<float>> morph =
      kinema::sampleMorphWeights(scene, scene.clips.empty() ? -1 : 0, 0.5);
  std::vector<kinema::DeformedPrimitive> deformed;
  kinema::SceneDeformationJob job;
  job.scene = &scene;
  job.world = &world;
  job.morphWeights = &morph;
  job.out = &deformed;
  (void)job.run();
  return 0;
}
