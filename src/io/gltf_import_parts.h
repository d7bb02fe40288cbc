#pragma once
// The pieces of glTF import (gltf_reader.cpp calls them in order). Each returns "" or a
// one-line error from GltfContext::error.
#include <string>
#include <vector>

#include "io/gltf_accessor.h"
#include "scene/scene.h"

namespace kinema {

// Images (decoded only when a material uses them as base colour) and materials.
std::string importMaterials(GltfContext& ctx, Scene& scene);

// Meshes, and one MeshInstance per node that shows one. Needs the skins (joint counts).
std::string importMeshes(GltfContext& ctx, const std::vector<int>& jointOfNode, Scene& scene);

// Every animation as a Clip; morph-weight channels become Scalar "weights/K" channels. Each
// clip's rate: extras.kinema_frame_time where Kinema wrote it; in a foreign file (not
// `writtenByKinema`) the grid its keys lie on (keyGridFrameTime); else none (the document's).
std::string importAnimations(GltfContext& ctx, const std::vector<int>& jointOfNode, Scene& scene,
                             bool writtenByKinema);

// Bytes [data, data + length) of bufferView `view` after checking it lies in its buffer.
std::string bufferViewBytes(const GltfContext& ctx, int view, const std::string& use, const unsigned char*& data,
                            size_t& length);

}  // namespace kinema
