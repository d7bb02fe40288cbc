#include "io/gltf_writer.h"

#include <tiny_gltf.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstring>
#include <map>
#include <numeric>
#include <sstream>

#include "anim/channel_modifiers.h"
#include "core/forward_kinematics.h"
#include "io/atomic_write.h"
#include "io/gltf_curves.h"
#include "io/image.h"

namespace kinema {

namespace {

// Appends typed arrays to the one buffer and describes them with views and accessors.
class BufferBuilder {
 public:
  explicit BufferBuilder(tinygltf::Model& model) : model_(model) { model_.buffers.resize(1); }

  int view(const void* bytes, size_t size, int target) {
    std::vector<unsigned char>& data = model_.buffers[0].data;
    while (data.size() % 4) data.push_back(0);  // every component type stays aligned
    tinygltf::BufferView v;
    v.buffer = 0;
    v.byteOffset = data.size();
    v.byteLength = size;
    v.target = target;
    const auto* p = static_cast<const unsigned char*>(bytes);
    data.insert(data.end(), p, p + size);
    model_.bufferViews.push_back(v);
    return static_cast<int>(model_.bufferViews.size()) - 1;
  }

  // `components` floats per element; min/max per component when asked (POSITION and
  // animation inputs must have them).
  int floats(const float* values, size_t count, int type, int components, int target, bool minMax) {
    tinygltf::Accessor a;
    a.bufferView = view(values, count * components * sizeof(float), target);
    a.componentType = TINYGLTF_COMPONENT_TYPE_FLOAT;
    a.count = count;
    a.type = type;
    if (minMax && count > 0) {
      a.minValues.assign(components, INFINITY);
      a.maxValues.assign(components, -INFINITY);
      for (size_t i = 0; i < count; ++i)
        for (int c = 0; c < components; ++c) {
          a.minValues[c] = std::min<double>(a.minValues[c], values[i * components + c]);
          a.maxValues[c] = std::max<double>(a.maxValues[c], values[i * components + c]);
        }
    }
    return push(a);
  }

  template <class T>
  int integers(const std::vector<T>& values, int componentType, int type, size_t count, int target) {
    tinygltf::Accessor a;
    a.bufferView = view(values.data(), values.size() * sizeof(T), target);
    a.componentType = componentType;
    a.count = count;
    a.type = type;
    return push(a);
  }

