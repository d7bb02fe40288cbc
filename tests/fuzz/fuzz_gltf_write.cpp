// Fuzzes the glTF writer with whatever the glTF reader accepts: read -> write (.glb or
// .gltf, by the input's length, so the seeds stay plain files) -> read gives the same scene: skeleton (names, parents, rest
// transforms), clips (every channel's value at every key time, where resampling keeps the
// keys), meshes, skins, materials and decoded images; and -> .kinema -> read is exact.
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "anim/sampling.h"
#include "io/gltf_reader.h"
#include "io/gltf_writer.h"
#include "io/kinema_file.h"

namespace {

[[noreturn]] void fail(const char* what, long index = -1) {
  std::fprintf(stderr, "fuzz_gltf_write: %s (%ld)\n", what, index);
  std::abort();
}

bool near(float a, float b, float tol = 1e-5f) { return std::abs(a - b) <= tol + tol * std::abs(a); }

bool sameTransform(const kinema::Transform& a, const kinema::Transform& b) {
  for (int i = 0; i < 3; ++i)
    if (!near(a.translation[i], b.translation[i]) || !near(a.scale[i], b.scale[i])) return false;
  return std::abs(std::abs(glm::dot(glm::normalize(a.rotation), glm::normalize(b.rotation))) - 1.0f) <= 1e-4f;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, size_t size) {
  kinema::GltfWriteOptions options;
  options.binary = size & 1;
  const std::string bytes(reinterpret_cast<const char*>(data), size);
  kinema::Result<kinema::Scene> first = kinema::parseGltf(bytes, "/nonexistent-fuzz-dir/fuzz.gltf");
  if (!first.ok()) return 0;
  const kinema::Scene& a = first.value();
  // Huge numbers make FK and resampling non-finite; the writer may refuse those, never crash.
  std::vector<std::string> report;
  const kinema::Result<std::string> written = kinema::gltfBytes(a, options, &report);
  if (!written.ok()) {
    if (written.error().find('\n') != std::string::npos) fail("a multi-line error");
    return 0;
  }
  kinema::Result<kinema::Scene> second = kinema::parseGltf(written.value(), "/nonexistent-fuzz-dir/out.gltf");
  if (!second.ok()) {
    std::fprintf(stderr, "%s\n", second.error().c_str());
    fail("the reader refused what the writer wrote");
  }
  const kinema::Scene& b = second.value();
  if (b.skeleton.size() != a.skeleton.size()) fail("joint count changed", b.skeleton.size());
  for (int j = 0; j < a.skeleton.size(); ++j) {
    if (b.skeleton.names[j] != a.skeleton.names[j]) fail("a name changed", j);
    if (b.skeleton.parents[j] != a.skeleton.parents[j]) fail("a parent changed", j);
    if (!sameTransform(a.skeleton.rest[j], b.skeleton.rest[j])) fail("a rest transform changed", j);
  }
  // Skins: kept as they are; a scene without any gets one armature skin per joint tree.
  if (!a.skins.empty() && b.skins.size() != a.skins.size()) fail("skin count changed");
  for (size_t s = 0; s < a.skins.size(); ++s)
    if (b.skins[s].joints != a.skins[s].joints) fail("skin joints changed", static_cast<long>(s));
  if (b.meshes.size() != a.meshes.size() || b.materials.size() != a.materials.size()) fail("meshes or materials changed");
  for (size_t m = 0; m < a.meshes.size(); ++m) {
    if (b.meshes[m].primitives.size() != a.meshes[m].primitives.size()) fail("primitive count changed", m);
    for (size_t p = 0; p < a.meshes[m].primitives.size(); ++p) {
      const kinema::MeshPrimitive &pa = a.meshes[m].primitives[p], &pb = b.meshes[m].primitives[p];
      if (pa.positions.size() != pb.positions.size() || pa.indices != pb.indices) fail("vertices changed", m);
      for (size_t v = 0; v < pa.positions.size(); ++v)
        if (pa.positions[v] != pb.positions[v]) fail("a position changed", m);
    }
  }
  size_t decoded = 0;
  for (const kinema::TextureImage& im : a.images) decoded += !kinema::isUndecodedImage(im);
  if (b.images.size() != decoded) fail("decoded images were not all kept");
  // Clips: every channel's value at its own key times (exact conversions and resampling both
  // keep the keys), through the whole pose.
  if (b.clips.size() > a.clips.size()) fail("clips were added");
  for (size_t c = 0; c < b.clips.size(); ++c) {
    const kinema::Clip& ca = a.clips[c];
    for (const kinema::Channel& ch : ca.channels) {
      if (ch.target == kinema::ChannelTarget::Scalar) continue;  // morph weights: checked by their own tests
      for (size_t k = 0; k < ch.times.size() && k < 8; ++k) {
        kinema::Pose pa = kinema::Pose::rest(a.skeleton), pb = kinema::Pose::rest(b.skeleton);
        kinema::sampleClip(ca, ch.times[k], pa);
        kinema::sampleClip(b.clips[c], ch.times[k], pb);
        if (!pa.local[ch.joint].isFinite()) continue;
        if (!sameTransform(pa.local[ch.joint], pb.local[ch.joint])) fail("a key's value changed", ch.joint);
      }
    }
  }
  // The same scene through .kinema comes back exactly (undecoded images left out).
  const std::string saved = kinema::toKinemaJson(kinema::withoutUndecodedImages(a));
  kinema::Result<kinema::Scene> reread = kinema::parseKinemaJson(saved, "fuzz.kinema");
  if (!reread.ok()) {
    std::fprintf(stderr, "%s\n", reread.error().c_str());
    fail(".kinema refused what its writer wrote");
  }
  if (kinema::toKinemaJson(reread.value()) != saved) fail(".kinema round trip is not exact");
  return 0;
}
