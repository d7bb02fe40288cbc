#pragma once
#include <string>
#include <vector>

#include "core/result.h"
#include "scene/scene.h"

namespace kinema {

struct GltfWriteOptions {
  bool binary = false;  // .glb; otherwise .gltf JSON with the buffer embedded as a data URI
  // Samples per second for curves glTF cannot express exactly; 0: each clip's frame rate,
  // or the document's (Scene::frameRate) when it has none.
  double resampleRate = 0.0;
};

// Scene -> glTF 2.0. One node per joint, in the file's node order when the scene came
// from glTF (nodeOfJoint), names and rest TRS kept; skins, meshes (every attribute, up to
// two JOINTS/WEIGHTS sets), morph targets, base-colour materials and PNG textures, and one
// animation per clip (gltf_curves.h). `report` receives one line for everything that could
// not be carried exactly (resampled curves with their error, dropped channels).
Result<std::string> gltfBytes(const Scene& scene, const GltfWriteOptions& options,
                              std::vector<std::string>* report = nullptr);
// Writes the file atomically (temporary file + rename). Returns "" or the one-line error.
std::string saveGltf(const std::string& path, const Scene& scene, const GltfWriteOptions& options,
                     std::vector<std::string>* report = nullptr);

}  // namespace kinema