 private:
  int push(const tinygltf::Accessor& a) {
    model_.accessors.push_back(a);
    return static_cast<int>(model_.accessors.size()) - 1;
  }
  tinygltf::Model& model_;
};

std::vector<double> toDoubles(const float* v, int n) { return std::vector<double>(v, v + n); }

// Node index of each joint: the scene's file order when it has one (ranks of nodeOfJoint,
// so gaps left by dropped nodes close up), else the joint order.
std::vector<int> nodeIndices(const Scene& scene) {
  const int n = scene.skeleton.size();
  std::vector<int> node(n);
  std::iota(node.begin(), node.end(), 0);
  if (static_cast<int>(scene.nodeOfJoint.size()) != n) return node;
  std::vector<int> order(n);
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(),
                   [&](int a, int b) { return scene.nodeOfJoint[a] < scene.nodeOfJoint[b]; });
  for (int rank = 0; rank < n; ++rank) node[order[rank]] = rank;
  return node;
}

std::string checkScene(const Scene& scene) {
  const std::string bad = scene.skeleton.validate();
  if (!bad.empty()) return "cannot export: " + bad;
  for (size_t c = 0; c < scene.clips.size(); ++c) {
    const std::string e = scene.clips[c].validate(scene.skeleton);
    if (!e.empty()) return "cannot export: clip " + std::to_string(c) + ": " + e;
  }
  const int joints = scene.skeleton.size();
  for (size_t s = 0; s < scene.skins.size(); ++s) {
    const Skin& skin = scene.skins[s];
    if (skin.joints.empty()) return "cannot export: skin " + std::to_string(s) + " has no joints";
    if (skin.inverseBind.size() != skin.joints.size())
      return "cannot export: skin " + std::to_string(s) + " has " + std::to_string(skin.inverseBind.size()) +
             " inverse bind matrices for " + std::to_string(skin.joints.size()) + " joints";
    for (int j : skin.joints)
      if (j < 0 || j >= joints) return "cannot export: skin " + std::to_string(s) + " names joint " + std::to_string(j);
  }
  for (size_t m = 0; m < scene.meshes.size(); ++m)
    for (size_t p = 0; p < scene.meshes[m].primitives.size(); ++p) {
      const MeshPrimitive& prim = scene.meshes[m].primitives[p];
      const std::string at = "cannot export: mesh " + std::to_string(m) + " primitive " + std::to_string(p) + ": ";
      const size_t n = prim.positions.size();
      if (n == 0) return at + "no vertices";
      if ((!prim.normals.empty() && prim.normals.size() != n) || (!prim.texcoords.empty() && prim.texcoords.size() != n))
        return at + "attribute arrays differ in length";
      if (prim.influenceJoints.size() != prim.influenceWeights.size() ||
          (prim.skinned() && prim.influenceWeights.size() != n * kMaxInfluences))
        return at + "skin influences are not " + std::to_string(kMaxInfluences) + " per vertex";
      for (uint32_t i : prim.indices)
        if (i >= n) return at + "index " + std::to_string(i) + " is past the " + std::to_string(n) + " vertices";
      for (const MorphTarget& t : prim.targets)
        if (t.positionDeltas.size() != n || (!t.normalDeltas.empty() && t.normalDeltas.size() != n))
          return at + "a morph target's arrays differ from the vertex count";
      if (prim.material >= static_cast<int>(scene.materials.size()))
        return at + "material " + std::to_string(prim.material) + " does not exist";
    }
  for (size_t i = 0; i < scene.meshInstances.size(); ++i) {
    const MeshInstance& mi = scene.meshInstances[i];
    if (mi.joint < 0 || mi.joint >= joints || mi.mesh < 0 || mi.mesh >= static_cast<int>(scene.meshes.size()) ||
        mi.skin >= static_cast<int>(scene.skins.size()))
      return "cannot export: mesh instance " + std::to_string(i) + " names a joint, mesh or skin that does not exist";
    const size_t skinJoints = mi.skin >= 0 ? scene.skins[mi.skin].joints.size() : 0;
    for (const MeshPrimitive& prim : scene.meshes[mi.mesh].primitives)
      for (size_t k = 0; k < prim.influenceJoints.size(); ++k)
        if (prim.influenceWeights[k] != 0.0f && prim.influenceJoints[k] >= skinJoints)
          return "cannot export: mesh " + std::to_string(mi.mesh) + " uses joint " +
                 std::to_string(prim.influenceJoints[k]) + " of a skin with " + std::to_string(skinJoints);
  }
  for (size_t m = 0; m < scene.materials.size(); ++m)
    if (scene.materials[m].baseColorImage >= static_cast<int>(scene.images.size()))
      return "cannot export: material " + std::to_string(m) + " names a missing image";
  for (size_t i = 0; i < scene.images.size(); ++i) {
    const TextureImage& im = scene.images[i];
    if (im.width <= 0 || im.height <= 0 || im.rgba.size() != static_cast<size_t>(im.width) * im.height * 4)
      return "cannot export: image " + std::to_string(i) + " is empty or its size is inconsistent";
  }
  return {};
}

void addMesh(const Mesh& mesh, BufferBuilder& b, tinygltf::Model& model) {
  tinygltf::Mesh out;
  out.name = mesh.name;
  out.weights.assign(mesh.morphWeights.begin(), mesh.morphWeights.end());
  for (const MeshPrimitive& p : mesh.primitives) {
    tinygltf::Primitive prim;
    prim.mode = TINYGLTF_MODE_TRIANGLES;
    prim.material = p.material;
    const size_t n = p.positions.size();
    prim.attributes["POSITION"] =
        b.floats(&p.positions[0].x, n, TINYGLTF_TYPE_VEC3, 3, TINYGLTF_TARGET_ARRAY_BUFFER, true);
    if (!p.normals.empty())
      prim.attributes["NORMAL"] = b.floats(&p.normals[0].x, n, TINYGLTF_TYPE_VEC3, 3, TINYGLTF_TARGET_ARRAY_BUFFER, false);
    if (!p.texcoords.empty())
      prim.attributes["TEXCOORD_0"] =
          b.floats(&p.texcoords[0].x, n, TINYGLTF_TYPE_VEC2, 2, TINYGLTF_TARGET_ARRAY_BUFFER, false);
    if (p.skinned()) {
      // Influences 4..7 need a second set only when some vertex uses them.
      bool second = false;
      for (size_t v = 0; v < n && !second; ++v)
        for (int i = 4; i < kMaxInfluences; ++i) second = second || p.influenceWeights[v * kMaxInfluences + i] != 0.0f;
      // glTF wants each vertex's weights to sum to 1; data from elsewhere may be off a bit.
      std::vector<float> scale(n, 1.0f);
      for (size_t v = 0; v < n; ++v) {
        float sum = 0.0f;
        for (int i = 0; i < kMaxInfluences; ++i) sum += p.influenceWeights[v * kMaxInfluences + i];
        if (sum > 0.0f && std::abs(sum - 1.0f) > 1e-6f) scale[v] = 1.0f / sum;
      }
      for (int set = 0; set < (second ? 2 : 1); ++set) {
        std::vector<uint16_t> joints(n * 4);
        std::vector<float> weights(n * 4);
        for (size_t v = 0; v < n; ++v)
          for (int i = 0; i < 4; ++i) {
            const size_t from = v * kMaxInfluences + set * 4 + i;
            weights[v * 4 + i] = p.influenceWeights[from] * scale[v];
            // Unused slots name joint 0 with weight 0, as glTF asks.
            joints[v * 4 + i] = p.influenceWeights[from] != 0.0f ? p.influenceJoints[from] : 0;
          }
        const std::string suffix = "_" + std::to_string(set);
        prim.attributes["JOINTS" + suffix] = b.integers(joints, TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT,
                                                        TINYGLTF_TYPE_VEC4, n, TINYGLTF_TARGET_ARRAY_BUFFER);
        prim.attributes["WEIGHTS" + suffix] =
            b.floats(weights.data(), n, TINYGLTF_TYPE_VEC4, 4, TINYGLTF_TARGET_ARRAY_BUFFER, false);
      }
    }
    if (!p.indices.empty()) {
      if (n <= 65535) {
        const std::vector<uint16_t> small(p.indices.begin(), p.indices.end());
        prim.indices = b.integers(small, TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT, TINYGLTF_TYPE_SCALAR, small.size(),
                                  TINYGLTF_TARGET_ELEMENT_ARRAY_BUFFER);
      } else {
        prim.indices = b.integers(p.indices, TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT, TINYGLTF_TYPE_SCALAR,
                                  p.indices.size(), TINYGLTF_TARGET_ELEMENT_ARRAY_BUFFER);
      }
    } else {
      // No triangle (Kinema's empty index list): glTF's triangles without indices would read
      // back as one triangle per three vertices, so the vertices are written as points.
      prim.mode = TINYGLTF_MODE_POINTS;
    }
    for (const MorphTarget& t : p.targets) {
      std::map<std::string, int> target;
      target["POSITION"] =
          b.floats(&t.positionDeltas[0].x, n, TINYGLTF_TYPE_VEC3, 3, TINYGLTF_TARGET_ARRAY_BUFFER, true);
      if (!t.normalDeltas.empty())
        target["NORMAL"] = b.floats(&t.normalDeltas[0].x, n, TINYGLTF_TYPE_VEC3, 3, TINYGLTF_TARGET_ARRAY_BUFFER, false);
      prim.targets.push_back(std::move(target));
    }
    out.primitives.push_back(std::move(prim));
  }
  if (!mesh.targetNames.empty()) {
    tinygltf::Value::Array names;
    for (const std::string& s : mesh.targetNames) names.emplace_back(s);
    tinygltf::Value::Object extras;
    extras["targetNames"] = tinygltf::Value(names);
    out.extras = tinygltf::Value(extras);
  }
  model.meshes.push_back(std::move(out));
}

int morphTargetCount(const Mesh& mesh) {
  return mesh.primitives.empty() ? 0 : static_cast<int>(mesh.primitives[0].targets.size());
}

std::string degreesText(double radians) {
  std::ostringstream s;
  s.precision(3);
  s << radians * 180.0 / 3.14159265358979323846;
  return s.str();
}

std::string errorText(const GltfSampler& s, bool rotation) {
  std::ostringstream o;
  o.precision(3);
  if (rotation)
    o << degreesText(s.maxError) << " deg";
  else
    o << s.maxError;
  return o.str();
}

class AnimationWriter {
 public:
  AnimationWriter(const Scene& scene, const std::vector<int>& node, BufferBuilder& b, tinygltf::Model& model,
                  std::vector<std::string>* report)
      : scene_(scene), node_(node), b_(b), model_(model), report_(report) {}

