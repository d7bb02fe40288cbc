// Fuzzes the BVH writer with whatever the BVH reader accepts: read -> write -> read gives the
// same scene (joints, parents, offsets, frame count and time, every frame's local pose),
// except for what BVH cannot keep and the writer reports (End Sites it adds to plain leaves,
// names it rewrites), and -> .kinema -> read is exact. The input's length picks the Euler
// order (so the seeds stay plain BVH files).
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <unordered_map>

#include "io/bvh.h"
#include "io/bvh_writer.h"
#include "io/kinema_file.h"

namespace {

[[noreturn]] void fail(const char* what, int joint = -1) {
  std::fprintf(stderr, "fuzz_bvh_write: %s (joint %d)\n", what, joint);
  std::abort();
}

// %.6f keeps 5e-7 absolutely; a float read back keeps 6e-8 relatively.
bool near(float a, float b) { return std::abs(a - b) <= 1e-6f + 1e-6f * std::abs(a); }

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, size_t size) {
  const kinema::EulerOrder orders[] = {kinema::EulerOrder::XYZ, kinema::EulerOrder::XZY, kinema::EulerOrder::YXZ,
                                       kinema::EulerOrder::YZX, kinema::EulerOrder::ZXY, kinema::EulerOrder::ZYX};
  kinema::BvhWriteOptions options;
  options.order = orders[size % 6];
  const std::string text(reinterpret_cast<const char*>(data), size);
  kinema::Result<kinema::BvhData> first = kinema::parseBvh(text, "fuzz.bvh");
  if (!first.ok()) return 0;
  const kinema::Skeleton skeleton = first->skeleton();
  const kinema::Clip clip = first->clip();
  if (!clip.validate(skeleton).empty()) return 0;  // frames that share a key time: not a clip to write
  std::vector<std::string> report;
  const kinema::Result<std::string> written = kinema::bvhText(skeleton, &clip, options, &report);
  if (!written.ok()) {
    std::fprintf(stderr, "%s\n", written.error().c_str());
    fail("the writer refused what the reader accepted");
  }
  kinema::Result<kinema::BvhData> second = kinema::parseBvh(written.value(), "fuzz.bvh");
  if (!second.ok()) {
    std::fprintf(stderr, "%s\n", second.error().c_str());
    fail("the reader refused what the writer wrote");
  }
  // A file without frames is written with one (the rest pose).
  if (second->frameCount != std::max(first->frameCount, 1)) fail("frame count changed");
  if (std::abs(second->frameTime - clip.frameTime) > 1e-8 * clip.frameTime) fail("frame time changed");
  const kinema::Skeleton back = second->skeleton();
  for (const std::string& line : report)
    if (line.find("names written as '_'") != std::string::npos) return 0;  // joints renamed: no name match
  std::unordered_map<std::string, int> index;
  for (int j = 0; j < back.size(); ++j) index[back.names[j]] = j;
  std::vector<int> map(skeleton.size(), -1);
  for (int j = 0; j < skeleton.size(); ++j) {
    const auto it = index.find(skeleton.names[j]);
    if (it == index.end()) fail("a joint is missing", j);
    map[j] = it->second;
    const int p = skeleton.parents[j];
    if ((p < 0) != (back.parents[map[j]] < 0) || (p >= 0 && back.parents[map[j]] != map[p])) fail("parent changed", j);
    for (int i = 0; i < 3; ++i)
      if (!near(skeleton.rest[j].translation[i], back.rest[map[j]].translation[i])) fail("offset changed", j);
  }
  // Joints the writer added are End Sites of leaves ("<leaf>_End").
  std::vector<bool> mapped(back.size(), false);
  for (int m : map) mapped[m] = true;
  for (int j = 0; j < back.size(); ++j)
    if (!mapped[j] && (back.parents[j] < 0 || back.names[j] != back.names[back.parents[j]] + "_End"))
      fail("an unexpected joint was added", j);
  for (int f = 0; f < first->frameCount; f += std::max(1, first->frameCount / 8)) {
    const kinema::Pose a = first->framePose(f), b = second->framePose(f);
    for (int j = 0; j < skeleton.size(); ++j) {
      const kinema::Transform& x = a.local[j];
      const kinema::Transform& y = b.local[map[j]];
      for (int i = 0; i < 3; ++i)
        if (!near(x.translation[i], y.translation[i])) fail("a translation changed", j);
      if (std::abs(std::abs(glm::dot(x.rotation, y.rotation)) - 1.0f) > 2e-5f) fail("a rotation changed", j);
    }
  }
  // The same scene through .kinema comes back exactly.
  kinema::Scene scene;
  scene.skeleton = skeleton;
  scene.clips.push_back(clip);
  const std::string saved = kinema::toKinemaJson(scene);
  kinema::Result<kinema::Scene> reread = kinema::parseKinemaJson(saved, "fuzz.kinema");
  if (!reread.ok()) {
    std::fprintf(stderr, "%s\n", reread.error().c_str());
    fail(".kinema refused what its writer wrote");
  }
  if (kinema::toKinemaJson(reread.value()) != saved) fail(".kinema round trip is not exact");
  return 0;
}
