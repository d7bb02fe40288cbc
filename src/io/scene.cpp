#include "io/scene.h"

#include <algorithm>
#include <cctype>
#include <cstdio>

#include "io/bvh.h"
#include "io/gltf_reader.h"
#include "io/kinema_file.h"

namespace kinema {

std::string lowerExtension(const std::string& path) {
  const size_t slash = path.find_last_of('/');
  const size_t dot = path.find_last_of('.');
  if (dot == std::string::npos || (slash != std::string::npos && dot < slash)) return {};
  std::string ext = path.substr(dot);
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
  return ext;
}

Result<Scene> loadScene(const std::string& path, const InputLimits& limits) { return loadScene(path, limits, UpAxis::Y); }

Result<Scene> loadScene(const std::string& path, const InputLimits& limits, UpAxis bvhUp) {
  const std::string ext = lowerExtension(path);
  if (ext == ".bvh") {
    Result<BvhData> bvh = loadBvh(path, limits);
    if (!bvh) return Result<Scene>::failure(bvh.error());
    if (bvhUp == UpAxis::Z) convertZUpToYUp(bvh.value());
    Scene scene;
    scene.source = path;
    scene.skeleton = bvh->skeleton();
    scene.clips.push_back(bvh->clip());
    if (bvh->keyFrameTime() != bvh->frameTime) {
      char seconds[32];
      std::snprintf(seconds, sizeof seconds, "%.3g", bvh->frameTime);
      scene.warnings.push_back(std::string("Frame Time ") + seconds +
                               " s is too small to tell frames apart: read as 1/30 s");
    }
    return scene;
  }
  if (ext == ".kinema") return loadKinemaFile(path, limits);
  if (ext == ".gltf" || ext == ".glb") return loadGltf(path, limits);  // its own caps too: io/gltf_limits.h
  return Result<Scene>::failure(path + ": unsupported file type '" + ext +
                                "' (Kinema reads .bvh, .kinema, .gltf and .glb)");
}

bool hasUndecodedImages(const Scene& scene) {
  return std::any_of(scene.images.begin(), scene.images.end(), isUndecodedImage);
}

Scene withoutUndecodedImages(const Scene& scene, std::vector<int>* dropped) {
  Scene out = scene;
  std::vector<int> newIndex(scene.images.size(), -1);
  out.images.clear();
  for (size_t i = 0; i < scene.images.size(); ++i) {
    if (isUndecodedImage(scene.images[i])) {
      if (dropped) dropped->push_back(static_cast<int>(i));
      continue;
    }
    newIndex[i] = static_cast<int>(out.images.size());
    out.images.push_back(scene.images[i]);
  }
  for (Material& m : out.materials)
    if (m.baseColorImage >= 0 && m.baseColorImage < static_cast<int>(newIndex.size()))
      m.baseColorImage = newIndex[m.baseColorImage];
  return out;
}

}  // namespace kinema