  void add(const Clip& clip, size_t index, double rate) {
    tinygltf::Animation anim;
    anim.name = clip.name;
    // glTF keeps no frame rate: Kinema's own reader takes the clip's back from here.
    if (clip.frameTime > 0.0) {
      tinygltf::Value::Object extras;
      extras["kinema_frame_time"] = tinygltf::Value(clip.frameTime);
      anim.extras = tinygltf::Value(extras);
    }
    clipLabel_ = "clip '" + (clip.name.empty() ? std::to_string(index) : clip.name) + "'";
    std::map<std::pair<int, std::string>, bool> used;
    std::map<int, std::vector<const Channel*>> weights;  // joint -> per morph target
    for (const Channel& ch : clip.channels) {
      if (ch.times.empty()) continue;
      const std::string joint = ch.joint >= 0 ? "joint '" + scene_.skeleton.names[ch.joint] + "'" : "no joint";
      if (ch.target == ChannelTarget::Scalar) {
        const int k = morphIndex(ch);
        const int targets = ch.joint >= 0 ? targetCount(ch.joint) : 0;
        if (k < 0 || k >= targets) {
          note(clipLabel_ + ": " + joint + " scalar channel '" + ch.property + "' dropped (glTF animates only " +
               "transforms and morph weights of a mesh with that many targets)");
          continue;
        }
        auto& list = weights[ch.joint];
        list.resize(targets, nullptr);
        if (list[k]) {
          note(clipLabel_ + ": " + joint + " second '" + ch.property + "' channel dropped");
          continue;
        }
        list[k] = &ch;
        continue;
      }
      const std::string path = ch.target == ChannelTarget::Translation ? "translation"
                               : ch.target == ChannelTarget::Scale     ? "scale"
                                                                       : "rotation";
      if (used[{ch.joint, path}]) {
        note(clipLabel_ + ": " + joint + " second " + path + " channel dropped (glTF allows one per node)");
        continue;
      }
      used[{ch.joint, path}] = true;
      const GltfSampler s = toGltfSampler(ch, rate);
      if (s.resampled)
        note(clipLabel_ + ": " + joint + " " + toString(ch.target) + " resampled at " + rateText(rate) +
             " fps as LINEAR (" + s.reason + "), max error " + errorText(s, path == "rotation"));
      addChannel(anim, s, node_[ch.joint], path);
    }
    for (auto& [joint, list] : weights) {
      const std::vector<float> defaults = defaultWeights(joint);
      const GltfSampler s = toGltfWeightsSampler(list, defaults, rate);
      if (s.resampled)
        note(clipLabel_ + ": joint '" + scene_.skeleton.names[joint] + "' morph weights resampled at " +
             rateText(rate) + " fps as LINEAR (" + s.reason + "), max error " + errorText(s, false));
      addChannel(anim, s, node_[joint], "weights");
    }
    if (anim.channels.empty()) {
      note(clipLabel_ + ": nothing glTF can animate; not written");
      return;
    }
    model_.animations.push_back(std::move(anim));
  }

