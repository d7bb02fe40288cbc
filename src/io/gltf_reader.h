#pragma once
#include <string>

#include "core/result.h"
#include "io/input_limits.h"
#include "scene/scene.h"

namespace kinema {

// glTF 2.0 (.gltf with its buffers and images, or .glb) → Scene. Every node becomes a
// joint (the skeleton sorted parent-first, nodeOfJoint mapping back to node indices);
// skins, meshes, morph targets, base-colour materials and every animation (as clips) are
// kept; what cannot be kept is listed in Scene::warnings. The file is validated before
// any of its data is trusted: a problem is one line naming the file and the accessor,
// node, mesh, skin or animation index.
// `limits`: the file size cap (the smaller of it and GltfLimits::kMaxFileBytes), the image
// memory budget and whether uris may leave the file's folder (allowOutsidePaths).
Result<Scene> loadGltf(const std::string& path, const InputLimits& limits = {});

// The same from bytes already in memory (`path` names them in messages; external buffers
// and images are looked up beside it). Binary when the bytes start with the GLB magic.
Result<Scene> parseGltf(const std::string& bytes, const std::string& path, const InputLimits& limits = {});

}  // namespace kinema
