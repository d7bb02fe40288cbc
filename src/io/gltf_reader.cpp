#include "io/gltf_reader.h"

#include <sys/stat.h>
#include <tiny_gltf.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <fstream>
#include <unordered_set>

#include "core/rotation.h"
#include "io/gltf_error_text.h"
#include "io/gltf_external_files.h"
#include "io/gltf_import_parts.h"
#include "io/gltf_limits.h"
#include "io/json_depth.h"
#include "io/json_syntax.h"
#include "io/message_text.h"
#include "io/text_file.h"

namespace kinema {

namespace {

uint32_t readU32(const std::string& b, size_t at) {
  uint32_t v = 0;
  for (int i = 3; i >= 0; --i) v = (v << 8) | static_cast<unsigned char>(b[at + i]);
  return v;
}

// tinygltf hands every image's bytes here while it parses. Images in a bufferView are
// left alone (tinygltf has not checked that view's bounds; we decode them later, after
// our own check); bytes from a URI are kept encoded. Decoding waits until a material needs it.
bool keepEncodedImage(tinygltf::Image* image, const int, std::string*, std::string*, int, int,
                      const unsigned char* bytes, int size, void*) {
  if (image->bufferView >= 0) return true;
  if (bytes && size > 0) image->image.assign(bytes, bytes + size);
  image->width = image->height = -1;
  image->as_is = true;
  return true;
}

std::string directoryOf(const std::string& path) {
  const size_t slash = path.find_last_of('/');
  return slash == std::string::npos ? "." : path.substr(0, slash);
}

// Checks the GLB header and chunk table against the bytes (clear messages for truncated files).
std::string checkGlb(const std::string& bytes, const std::string& file, size_t& jsonOffset, size_t& jsonLength) {
  if (bytes.size() < 20) return file + ": truncated GLB: " + std::to_string(bytes.size()) + " bytes, the header needs 20";
  const uint32_t version = readU32(bytes, 4), length = readU32(bytes, 8);
  if (version != 2) return file + ": GLB version " + std::to_string(version) + " is not 2";
  if (length < 20) return file + ": GLB header length " + std::to_string(length) + " is shorter than the header";
  if (length > bytes.size())
    return file + ": truncated GLB: the header says " + std::to_string(length) + " bytes, the file has " +
           std::to_string(bytes.size());
  const uint32_t chunkLength = readU32(bytes, 12), chunkType = readU32(bytes, 16);
  if (chunkType != 0x4E4F534A) return file + ": GLB: the first chunk is not JSON";
  if (chunkLength > length - 20)
    return file + ": truncated GLB: the JSON chunk says " + std::to_string(chunkLength) + " bytes, " +
           std::to_string(length - 20) + " remain";
  jsonOffset = 20;
  jsonLength = chunkLength;
  return {};
}

glm::vec3 vec3Of(const std::vector<double>& v) { return {float(v[0]), float(v[1]), float(v[2])}; }

bool allFinite(const std::vector<double>& v) {
  for (double x : v)
    if (!std::isfinite(x) || std::abs(x) > 3.0e38) return false;
  return true;
}

// A node's `matrix` as TRS. glTF requires it to be decomposable; shear, projection and
// singular matrices are refused rather than approximated.
std::string decomposeMatrix(const std::vector<double>& m, Transform& out) {
  for (int r = 0; r < 3; ++r)
    if (std::abs(m[r * 4 + 3]) > 1e-6) return "matrix is not affine (its last row is not 0 0 0 1)";
  if (std::abs(m[15] - 1.0) > 1e-6) return "matrix is not affine (its last row is not 0 0 0 1)";
  glm::dvec3 c[3];
  for (int k = 0; k < 3; ++k) c[k] = glm::dvec3(m[k * 4], m[k * 4 + 1], m[k * 4 + 2]);
  glm::dvec3 s(glm::length(c[0]), glm::length(c[1]), glm::length(c[2]));
  const double det = glm::dot(c[0], glm::cross(c[1], c[2]));
  const double largest = std::max(s.x, std::max(s.y, s.z));
  if (!(largest > 0) || std::abs(det) <= 1e-12 * largest * largest * largest || std::min(s.x, std::min(s.y, s.z)) <= 0)
    return "matrix is not invertible (a zero scale cannot be decomposed into a rotation)";
  if (det < 0) s.x = -s.x;  // a mirror: one negative scale
  glm::dmat3 r(c[0] / s.x, c[1] / s.y, c[2] / s.z);
  const glm::dmat3 rtr = glm::transpose(r) * r;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      if (std::abs(rtr[i][j] - (i == j ? 1.0 : 0.0)) > 1e-3) return "matrix has shear (it is not translation * rotation * scale)";
  out.translation = glm::vec3(float(m[12]), float(m[13]), float(m[14]));
  out.rotation = glm::normalize(glm::quat(glm::quat_cast(r)));
  out.scale = glm::vec3(s);
  return {};
}

// The rest transform of node `n` from its TRS properties or matrix.
std::string restTransform(const GltfContext& ctx, int n, const tinygltf::Node& node, Transform& out) {
  const std::string where = "node " + std::to_string(n);
  auto sizeIs = [&](const std::vector<double>& v, size_t want, const char* what) -> std::string {
    if (!v.empty() && v.size() != want)
      return ctx.error(where + ": " + what + " has " + std::to_string(v.size()) + " numbers, expected " +
                       std::to_string(want));
    if (!allFinite(v)) return ctx.error(where + ": " + what + " holds a non-finite number");
    return {};
  };
  if (std::string e = sizeIs(node.translation, 3, "translation"); !e.empty()) return e;
  if (std::string e = sizeIs(node.rotation, 4, "rotation"); !e.empty()) return e;
  if (std::string e = sizeIs(node.scale, 3, "scale"); !e.empty()) return e;
  if (std::string e = sizeIs(node.matrix, 16, "matrix"); !e.empty()) return e;
  out = Transform::identity();
  if (!node.matrix.empty()) {
    if (!node.translation.empty() || !node.rotation.empty() || !node.scale.empty())
      return ctx.error(where + ": has both a matrix and translation/rotation/scale");
    if (std::string e = decomposeMatrix(node.matrix, out); !e.empty()) return ctx.error(where + ": " + e);
    return {};
  }
  if (!node.translation.empty()) out.translation = vec3Of(node.translation);
  if (!node.scale.empty()) out.scale = vec3Of(node.scale);
  if (!node.rotation.empty()) {
    const glm::quat q(float(node.rotation[3]), float(node.rotation[0]), float(node.rotation[1]), float(node.rotation[2]));
    if (!isFinite(q)) return ctx.error(where + ": rotation does not fit in float");
    if (q == glm::quat(0.0f, 0.0f, 0.0f, 0.0f)) return ctx.error(where + ": rotation is a zero quaternion");
    out.rotation = safeNormalize(q);  // huge or tiny components normalise too (a plain length overflows)
  }
  return {};
}

// Nodes → skeleton: one joint per node, parents before children, names made unique.
std::string importNodes(GltfContext& ctx, Scene& scene, std::vector<int>& jointOfNode) {
  const std::vector<tinygltf::Node>& nodes = ctx.model.nodes;
  const int n = static_cast<int>(nodes.size());
  std::vector<int> parent(n, -1);
  for (int i = 0; i < n; ++i)
    for (int c : nodes[i].children) {
      if (c < 0 || c >= n)
        return ctx.error("node " + std::to_string(i) + ": child " + std::to_string(c) + " does not exist (the file has " +
                         std::to_string(n) + " nodes)");
      if (c == i) return ctx.error("node " + std::to_string(i) + " is its own child (a cycle)");
      if (parent[c] != -1)
        return ctx.error("node " + std::to_string(c) + " has two parents (nodes " + std::to_string(parent[c]) + " and " +
                         std::to_string(i) + ")");
      parent[c] = i;
    }
  // With one parent each, a node is in a cycle exactly when walking up never reaches a
  // root. Emit ancestors first, walking up iteratively (depth is file-controlled).
  jointOfNode.assign(n, -1);
  std::vector<int> chain;
  std::vector<char> onChain(n, 0);
  for (int i = 0; i < n; ++i) {
    chain.clear();
    for (int a = i; a != -1 && jointOfNode[a] == -1; a = parent[a]) {
      if (onChain[a]) return ctx.error("node " + std::to_string(a) + " is its own ancestor (the node graph has a cycle)");
      onChain[a] = 1;
      chain.push_back(a);
    }
    for (auto it = chain.rbegin(); it != chain.rend(); ++it) {
      const int node = *it;
      jointOfNode[node] = static_cast<int>(scene.nodeOfJoint.size());
      scene.nodeOfJoint.push_back(node);
    }
  }
  scene.nodeNames.resize(n);
  std::unordered_set<std::string> used;
  for (const tinygltf::Node& node : nodes)
    if (!node.name.empty()) used.insert(node.name);
  std::unordered_set<std::string> taken;
  for (int j = 0; j < n; ++j) {
    const int i = scene.nodeOfJoint[j];
    const tinygltf::Node& node = nodes[i];
    Transform rest;
    if (std::string e = restTransform(ctx, i, node, rest); !e.empty()) return e;
    scene.nodeNames[i] = node.name;
    std::string name = node.name.empty() ? "node_" + std::to_string(i) : node.name;
    if (taken.count(name) || (node.name.empty() && used.count(name))) {
      const std::string base = name + "_node" + std::to_string(i);
      name = base;
      for (int k = 2; taken.count(name) || used.count(name); ++k) name = base + "_" + std::to_string(k);
    }
    taken.insert(name);
    const int p = parent[i] == -1 ? -1 : jointOfNode[parent[i]];
    scene.skeleton.addJoint(name, p, rest);
    if (node.camera >= 0) ctx.warn("cameras are not kept (node " + std::to_string(i) + ")");
    if (node.extensions.count("KHR_lights_punctual")) ctx.warn("lights are not kept (node " + std::to_string(i) + ")");
  }
  return {};
}

std::string importSkins(GltfContext& ctx, const std::vector<int>& jointOfNode, Scene& scene) {
  const int nodes = static_cast<int>(jointOfNode.size());
  for (size_t s = 0; s < ctx.model.skins.size(); ++s) {
    const tinygltf::Skin& in = ctx.model.skins[s];
    const std::string where = "skin " + std::to_string(s);
    if (in.joints.empty()) return ctx.error(where + ": has no joints");
    if (in.joints.size() > GltfLimits::kMaxSkinJoints)
      return ctx.error(where + ": " + std::to_string(in.joints.size()) + " joints exceed the limit of " +
                       std::to_string(GltfLimits::kMaxSkinJoints));
    Skin skin;
    skin.name = in.name;
    for (size_t k = 0; k < in.joints.size(); ++k) {
      const int node = in.joints[k];
      if (node < 0 || node >= nodes)
        return ctx.error(where + ": joint " + std::to_string(k) + " is node " + std::to_string(node) +
                         ", which does not exist");
      skin.joints.push_back(jointOfNode[node]);
    }
    if (in.skeleton >= nodes || in.skeleton < -1)
      return ctx.error(where + ": skeleton node " + std::to_string(in.skeleton) + " does not exist");
    skin.skeletonRoot = in.skeleton < 0 ? -1 : jointOfNode[in.skeleton];
    skin.inverseBind.assign(in.joints.size(), glm::mat4(1.0f));
    if (in.inverseBindMatrices >= 0) {
      const std::string use = where + " inverseBindMatrices";
      if (accessorCount(ctx, in.inverseBindMatrices) < in.joints.size() && accessorCount(ctx, in.inverseBindMatrices) > 0)
        return ctx.error(use + " accessor " + std::to_string(in.inverseBindMatrices) + ": " +
                         std::to_string(accessorCount(ctx, in.inverseBindMatrices)) + " matrices for " +
                         std::to_string(in.joints.size()) + " joints");
      std::vector<float> m;
      if (std::string e = readFloatAccessor(ctx, in.inverseBindMatrices, 16, kCompFloat, use, m); !e.empty()) return e;
      for (size_t k = 0; k < in.joints.size(); ++k) std::memcpy(&skin.inverseBind[k][0][0], &m[k * 16], 16 * sizeof(float));
    }
    scene.skins.push_back(std::move(skin));
  }
  return {};
}

}  // namespace

Result<Scene> parseGltf(const std::string& bytes, const std::string& path, const InputLimits& limits) {
  using R = Result<Scene>;
  if (bytes.size() > GltfLimits::kMaxFileBytes)
    return R::failure(path + ": " + std::to_string(bytes.size()) + " bytes exceed the limit of " +
                      std::to_string(GltfLimits::kMaxFileBytes));
  const bool binary = bytes.size() >= 4 && std::memcmp(bytes.data(), "glTF", 4) == 0;
  size_t jsonOffset = 0, jsonLength = bytes.size();
  if (binary)
    if (std::string e = checkGlb(bytes, path, jsonOffset, jsonLength); !e.empty()) return R::failure(e);
  // tinygltf turns `extras` into Values recursively: cap the depth before it parses.
  if (jsonNestingDepth(bytes.data() + jsonOffset, jsonLength) > GltfLimits::kMaxJsonDepth)
    return R::failure(path + ": JSON nested deeper than " + std::to_string(GltfLimits::kMaxJsonDepth) + " levels");

  tinygltf::Model model;
  tinygltf::TinyGLTF loader;
  loader.SetImageLoader(keepEncodedImage, nullptr);
  std::string err, warn;
  const std::string dir = directoryOf(path);
  GltfExternalFiles files;
  files.folder = dir;
  files.allowOutside = limits.allowOutsidePaths;
  files.maxBytes = std::min(GltfLimits::kMaxFileBytes, limits.maxFileBytes);
  files.install(loader);
  const bool ok =
      binary ? loader.LoadBinaryFromMemory(&model, &err, &warn, reinterpret_cast<const unsigned char*>(bytes.data()),
                                           static_cast<unsigned>(bytes.size()), dir)
             : loader.LoadASCIIFromString(&model, &err, &warn, bytes.data(), static_cast<unsigned>(bytes.size()), dir);
  GltfErrorText errorText;
  errorText.json = bytes.data() + jsonOffset;
  errorText.jsonLength = jsonLength;
  errorText.treeBudget = jsonTreeBudgetBytes(jsonLength, limits);
  errorText.files = &files;
  if (!ok) {
    // tinygltf passes on its JSON library's exception text; say in plain words what is wrong.
    const std::string syntax = jsonSyntaxError(bytes.data() + jsonOffset, jsonLength);
    if (!syntax.empty()) {
      const size_t first = bytes.find_first_not_of(" \t\r\n");
      if (!binary && (first == std::string::npos || bytes[first] != '{'))
        return R::failure(path + ": not a glTF file: neither binary glTF (which starts with \"glTF\") nor glTF JSON text");
      return R::failure(oneLineMessage(path + ": the glTF JSON is malformed at " + syntax));
    }
    if (err.empty()) return R::failure(path + ": not a glTF 2.0 file");
    return R::failure(oneLineMessage(path + ": " + errorText.error(err)));
  }

  GltfContext ctx{model, path, 0, {}};
  ctx.imageBytesLeft = imageBudgetBytes(bytes.size() + files.bytesRead, limits);
  ctx.imageBytesOverFileSize = limits.imageBytesOverFileSize;
  for (const std::string& w : errorText.warnings(warn)) ctx.warn(oneLineMessage(w));
  for (const std::string& ext : model.extensionsRequired) {
    if (ext == "KHR_draco_mesh_compression" || ext == "EXT_meshopt_compression")
      return R::failure(ctx.error("requires " + ext + " (compressed geometry), which Kinema does not read"));
    if (ext != "KHR_mesh_quantization") ctx.warn("requires " + ext + ", which Kinema does not read: it may look different");
  }
  if (model.nodes.size() > GltfLimits::kMaxNodes)
    return R::failure(ctx.error(std::to_string(model.nodes.size()) + " nodes exceed the limit of " +
                                std::to_string(GltfLimits::kMaxNodes)));
  Scene scene;
  scene.source = path;
  std::vector<int> jointOfNode;
  if (std::string e = importNodes(ctx, scene, jointOfNode); !e.empty()) return R::failure(e);
  if (std::string e = importSkins(ctx, jointOfNode, scene); !e.empty()) return R::failure(e);
  if (std::string e = importMaterials(ctx, scene); !e.empty()) return R::failure(e);
  if (std::string e = importMeshes(ctx, jointOfNode, scene); !e.empty()) return R::failure(e);
  // The document's frame rate, where Kinema wrote it (asset.extras.kinema_frame_rate).
  const bool writtenByKinema = model.asset.extras.IsObject() && model.asset.extras.Has("kinema_frame_rate");
  if (writtenByKinema) {
    const tinygltf::Value& v = model.asset.extras.Get("kinema_frame_rate");
    const double rate = v.IsNumber() ? v.GetNumberAsDouble() : 0.0;
    if (rate >= kMinFrameRate && rate <= kMaxFrameRate) scene.frameRate = rate;
    else ctx.warn("asset.extras.kinema_frame_rate is not a frame rate of 1 to 1000 fps: ignored");
  }
  if (std::string e = importAnimations(ctx, jointOfNode, scene, writtenByKinema); !e.empty()) return R::failure(e);
  if (!model.cameras.empty()) ctx.warn("cameras are not kept");
  // Guards: the pieces above only build valid skeletons and clips.
  if (std::string e = scene.skeleton.validate(); !e.empty()) return R::failure(ctx.error(e));
  for (size_t c = 0; c < scene.clips.size(); ++c)
    if (std::string e = scene.clips[c].validate(scene.skeleton); !e.empty())
      return R::failure(ctx.error("animation " + std::to_string(c) + ": " + e));
  scene.warnings = std::move(ctx.warnings);
  return scene;
}

Result<Scene> loadGltf(const std::string& path, const InputLimits& limits) {
  std::string bytes;  // readTextFile reads bytes as they are and stops at the cap
  if (std::string e = readTextFile(path, bytes, std::min(GltfLimits::kMaxFileBytes, limits.maxFileBytes)); !e.empty())
    return Result<Scene>::failure(e);
  return parseGltf(bytes, path, limits);
}

}  // namespace kinema