 private:
  static std::string rateText(double rate) {
    std::ostringstream o;
    o << rate;
    return o.str();
  }
  static int morphIndex(const Channel& ch) {
    if (ch.property.rfind("weights/", 0) != 0) return -1;
    const std::string digits = ch.property.substr(8);
    if (digits.empty() || digits.size() > 6 ||
        !std::all_of(digits.begin(), digits.end(), [](unsigned char c) { return std::isdigit(c) != 0; }))
      return -1;
    return std::stoi(digits);
  }
  const MeshInstance* instanceOf(int joint) const {
    for (const MeshInstance& mi : scene_.meshInstances)
      if (mi.joint == joint) return &mi;
    return nullptr;
  }
  int targetCount(int joint) const {
    const MeshInstance* mi = instanceOf(joint);
    return mi ? morphTargetCount(scene_.meshes[mi->mesh]) : 0;
  }
  std::vector<float> defaultWeights(int joint) const {
    const MeshInstance* mi = instanceOf(joint);
    const int n = targetCount(joint);
    std::vector<float> w(n, 0.0f);
    const std::vector<float>& from = !mi->morphWeights.empty() ? mi->morphWeights : scene_.meshes[mi->mesh].morphWeights;
    for (int k = 0; k < n && k < static_cast<int>(from.size()); ++k) w[k] = from[k];
    return w;
  }
  void addChannel(tinygltf::Animation& anim, const GltfSampler& s, int node, const std::string& path) {
    tinygltf::AnimationSampler sampler;
    sampler.input = b_.floats(s.times.data(), s.times.size(), TINYGLTF_TYPE_SCALAR, 1, 0, true);
    const bool vector = path != "weights";
    const int type = !vector ? TINYGLTF_TYPE_SCALAR : s.components == 4 ? TINYGLTF_TYPE_VEC4 : TINYGLTF_TYPE_VEC3;
    const int perElement = vector ? s.components : 1;
    sampler.output = b_.floats(s.values.data(), s.values.size() / perElement, type, perElement, 0, false);
    sampler.interpolation = toString(s.interpolation);
    anim.samplers.push_back(sampler);
    tinygltf::AnimationChannel channel;
    channel.sampler = static_cast<int>(anim.samplers.size()) - 1;
    channel.target_node = node;
    channel.target_path = path;
    anim.channels.push_back(channel);
  }
  void note(const std::string& line) {
    if (report_) report_->push_back(line);
  }

