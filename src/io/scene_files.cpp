#include "io/scene_files.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>

#include "io/bvh.h"
#include "io/bvh_writer.h"
#include "io/gltf_reader.h"
#include "io/gltf_writer.h"
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
                               " s is too small to tell frames apart: read as 1/24 s (the default frame rate)");
    }
    return scene;
  }
  if (ext == ".kinema") return loadKinemaFile(path, limits);
  if (ext == ".gltf" || ext == ".glb") return loadGltf(path, limits);  // its own caps too: io/gltf_limits.h
  return Result<Scene>::failure(path + ": unsupported file type '" + ext +
                                "' (Kinema reads .bvh, .kinema, .gltf and .glb)");
}

bool canSaveScene(const std::string& path) {
  const std::string ext = lowerExtension(path);
  return ext == ".bvh" || ext == ".gltf" || ext == ".glb" || ext == ".kinema";
}

namespace {

// What BVH (a skeleton and one motion) cannot hold of the scene, one line each.
void bvhLosses(const Scene& scene, int clip, std::vector<std::string>& lost) {
  if (!scene.meshes.empty())
    lost.push_back(std::to_string(scene.meshes.size()) + " mesh(es), their skins and materials dropped (BVH holds a skeleton and one motion)");
  if (scene.clips.size() > 1)
    lost.push_back("only clip " + std::to_string(clip) + " ('" + scene.clips[clip].name + "') written; " +
                   std::to_string(scene.clips.size() - 1) + " more dropped (BVH holds one motion)");
  if (!scene.ik.empty()) lost.push_back("IK limits and targets dropped (BVH has no place for them)");
}

}  // namespace

std::string saveScene(const std::string& path, const Scene& scene, const SceneSaveOptions& options,
                      std::vector<std::string>* report) {
  const std::string ext = lowerExtension(path);
  if (!canSaveScene(path))
    return path + ": cannot write '" + ext + "' files (Kinema writes .bvh, .gltf, .glb and .kinema)";
  if (!std::isfinite(options.frameRate) || options.frameRate < 0.0)
    return path + ": the frame rate must be a positive number of frames per second";
  std::vector<std::string> lines;
  std::string error;
  if (ext == ".bvh") {
    const int clip = options.bvhClip >= 0 && options.bvhClip < static_cast<int>(scene.clips.size()) ? options.bvhClip : 0;
    bvhLosses(scene, clip, lines);
    BvhWriteOptions bvh;
    bvh.order = options.bvhRotationOrder;
    bvh.frameRate = options.frameRate;
    bvh.documentFrameRate = scene.frameRate;
    bvh.progress = options.progress;
    bvh.scene = &scene;
    bvh.clipIndex = clip;
    bvh.stages = options.bvhStages;
    error = saveBvh(path, scene.skeleton, scene.clips.empty() ? nullptr : &scene.clips[clip], bvh, &lines);
  } else if (ext == ".gltf" || ext == ".glb") {
    GltfWriteOptions gltf;
    gltf.binary = ext == ".glb";
    gltf.resampleRate = options.frameRate;
    error = saveGltf(path, scene, gltf, &lines);
  } else {
    error = saveKinemaFile(path, scene);
  }
  if (report) report->insert(report->end(), lines.begin(), lines.end());
  return error;
}

}  // namespace kinema
