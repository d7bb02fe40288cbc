#include "io/scene.h"

#include <algorithm>
#include <cctype>

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
    return scene;
  }
  if (ext == ".kinema") return loadKinemaFile(path, limits);
  if (ext == ".gltf" || ext == ".glb") return loadGltf(path);  // its caps: io/gltf_limits.h
  return Result<Scene>::failure(path + ": unsupported file type '" + ext +
                                "' (Kinema reads .bvh, .kinema, .gltf and .glb)");
}

}  // namespace kinema