  const Scene& scene_;
  const std::vector<int>& node_;
  BufferBuilder& b_;
  tinygltf::Model& model_;
  std::vector<std::string>* report_;
  std::string clipLabel_;
};

constexpr double kMaxResampledKeys = 1e7;

// The option's rate, else the rate clip `c` counts in (its own, else the document's).
double rateFor(const Scene& scene, size_t c, const GltfWriteOptions& options) {
  if (options.resampleRate > 0.0) return options.resampleRate;
  return scene.frameGrid(static_cast<int>(c)).framesPerSecond();
}

std::string numberText(double v) {
  std::ostringstream o;
  o.precision(4);
  o << v;
  return o.str();
}

// A rate that is not a finite number (1 / a denormal frame time) resamples at the default rate.
double usableRate(double rate) { return std::isfinite(rate) && rate > 0.0 ? rate : kDefaultFrameRate; }

// Resampling allocates duration x rate keys per curve and a file controls both (key times
// near 3e38): a clip that would need more than kMaxResampledKeys is refused, but only when
// one of its curves must be resampled (converted at rate 0: keys only, no allocation);
// exact STEP / LINEAR / CUBICSPLINE curves of any length export. Counts are doubles, so
// the message cannot overflow. Morph weights may share a resampled grid: refused too.
std::string resamplingError(const Clip& clip, size_t index, double rate) {
  const double duration = double(clip.duration());
  const double samples = duration * rate;
  if (samples <= kMaxResampledKeys) return {};
  for (const Channel& ch : clip.channels) {
    if (ch.times.size() < 2) continue;
    if (ch.target != ChannelTarget::Scalar && !toGltfSampler(ch, 0.0).resampled) continue;
    if (ch.target == ChannelTarget::Scalar && ch.property.rfind("weights/", 0) != 0) continue;  // dropped anyway
    return "cannot export: clip " + std::to_string(index) + " would need " + numberText(samples) +
           " samples per resampled curve (" + numberText(duration) + " s at " + numberText(rate) + " fps; at most " +
           numberText(kMaxResampledKeys) + ")";
  }
  return {};
}

// The file's name without folder and extension ("walk" for "data/walk.bvh"), or "Armature".
std::string armatureName(const std::string& source) {
  const size_t slash = source.find_last_of('/');
  std::string stem = slash == std::string::npos ? source : source.substr(slash + 1);
  const size_t dot = stem.find_last_of('.');
  if (dot != std::string::npos && dot > 0) stem.resize(dot);
  return stem.empty() ? "Armature" : stem;
}

// A scene without skins or meshes (BVH, a .kinema of a bare skeleton) gets one skin per joint
// tree, joints = the tree's joints, inverse bind matrices = inverses of the rest pose's world
// matrices, as Blender's exporter writes an armature without a mesh: importers (Blender's
// among them) then build an armature instead of a hierarchy of empties. glTF asks a skin's
// joints to share a root, hence one skin per tree.
std::vector<Skin> armatureSkins(const Scene& scene, std::vector<std::string>& notes) {
  const Skeleton& sk = scene.skeleton;
  std::vector<Skin> skins;
  if (sk.empty()) return skins;
  const std::vector<glm::mat4> world = computeWorld(sk, Pose::rest(sk));
  std::vector<int> treeOf(sk.size(), -1);
  int roots = 0;
  for (int j = 0; j < sk.size(); ++j) roots += sk.parents[j] < 0;
  const std::string base = armatureName(scene.source);
  for (int j = 0; j < sk.size(); ++j) {  // parents come first: each joint joins its root's skin
    if (sk.parents[j] < 0) {
      treeOf[j] = static_cast<int>(skins.size());
      Skin skin;
      skin.name = roots > 1 ? base + "_" + sk.names[j] : base;
      skins.push_back(std::move(skin));
    } else {
      treeOf[j] = treeOf[sk.parents[j]];
    }
    Skin& skin = skins[treeOf[j]];
    const glm::mat4 inverse = glm::inverse(world[j]);
    bool finite = std::abs(glm::determinant(world[j])) > 1e-30f;
    for (int c = 0; c < 4; ++c)
      for (int r = 0; r < 4; ++r) finite = finite && std::isfinite(inverse[c][r]);
    if (!finite) {
      notes.push_back("no skin (armature) written: joint '" + sk.names[j] +
                      "' has a rest transform that cannot be inverted (zero scale)");
      return {};
    }
    skin.joints.push_back(j);
    skin.inverseBind.push_back(inverse);
  }
  return skins;
}

}  // namespace

