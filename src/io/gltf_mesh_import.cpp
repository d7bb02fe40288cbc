// glTF meshes, materials and base-colour images → Scene (see gltf_import_parts.h).
#include <stb_image.h>
#include <tiny_gltf.h>

#include <algorithm>
#include <cmath>
#include <cstdint>

#include "io/gltf_import_parts.h"
#include "io/gltf_limits.h"

namespace kinema {

namespace {

// A JSON number that converts to a finite float (casting one beyond float range is undefined).
bool finiteFloat(double x) { return std::isfinite(x) && std::abs(x) <= 3.0e38; }

std::string decodeImage(GltfContext& ctx, int index, size_t& pixelBudget, TextureImage& out) {
  const tinygltf::Image& in = ctx.model.images[index];
  const std::string where = "image " + std::to_string(index);
  const unsigned char* data = nullptr;
  size_t length = 0;
  if (in.bufferView >= 0) {
    if (std::string e = bufferViewBytes(ctx, in.bufferView, where, data, length); !e.empty()) return e;
  } else {
    data = in.image.data();
    length = in.image.size();
  }
  if (!data || length == 0 || length > static_cast<size_t>(INT32_MAX)) {
    ctx.warn(where + " (" + cutForMessage(in.uri) + ") could not be read: shown without its texture");
    return {};
  }
  int w = 0, h = 0, channels = 0;
  if (!stbi_info_from_memory(data, static_cast<int>(length), &w, &h, &channels)) {
    ctx.warn(where + " is not an image stb can decode (" + stbi_failure_reason() + "): shown without its texture");
    return {};
  }
  if (w <= 0 || h <= 0 || w > GltfLimits::kMaxImageSide || h > GltfLimits::kMaxImageSide ||
      static_cast<size_t>(w) * h > pixelBudget)
    return ctx.error(where + ": " + std::to_string(w) + "x" + std::to_string(h) + " pixels exceed the limit of " +
                     std::to_string(GltfLimits::kMaxImageSide) + " a side or " +
                     std::to_string(GltfLimits::kMaxImagePixels) + " pixels in all");
  // Memory follows the input: the header's size is checked before decoding.
  const size_t decodedBytes = static_cast<size_t>(w) * static_cast<size_t>(h) * 4;
  if (decodedBytes > ctx.imageBytesLeft) {
    ctx.warn(where + ": " + std::to_string(w) + "x" + std::to_string(h) + " pixels would take the file's decoded images "
             "past the limit of its size + " + std::to_string(ctx.imageBytesOverFileSize >> 20) +
             " MB (InputLimits::imageBytesOverFileSize): shown without its texture");
    return {};
  }
  unsigned char* pixels = stbi_load_from_memory(data, static_cast<int>(length), &w, &h, &channels, 4);
  if (!pixels) {
    ctx.warn(where + " could not be decoded (" + stbi_failure_reason() + "): shown without its texture");
    return {};
  }
  pixelBudget -= static_cast<size_t>(w) * h;
  ctx.imageBytesLeft -= decodedBytes;
  out.width = w;
  out.height = h;
  out.rgba.assign(pixels, pixels + static_cast<size_t>(w) * h * 4);
  stbi_image_free(pixels);
  return {};
}

// A vertex whose kept weights sum further than this from 1 is counted in the load report
// (every vertex is renormalised; float rounding alone stays far below it).
constexpr double kWeightSumTolerance = 1e-3;

// Per-vertex influences from every JOINTS_n / WEIGHTS_n pair: the largest kMaxInfluences
// kept, largest first, renormalised to sum 1. `maxJoint` gets the largest joint used.
std::string readInfluences(GltfContext& ctx, const tinygltf::Primitive& p, const std::string& where, size_t vertices,
                           MeshPrimitive& out, int& maxJoint) {
  std::vector<std::vector<uint32_t>> joints;
  std::vector<std::vector<float>> weights;
  for (int set = 0;; ++set) {
    const std::string js = "JOINTS_" + std::to_string(set), ws = "WEIGHTS_" + std::to_string(set);
    const auto j = p.attributes.find(js), w = p.attributes.find(ws);
    if (j == p.attributes.end() && w == p.attributes.end()) break;
    if (j == p.attributes.end() || w == p.attributes.end())
      return ctx.error(where + ": " + (j == p.attributes.end() ? ws + " without " + js : js + " without " + ws));
    joints.emplace_back();
    weights.emplace_back();
    if (std::string e = readUintAccessor(ctx, j->second, 4, kCompUByte | kCompUShort, where + " " + js, joints.back());
        !e.empty())
      return e;
    if (std::string e =
            readFloatAccessor(ctx, w->second, 4, kCompFloat | kCompUByte | kCompUShort, where + " " + ws, weights.back());
        !e.empty())
      return e;
    if (joints.back().size() != vertices * 4 || weights.back().size() != vertices * 4)
      return ctx.error(where + ": " + js + " / " + ws + " counts differ from POSITION's " + std::to_string(vertices));
  }
  if (joints.empty()) return {};
  out.influenceJoints.assign(vertices * kMaxInfluences, 0);
  out.influenceWeights.assign(vertices * kMaxInfluences, 0.0f);
  std::vector<std::pair<float, uint32_t>> all;
  bool zeroWeights = false;
  size_t renormalised = 0;  // vertices whose kept weights summed to 1 +- more than 1e-3
  for (size_t v = 0; v < vertices; ++v) {
    all.clear();
    for (size_t s = 0; s < joints.size(); ++s)
      for (int k = 0; k < 4; ++k) {
        const float w = weights[s][v * 4 + k];
        if (w < 0) return ctx.error(where + " WEIGHTS_" + std::to_string(s) + ": vertex " + std::to_string(v) + " has a negative weight");
        if (w > 0) all.emplace_back(w, joints[s][v * 4 + k]);
      }
    // Largest weight first; equal weights keep the lower joint first (deterministic).
    std::sort(all.begin(), all.end(), [](const auto& a, const auto& b) {
      return a.first != b.first ? a.first > b.first : a.second < b.second;
    });
    if (all.size() > static_cast<size_t>(kMaxInfluences)) all.resize(kMaxInfluences);
    if (all.empty()) {  // glTF forbids it; bind such a vertex rigidly to its first joint
      zeroWeights = true;
      all.emplace_back(1.0f, joints[0][v * 4]);
    }
    double sum = 0;  // double: weights near FLT_MAX must not sum to infinity
    for (const auto& a : all) sum += a.first;
    if (std::abs(sum - 1.0) > kWeightSumTolerance) ++renormalised;
    for (size_t k = 0; k < all.size(); ++k) {
      const float w = static_cast<float>(all[k].first / sum);
      // A weight the division took to zero sits on joint 0, as core/mesh.h promises and the
      // .kinema reader makes it (the fuzzer found the two disagreeing on a 1e-43 weight).
      if (w == 0.0f) continue;
      out.influenceJoints[v * kMaxInfluences + k] = static_cast<uint16_t>(all[k].second);
      out.influenceWeights[v * kMaxInfluences + k] = w;
      maxJoint = std::max(maxJoint, static_cast<int>(all[k].second));
    }
  }
  if (zeroWeights) ctx.warn(where + ": vertices whose weights are all zero follow their first joint");
  if (renormalised)
    ctx.warn(where + ": " + std::to_string(renormalised) + " of " + std::to_string(vertices) +
             " vertices had skin weights not summing to 1 (beyond 1e-3); renormalised");
  return {};
}

std::vector<glm::vec3> toVec3(const std::vector<float>& f) {
  std::vector<glm::vec3> v(f.size() / 3);
  for (size_t i = 0; i < v.size(); ++i) v[i] = glm::vec3(f[3 * i], f[3 * i + 1], f[3 * i + 2]);
  return v;
}

// Triangle list indices for a primitive (strips and fans expanded as glTF defines them).
std::string readTriangles(GltfContext& ctx, const tinygltf::Primitive& p, const std::string& where, size_t vertices,
                          std::vector<uint32_t>& out) {
  std::vector<uint32_t> idx;
  if (p.indices >= 0) {
    if (std::string e = readUintAccessor(ctx, p.indices, 1, kCompUByte | kCompUShort | kCompUInt, where + " indices", idx);
        !e.empty())
      return e;
    for (size_t i = 0; i < idx.size(); ++i)
      if (idx[i] >= vertices)
        return ctx.error(where + " indices accessor " + std::to_string(p.indices) + ": index " + std::to_string(idx[i]) +
                         " at " + std::to_string(i) + " is past the " + std::to_string(vertices) + " vertices");
  } else {
    idx.resize(vertices);
    for (size_t i = 0; i < vertices; ++i) idx[i] = static_cast<uint32_t>(i);
  }
  const int mode = p.mode < 0 ? TINYGLTF_MODE_TRIANGLES : p.mode;
  out.clear();
  if (mode == TINYGLTF_MODE_TRIANGLES) {
    if (idx.size() % 3) ctx.warn(where + ": " + std::to_string(idx.size() % 3) + " indices after the last whole triangle ignored");
    idx.resize(idx.size() - idx.size() % 3);
    out = std::move(idx);
  } else if (mode == TINYGLTF_MODE_POINTS) {
    // Vertices without faces (lines are dropped before this; see importMeshes).
  } else if (idx.size() >= 3) {
    out.reserve((idx.size() - 2) * 3);
    for (size_t i = 0; i + 2 < idx.size(); ++i) {
      if (mode == TINYGLTF_MODE_TRIANGLE_STRIP) {  // {v_i, v_(i+1+i%2), v_(i+2-i%2)}
        out.insert(out.end(), {idx[i], idx[i + 1 + i % 2], idx[i + 2 - i % 2]});
      } else {  // fan: {v_(i+1), v_(i+2), v_0}
        out.insert(out.end(), {idx[i + 1], idx[i + 2], idx[0]});
      }
    }
  }
  return {};
}

std::string readPrimitive(GltfContext& ctx, const tinygltf::Primitive& p, const std::string& where,
                          MeshPrimitive& out, int& maxJoint) {
  const auto pos = p.attributes.find("POSITION");
  const size_t n = accessorCount(ctx, pos->second);
  std::vector<float> f;
  // Integer positions are KHR_mesh_quantization's (normalised or not).
  const unsigned any = kCompFloat | kCompByte | kCompUByte | kCompShort | kCompUShort;
  if (std::string e = readFloatAccessor(ctx, pos->second, 3, any, where + " POSITION", f); !e.empty()) return e;
  out.positions = toVec3(f);
  for (const auto& [name, accessor] : p.attributes) {
    if (accessorCount(ctx, accessor) != n && accessor >= 0 && static_cast<size_t>(accessor) < ctx.model.accessors.size())
      return ctx.error(where + " " + name + " accessor " + std::to_string(accessor) + ": " +
                       std::to_string(accessorCount(ctx, accessor)) + " elements, POSITION has " + std::to_string(n));
    const bool known = name == "POSITION" || name == "NORMAL" || name == "TEXCOORD_0" ||
                       name.rfind("JOINTS_", 0) == 0 || name.rfind("WEIGHTS_", 0) == 0;
    if (!known) ctx.warn("vertex attribute " + name + " is not kept (" + where + ")");
  }
  if (const auto it = p.attributes.find("NORMAL"); it != p.attributes.end()) {
    if (std::string e = readFloatAccessor(ctx, it->second, 3, kCompFloat | kCompByte | kCompShort, where + " NORMAL", f);
        !e.empty())
      return e;
    out.normals = toVec3(f);
  }
  if (const auto it = p.attributes.find("TEXCOORD_0"); it != p.attributes.end()) {
    if (std::string e = readFloatAccessor(ctx, it->second, 2, kCompFloat | kCompUByte | kCompUShort | kCompByte | kCompShort,
                                          where + " TEXCOORD_0", f);
        !e.empty())
      return e;
    out.texcoords.resize(n);
    for (size_t i = 0; i < n; ++i) out.texcoords[i] = glm::vec2(f[2 * i], f[2 * i + 1]);
  }
  if (std::string e = readInfluences(ctx, p, where, n, out, maxJoint); !e.empty()) return e;
  if (std::string e = readTriangles(ctx, p, where, n, out.indices); !e.empty()) return e;
  if (p.targets.size() > GltfLimits::kMaxMorphTargets)
    return ctx.error(where + ": " + std::to_string(p.targets.size()) + " morph targets exceed the limit of " +
                     std::to_string(GltfLimits::kMaxMorphTargets));
  for (size_t t = 0; t < p.targets.size(); ++t) {
    MorphTarget target;
    const std::string tw = where + " target " + std::to_string(t);
    for (const auto& [name, accessor] : p.targets[t]) {
      if (name != "POSITION" && name != "NORMAL") {
        ctx.warn("morph target attribute " + name + " is not kept (" + where + ")");
        continue;
      }
      if (accessorCount(ctx, accessor) != n && accessorCount(ctx, accessor) != 0)
        return ctx.error(tw + " " + name + " accessor " + std::to_string(accessor) + ": " +
                         std::to_string(accessorCount(ctx, accessor)) + " elements, POSITION has " + std::to_string(n));
      if (std::string e = readFloatAccessor(ctx, accessor, 3, kCompFloat | kCompByte | kCompShort, tw + " " + name, f);
          !e.empty())
        return e;
      (name == "POSITION" ? target.positionDeltas : target.normalDeltas) = toVec3(f);
    }
    if (target.positionDeltas.empty()) target.positionDeltas.assign(n, glm::vec3(0.0f));
    out.targets.push_back(std::move(target));
  }
  out.material = p.material;
  return {};
}

std::vector<std::string> targetNamesOf(const tinygltf::Mesh& mesh) {
  std::vector<std::string> names;
  if (!mesh.extras.IsObject() || !mesh.extras.Has("targetNames")) return names;
  const tinygltf::Value& list = mesh.extras.Get("targetNames");
  if (!list.IsArray()) return names;
  for (size_t i = 0; i < list.ArrayLen(); ++i)
    names.push_back(list.Get(static_cast<int>(i)).IsString() ? list.Get(static_cast<int>(i)).Get<std::string>() : "");
  return names;
}

}  // namespace

std::string importMaterials(GltfContext& ctx, Scene& scene) {
  const tinygltf::Model& m = ctx.model;
  scene.images.resize(m.images.size());
  std::vector<char> needed(m.images.size(), 0);
  for (size_t i = 0; i < m.materials.size(); ++i) {
    const tinygltf::Material& in = m.materials[i];
    const std::string where = "material " + std::to_string(i);
    Material mat;
    mat.name = in.name;
    mat.doubleSided = in.doubleSided;
    const std::vector<double>& f = in.pbrMetallicRoughness.baseColorFactor;
    if (f.size() != 4) return ctx.error(where + ": baseColorFactor needs 4 numbers");
    for (int k = 0; k < 4; ++k) {
      if (!finiteFloat(f[k])) return ctx.error(where + ": baseColorFactor holds a non-finite number");
      mat.baseColor[k] = static_cast<float>(f[k]);
    }
    const int tex = in.pbrMetallicRoughness.baseColorTexture.index;
    if (tex >= 0) {
      if (static_cast<size_t>(tex) >= m.textures.size())
        return ctx.error(where + ": baseColorTexture " + std::to_string(tex) + " does not exist");
      const int source = m.textures[tex].source;
      if (source >= static_cast<int>(m.images.size()))
        return ctx.error("texture " + std::to_string(tex) + ": image " + std::to_string(source) + " does not exist");
      if (source < 0) ctx.warn("texture " + std::to_string(tex) + " has no image tinygltf can read (extension): not shown");
      else {
        mat.baseColorImage = source;
        needed[source] = 1;
      }
      if (in.pbrMetallicRoughness.baseColorTexture.texCoord != 0)
        ctx.warn(where + ": base colour uses TEXCOORD_" + std::to_string(in.pbrMetallicRoughness.baseColorTexture.texCoord) +
                 ", only TEXCOORD_0 is kept");
    }
    if (in.normalTexture.index >= 0 || in.occlusionTexture.index >= 0 || in.emissiveTexture.index >= 0 ||
        in.pbrMetallicRoughness.metallicRoughnessTexture.index >= 0)
      ctx.warn("materials keep only their base colour (normal, occlusion, emissive and metallic-roughness maps are not kept)");
    scene.materials.push_back(std::move(mat));
  }
  size_t pixelBudget = GltfLimits::kMaxImagePixels;
  for (size_t i = 0; i < m.images.size(); ++i) {
    scene.images[i].name = m.images[i].name;
    if (needed[i])
      if (std::string e = decodeImage(ctx, static_cast<int>(i), pixelBudget, scene.images[i]); !e.empty()) return e;
  }
  return {};
}

std::string importMeshes(GltfContext& ctx, const std::vector<int>& jointOfNode, Scene& scene) {
  const tinygltf::Model& m = ctx.model;
  std::vector<int> maxJointOfMesh(m.meshes.size(), -1);
  std::vector<size_t> targetsOfMesh(m.meshes.size(), 0);
  for (size_t mi = 0; mi < m.meshes.size(); ++mi) {
    const tinygltf::Mesh& in = m.meshes[mi];
    Mesh mesh;
    mesh.name = in.name;
    bool first = true;
    for (size_t pi = 0; pi < in.primitives.size(); ++pi) {
      const tinygltf::Primitive& p = in.primitives[pi];
      const std::string where = "mesh " + std::to_string(mi) + " primitive " + std::to_string(pi);
      const int mode = p.mode < 0 ? TINYGLTF_MODE_TRIANGLES : p.mode;
      if (mode < TINYGLTF_MODE_POINTS || mode > TINYGLTF_MODE_TRIANGLE_FAN)
        return ctx.error(where + ": mode " + std::to_string(mode) + " is not a glTF primitive mode (0..6)");
      // Points are kept as vertices without triangles (Kinema writes a primitive with no
      // triangle so); lines are not kept.
      if (mode != TINYGLTF_MODE_POINTS && mode < TINYGLTF_MODE_TRIANGLES) {
        ctx.warn(where + ": lines are not kept");
        continue;
      }
      if (!p.attributes.count("POSITION")) {
        ctx.warn(where + ": has no POSITION, not kept");
        continue;
      }
      if (p.material < -1 || p.material >= static_cast<int>(scene.materials.size()))
        return ctx.error(where + ": material " + std::to_string(p.material) + " does not exist");
      MeshPrimitive prim;
      if (std::string e = readPrimitive(ctx, p, where, prim, maxJointOfMesh[mi]); !e.empty()) return e;
      if (!first && prim.targets.size() != targetsOfMesh[mi])
        return ctx.error(where + ": " + std::to_string(prim.targets.size()) + " morph targets, the mesh's first primitive has " +
                         std::to_string(targetsOfMesh[mi]));
      targetsOfMesh[mi] = prim.targets.size();
      first = false;
      mesh.primitives.push_back(std::move(prim));
    }
    if (!in.weights.empty() && in.weights.size() != targetsOfMesh[mi])
      return ctx.error("mesh " + std::to_string(mi) + ": " + std::to_string(in.weights.size()) + " weights for " +
                       std::to_string(targetsOfMesh[mi]) + " morph targets");
    mesh.morphWeights.assign(targetsOfMesh[mi], 0.0f);
    for (size_t k = 0; k < in.weights.size(); ++k) {
      if (!finiteFloat(in.weights[k])) return ctx.error("mesh " + std::to_string(mi) + ": weight " + std::to_string(k) + " is not finite");
      mesh.morphWeights[k] = static_cast<float>(in.weights[k]);
    }
    mesh.targetNames = targetNamesOf(in);
    scene.meshes.push_back(std::move(mesh));
  }
  for (size_t n = 0; n < m.nodes.size(); ++n) {
    const tinygltf::Node& node = m.nodes[n];
    const std::string where = "node " + std::to_string(n);
    if (node.mesh < -1 || node.mesh >= static_cast<int>(m.meshes.size()))
      return ctx.error(where + ": mesh " + std::to_string(node.mesh) + " does not exist");
    if (node.skin < -1 || node.skin >= static_cast<int>(scene.skins.size()))
      return ctx.error(where + ": skin " + std::to_string(node.skin) + " does not exist");
    if (node.mesh < 0) {
      if (!node.weights.empty()) ctx.warn(where + ": morph weights without a mesh are not kept");
      continue;
    }
    MeshInstance inst;
    inst.joint = jointOfNode[n];
    inst.mesh = node.mesh;
    inst.skin = node.skin;
    if (inst.skin >= 0 && maxJointOfMesh[inst.mesh] >= static_cast<int>(scene.skins[inst.skin].joints.size()))
      return ctx.error(where + ": mesh " + std::to_string(inst.mesh) + " JOINTS use joint " +
                       std::to_string(maxJointOfMesh[inst.mesh]) + " but skin " + std::to_string(inst.skin) + " has " +
                       std::to_string(scene.skins[inst.skin].joints.size()) + " joints");
    if (!node.weights.empty() && node.weights.size() != targetsOfMesh[inst.mesh])
      return ctx.error(where + ": " + std::to_string(node.weights.size()) + " weights for " +
                       std::to_string(targetsOfMesh[inst.mesh]) + " morph targets of mesh " + std::to_string(inst.mesh));
    for (size_t k = 0; k < node.weights.size(); ++k) {
      if (!finiteFloat(node.weights[k])) return ctx.error(where + ": weight " + std::to_string(k) + " is not finite");
      inst.morphWeights.push_back(static_cast<float>(node.weights[k]));
    }
    scene.meshInstances.push_back(std::move(inst));
  }
  return {};
}

}  // namespace kinema