Result<std::string> gltfBytes(const Scene& scene, const GltfWriteOptions& options, std::vector<std::string>* report) {
  if (hasUndecodedImages(scene)) {
    // What loaded with a warning converts: the images without pixels are left out.
    std::vector<int> dropped;
    const Scene kept = withoutUndecodedImages(scene, &dropped);
    if (report)
      for (int i : dropped)
        report->push_back("image " + std::to_string(i) + (scene.images[i].name.empty() ? "" : " '" + scene.images[i].name + "'") +
                          " could not be decoded when loading: not written (its materials keep their base colour)");
    return gltfBytes(kept, options, report);
  }
  const std::string bad = checkScene(scene);
  if (!bad.empty()) return Result<std::string>::failure(bad);
  if (!(options.resampleRate >= 0.0) || !std::isfinite(options.resampleRate))
    return Result<std::string>::failure("cannot export: the resample rate must be a positive number of frames per second");
  for (size_t c = 0; c < scene.clips.size(); ++c)
    if (std::string e = resamplingError(scene.clips[c], c, usableRate(rateFor(scene, c, options))); !e.empty())
      return Result<std::string>::failure(e);
  auto note = [&](const std::string& line) {
    if (report) report->push_back(line);
  };

  tinygltf::Model model;
  model.asset.version = "2.0";
  model.asset.generator = "Kinema";
  {
    tinygltf::Value::Object extras;
    extras["kinema_frame_rate"] = tinygltf::Value(scene.frameRate);
    model.asset.extras = tinygltf::Value(extras);
  }
  BufferBuilder b(model);
  const Skeleton& sk = scene.skeleton;
  const std::vector<int> node = nodeIndices(scene);

  model.nodes.resize(sk.size());
  tinygltf::Scene root;
  for (int j = 0; j < sk.size(); ++j) {
    tinygltf::Node& n = model.nodes[node[j]];
    // The file's own node names when the scene came from glTF (they may repeat or be
    // empty there; the skeleton's are made unique).
    const bool fileNames = scene.nodeOfJoint.size() == static_cast<size_t>(sk.size()) &&
                           scene.nodeOfJoint[j] >= 0 &&
                           scene.nodeOfJoint[j] < static_cast<int>(scene.nodeNames.size());
    n.name = fileNames ? scene.nodeNames[scene.nodeOfJoint[j]] : sk.names[j];
    const Transform& t = sk.rest[j];
    if (t.translation != glm::vec3(0.0f)) n.translation = toDoubles(&t.translation.x, 3);
    const glm::quat q = glm::normalize(t.rotation);
    if (q != glm::quat(1, 0, 0, 0)) n.rotation = {q.x, q.y, q.z, q.w};
    if (t.scale != glm::vec3(1.0f)) n.scale = toDoubles(&t.scale.x, 3);
    if (sk.parents[j] < 0)
      root.nodes.push_back(node[j]);
    else
      model.nodes[node[sk.parents[j]]].children.push_back(node[j]);
  }
  for (tinygltf::Node& n : model.nodes) std::sort(n.children.begin(), n.children.end());
  std::sort(root.nodes.begin(), root.nodes.end());

  for (const Mesh& mesh : scene.meshes) addMesh(mesh, b, model);
  for (const MeshInstance& mi : scene.meshInstances) {
    int target = node[mi.joint];
    if (model.nodes[target].mesh >= 0) {
      // A glTF node shows one mesh: a further one goes on a child node at the same place.
      tinygltf::Node extra;
      extra.name = sk.names[mi.joint] + "_mesh" + std::to_string(model.nodes.size());
      model.nodes.push_back(extra);
      target = static_cast<int>(model.nodes.size()) - 1;
      model.nodes[node[mi.joint]].children.push_back(target);
      note("joint '" + sk.names[mi.joint] + "' shows several meshes: extra node '" + extra.name + "' added");
    }
    model.nodes[target].mesh = mi.mesh;
    model.nodes[target].skin = mi.skin;
    model.nodes[target].weights.assign(mi.morphWeights.begin(), mi.morphWeights.end());
  }

  std::vector<std::string> skinNotes;
  // Only a bare skeleton becomes an armature: a file with meshes but no skins (a prop, a
  // morphing cube) keeps its plain nodes, as Blender would export it.
  const std::vector<Skin> armature =
      scene.skins.empty() && scene.meshes.empty() ? armatureSkins(scene, skinNotes) : std::vector<Skin>{};
  for (const std::string& line : skinNotes) note(line);
  for (const Skin& skin : scene.skins.empty() ? armature : scene.skins) {
    tinygltf::Skin s;
    s.name = skin.name;
    for (int j : skin.joints) s.joints.push_back(node[j]);
    if (skin.skeletonRoot >= 0 && skin.skeletonRoot < sk.size()) s.skeleton = node[skin.skeletonRoot];
    s.inverseBindMatrices =
        b.floats(&skin.inverseBind[0][0][0], skin.inverseBind.size(), TINYGLTF_TYPE_MAT4, 16, 0, false);
    model.skins.push_back(std::move(s));
  }

  if (!scene.images.empty()) {
    tinygltf::Sampler sampler;
    sampler.minFilter = TINYGLTF_TEXTURE_FILTER_LINEAR_MIPMAP_LINEAR;
    sampler.magFilter = TINYGLTF_TEXTURE_FILTER_LINEAR;
    model.samplers.push_back(sampler);
  }
  for (size_t i = 0; i < scene.images.size(); ++i) {
    const TextureImage& im = scene.images[i];
    const std::string png = encodePng(im.width, im.height, im.rgba.data());
    if (png.empty()) return Result<std::string>::failure("cannot export: image " + std::to_string(i) + ": PNG encoding failed");
    tinygltf::Image out;
    out.name = im.name;
    out.mimeType = "image/png";
    out.bufferView = b.view(png.data(), png.size(), 0);
    model.images.push_back(std::move(out));
    tinygltf::Texture texture;
    texture.sampler = 0;
    texture.source = static_cast<int>(i);
    model.textures.push_back(texture);
  }
  for (const Material& m : scene.materials) {
    tinygltf::Material out;
    out.name = m.name;
    out.doubleSided = m.doubleSided;
    out.pbrMetallicRoughness.baseColorFactor = toDoubles(&m.baseColor.x, 4);
    out.pbrMetallicRoughness.baseColorTexture.index = m.baseColorImage;  // texture i shows image i
    // Kinema materials are display colours: not metal (glTF's default metallic is 1).
    out.pbrMetallicRoughness.metallicFactor = 0.0;
    out.pbrMetallicRoughness.roughnessFactor = 1.0;
    if (m.baseColor.a < 1.0f) out.alphaMode = "BLEND";
    model.materials.push_back(std::move(out));
  }

  AnimationWriter animations(scene, node, b, model, report);
  for (size_t c = 0; c < scene.clips.size(); ++c) {
    const Clip& clip = scene.clips[c];
    const double wanted = rateFor(scene, c, options);
    const double rate = usableRate(wanted);
    const size_t before = report ? report->size() : 0;
    // glTF has no procedural curves: modified channels go out as their bake, one key per
    // frame at the export rate, so the file plays what Kinema plays at those frames.
    Clip baked;
    if (hasChannelModifiers(clip)) {
      if (std::string e = bakeClipModifiers(clip, rate, baked); !e.empty())
        return Result<std::string>::failure("cannot export: clip " + std::to_string(c) + ": baking its modifiers: " + e);
      note("clip '" + (clip.name.empty() ? std::to_string(c) : clip.name) + "': channel modifiers baked to keys at " +
           numberText(rate) + " fps");
    }
    animations.add(hasChannelModifiers(clip) ? baked : clip, c, rate);
    // Said only when a curve was resampled at the lowered rate (its own line follows).
    if (rate != wanted && report &&
        std::any_of(report->begin() + static_cast<long>(before), report->end(),
                    [](const std::string& line) { return line.find(" resampled at ") != std::string::npos; }))
      report->insert(report->begin() + static_cast<long>(before),
                     "clip '" + (clip.name.empty() ? std::to_string(c) : clip.name) + "': resampled at " +
                         numberText(rate) + " fps instead of " + numberText(wanted) + " fps (" +
                         "its frame time is too small to resample at)");
  }
  if (!scene.ik.empty()) note("IK limits and targets dropped (glTF has no place for them; .kinema keeps them)");
  for (size_t i = 0; i < scene.deformers.size() && i < scene.meshInstances.size(); ++i)
    if (!scene.deformers[i].empty())
      note("mesh instance " + std::to_string(i) + " (joint '" + scene.skeleton.names[scene.meshInstances[i].joint] +
           "'): " + std::to_string(scene.deformers[i].deformers.size()) +
           " deformer(s) dropped (glTF has no deformers; kinema convert --bake-deformers writes them as morph targets)");

  // tinygltf writes a node without any property as null, which is not glTF: an unnamed
  // leaf at rest gets its identity rotation written out.
  for (tinygltf::Node& n : model.nodes)
    if (n.name.empty() && n.children.empty() && n.mesh < 0 && n.skin < 0 && n.translation.empty() &&
        n.rotation.empty() && n.scale.empty() && n.weights.empty())
      n.rotation = {0.0, 0.0, 0.0, 1.0};
  if (model.buffers[0].data.empty()) model.buffers.clear();
  if (root.nodes.empty()) root.name = "Scene";  // tinygltf writes an empty scene as null, which is not glTF
  model.scenes.push_back(root);
  model.defaultScene = 0;

  tinygltf::TinyGLTF writer;
  std::ostringstream out;
  if (!writer.WriteGltfSceneToStream(&model, out, !options.binary, options.binary))
    return Result<std::string>::failure("cannot export: glTF serialisation failed");
  return out.str();
}

std::string saveGltf(const std::string& path, const Scene& scene, const GltfWriteOptions& options,
                     std::vector<std::string>* report) {
  Result<std::string> bytes = gltfBytes(scene, options, report);
  if (!bytes) return path + ": " + bytes.error();
  return writeFileAtomically(path, bytes.value());
}

}  // namespace kinema
