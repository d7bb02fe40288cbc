// The .kinema file's glTF-scene sections: node order, images (base64 PNG), materials, meshes
// (flat number arrays), skins and mesh instances with their deformer stacks.
#include "io/kinema_file_sections.h"

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <functional>
#include <glm/gtc/type_ptr.hpp>

#include "io/image.h"
#include "io/json_number.h"

namespace kinema::kinema_format {

namespace {

const char kBase64[] = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";

std::string toBase64(const std::string& bytes) {
  std::string out;
  out.reserve((bytes.size() + 2) / 3 * 4);
  for (size_t i = 0; i < bytes.size(); i += 3) {
    const size_t n = std::min<size_t>(3, bytes.size() - i);
    uint32_t v = 0;
    for (size_t k = 0; k < 3; ++k) v = (v << 8) | (k < n ? static_cast<unsigned char>(bytes[i + k]) : 0u);
    for (size_t k = 0; k < 4; ++k) out += k <= n ? kBase64[(v >> (18 - 6 * k)) & 63] : '=';
  }
  return out;
}

bool fromBase64(const std::string& text, std::string& out) {
  if (text.size() % 4) return false;
  out.clear();
  for (size_t i = 0; i < text.size(); i += 4) {
    uint32_t v = 0;
    int pad = 0;
    for (size_t k = 0; k < 4; ++k) {
      const char c = text[i + k];
      const char* at = std::strchr(kBase64, c);
      if (c == '=' && i + 4 == text.size() && k >= 2) {
        ++pad;
        v <<= 6;
      } else if (c != '\0' && at && !pad) {
        v = (v << 6) | static_cast<uint32_t>(at - kBase64);
      } else {
        return false;
      }
    }
    for (int k = 0; k < 3 - pad; ++k) out += static_cast<char>((v >> (16 - 8 * k)) & 0xff);
  }
  return true;
}

template <class V>
Json flatFloats(const std::vector<V>& values, int n) {
  Json a = Json::array();
  for (const V& v : values)
    for (int i = 0; i < n; ++i) a.push_back(jsonFloat(reinterpret_cast<const float*>(&v)[i]));
  return a;
}

// A flat array of finite floats whose length is a multiple of `group` (the element size).
bool readFlatFloats(Reader& r, const Json& j, const std::string& p, size_t group, std::vector<float>& out) {
  if (!j.is_array() || j.size() % group)
    return r.fail(p, "expected an array of numbers, " + std::to_string(group) + " per element");
  out.resize(j.size());
  for (size_t i = 0; i < j.size(); ++i) {
    const Json& x = j[i];
    if (!x.is_number()) return r.fail(p + "[" + std::to_string(i) + "]", "expected a number");
    const double d = x.get<double>();
    if (!std::isfinite(d) || std::abs(d) >= kFloatOverflow)
      return r.fail(p + "[" + std::to_string(i) + "]", "not a finite float");
    out[i] = static_cast<float>(d);
  }
  return true;
}

template <class V>
bool readVectors(Reader& r, const Json& obj, const std::string& p, const char* key, bool required, std::vector<V>& out) {
  const Json* v = r.member(obj, p, key, required);
  if (!v) return !required;
  constexpr size_t n = sizeof(V) / sizeof(float);
  std::vector<float> flat;
  if (!readFlatFloats(r, *v, p + "." + key, n, flat)) return false;
  out.resize(flat.size() / n);
  if (!flat.empty()) std::memcpy(static_cast<void*>(out.data()), flat.data(), flat.size() * sizeof(float));
  return true;
}

// An index in [lo, hi), or a one-line error naming the path.
bool readIndex(Reader& r, const Json& j, const std::string& p, long long lo, long long hi, int& out) {
  long long v = 0;
  if (!r.integer(j, p, v)) return false;
  if (v < lo || v >= hi)
    return r.fail(p, std::to_string(v) + " is out of range (" + std::to_string(lo) + ".." + std::to_string(hi - 1) + ")");
  out = static_cast<int>(v);
  return true;
}

bool readOptionalIndex(Reader& r, const Json& obj, const std::string& p, const char* key, long long hi, int& out) {
  const Json* v = r.member(obj, p, key, false);
  return !v || readIndex(r, *v, p + "." + key, -1, hi, out);
}

bool readArrayOf(Reader& r, const Json& root, const char* key, const std::function<bool(const Json&, const std::string&)>& each) {
  const Json* a = r.member(root, "", key, false);
  if (!a) return true;
  if (!a->is_array()) return r.fail(key, "expected an array");
  for (size_t i = 0; i < a->size(); ++i) {
    const std::string p = std::string(key) + "[" + std::to_string(i) + "]";
    if (!(*a)[i].is_object()) return r.fail(p, "expected an object");
    if (!each((*a)[i], p)) return false;
  }
  return true;
}

// Influences as the loaders promise them (core/mesh.h): no negative weight, largest first,
// summing to 1 (renormalised, with one warning per primitive when a sum was off by more
// than 1e-3), zero weights on joint 0. A vertex without weight follows its first joint.
bool normaliseInfluences(Reader& r, const std::string& p, MeshPrimitive& prim, std::vector<std::string>& warnings) {
  const size_t n = prim.positions.size();
  size_t renormalised = 0, unweighted = 0;
  std::pair<float, uint16_t> slot[kMaxInfluences];
  for (size_t v = 0; v < n; ++v) {
    float* w = &prim.influenceWeights[v * kMaxInfluences];
    uint16_t* joint = &prim.influenceJoints[v * kMaxInfluences];
    double sum = 0.0;  // double: eight weights near FLT_MAX must not sum to infinity
    bool sorted = true;
    for (int k = 0; k < kMaxInfluences; ++k) {
      if (w[k] < 0.0f)
        return r.fail(p + ".weights[" + std::to_string(v * kMaxInfluences + k) + "]", "a weight must not be negative");
      sum += w[k];
      sorted = sorted && (k == 0 || w[k] <= w[k - 1]);
    }
    if (sum == 0.0) {
      ++unweighted;
      w[0] = 1.0f;
      sum = 1.0;
    }
    if (!sorted) {
      for (int k = 0; k < kMaxInfluences; ++k) slot[k] = {w[k], joint[k]};
      std::stable_sort(slot, slot + kMaxInfluences, [](const auto& a, const auto& b) { return a.first > b.first; });
      for (int k = 0; k < kMaxInfluences; ++k) w[k] = slot[k].first, joint[k] = slot[k].second;
    }
    if (std::abs(sum - 1.0) > 1e-3) ++renormalised;
    // Sums off by float rounding only are left alone, so saved files read back bit for bit.
    if (std::abs(sum - 1.0) > 1e-6)
      for (int k = 0; k < kMaxInfluences; ++k) w[k] = static_cast<float>(w[k] / sum);
    for (int k = 0; k < kMaxInfluences; ++k)
      if (w[k] == 0.0f) joint[k] = 0;
  }
  if (unweighted)
    warnings.push_back(p + ": " + std::to_string(unweighted) + " vertices without skin weight follow their first joint");
  if (renormalised)
    warnings.push_back(p + ": " + std::to_string(renormalised) + " of " + std::to_string(n) +
                       " vertices had skin weights not summing to 1 (beyond 1e-3); renormalised");
  return true;
}

bool readPrimitive(Reader& r, const Json& j, const std::string& p, Scene& scene, MeshPrimitive& prim) {
  if (!readVectors(r, j, p, "positions", true, prim.positions) || !readVectors(r, j, p, "normals", false, prim.normals) ||
      !readVectors(r, j, p, "texcoords", false, prim.texcoords))
    return false;
  const size_t n = prim.positions.size();
  if (!prim.normals.empty() && prim.normals.size() != n) return r.fail(p + ".normals", "one normal per position expected");
  if (!prim.texcoords.empty() && prim.texcoords.size() != n)
    return r.fail(p + ".texcoords", "one texture coordinate per position expected");
  if (const Json* v = r.member(j, p, "indices", false)) {
    if (!v->is_array() || v->size() % 3) return r.fail(p + ".indices", "expected an array of vertex indices, 3 per triangle");
    prim.indices.resize(v->size());
    for (size_t i = 0; i < v->size(); ++i) {
      const Json& x = (*v)[i];
      // The path is built only for an error: meshes have many indices.
      if (!x.is_number_unsigned() || x.get<unsigned long long>() >= n) {
        int unused = 0;
        readIndex(r, x, p + ".indices[" + std::to_string(i) + "]", 0, static_cast<long long>(n), unused);
        return false;
      }
      prim.indices[i] = static_cast<uint32_t>(x.get<unsigned long long>());
    }
  }
  const Json* joints = r.member(j, p, "joints", false);
  const Json* weights = r.member(j, p, "weights", false);
  if ((joints == nullptr) != (weights == nullptr)) return r.fail(p, "\"joints\" and \"weights\" come together");
  if (joints) {
    const size_t count = n * kMaxInfluences;
    if (!joints->is_array() || joints->size() != count)
      return r.fail(p + ".joints", "expected " + std::to_string(kMaxInfluences) + " joint numbers per vertex");
    if (!readFlatFloats(r, *weights, p + ".weights", kMaxInfluences, prim.influenceWeights)) return false;
    if (prim.influenceWeights.size() != count)
      return r.fail(p + ".weights", "expected " + std::to_string(kMaxInfluences) + " weights per vertex");
    prim.influenceJoints.resize(count);
    for (size_t i = 0; i < count; ++i) {
      const Json& x = (*joints)[i];
      if (!x.is_number_unsigned() || x.get<unsigned long long>() >= 65536) {
        int unused = 0;
        readIndex(r, x, p + ".joints[" + std::to_string(i) + "]", 0, 65536, unused);
        return false;
      }
      prim.influenceJoints[i] = static_cast<uint16_t>(x.get<unsigned long long>());
    }
    if (!normaliseInfluences(r, p, prim, scene.warnings)) return false;
  }
  if (!readOptionalIndex(r, j, p, "material", static_cast<long long>(scene.materials.size()), prim.material)) return false;
  if (const Json* v = r.member(j, p, "targets", false)) {
    if (!v->is_array()) return r.fail(p + ".targets", "expected an array");
    for (size_t t = 0; t < v->size(); ++t) {
      const std::string tp = p + ".targets[" + std::to_string(t) + "]";
      if (!(*v)[t].is_object()) return r.fail(tp, "expected an object");
      MorphTarget target;
      if (!readVectors(r, (*v)[t], tp, "positions", true, target.positionDeltas) ||
          !readVectors(r, (*v)[t], tp, "normals", false, target.normalDeltas))
        return false;
      if (target.positionDeltas.size() != n || (!target.normalDeltas.empty() && target.normalDeltas.size() != n))
        return r.fail(tp, "expected one delta per vertex (" + std::to_string(n) + ")");
      prim.targets.push_back(std::move(target));
    }
  }
  return true;
}

bool readNamedJoint(Reader& r, const Json& j, const std::string& p, const Skeleton& s, int& out) {
  std::string name;
  if (!r.string(j, p, name)) return false;
  out = r.joint(s, name);
  if (out < 0) return r.fail(p, "no joint named '" + cutForMessage(name) + "'");
  return true;
}

bool readVec3(Reader& r, const Json& obj, const std::string& p, const char* key, bool required, glm::vec3& out) {
  const Json* v = r.member(obj, p, key, required);
  if (!v) return !required;
  return r.floats(*v, p + "." + key, 3, &out.x);
}

bool readLattice(Reader& r, const Json& j, const std::string& p, FfdLattice& lat) {
  if (!j.is_object()) return r.fail(p, "expected an object");
  const Json* v;
  if (!(v = r.member(j, p, "counts", true))) return false;
  if (!v->is_array() || v->size() != 3) return r.fail(p + ".counts", "expected an array of 3 integers");
  for (int a = 0; a < 3; ++a)
    if (!readIndex(r, (*v)[a], p + ".counts[" + std::to_string(a) + "]", kLatticeMinPoints, kLatticeMaxPoints + 1,
                   lat.counts[a]))
      return false;
  if (!readVec3(r, j, p, "origin", true, lat.origin)) return false;
  if (!(v = r.member(j, p, "axes", true))) return false;
  if (!v->is_array() || v->size() != 3) return r.fail(p + ".axes", "expected an array of 3 vectors");
  for (int a = 0; a < 3; ++a)
    if (!r.floats((*v)[a], p + ".axes[" + std::to_string(a) + "]", 3, &lat.axes[a].x)) return false;
  if (!readVectors(r, j, p, "points", true, lat.points)) return false;
  if (static_cast<int>(lat.points.size()) != lat.pointCount())
    return r.fail(p + ".points", "expected " + std::to_string(lat.pointCount()) + " points (3 numbers each), found " +
                                     std::to_string(lat.points.size()));
  if (std::string e = lat.validate(); !e.empty()) return r.fail(p, e);
  return true;
}

bool readAxisDeformer(Reader& r, const Json& j, const std::string& p, AxisDeformer& ax) {
  if (!j.is_object()) return r.fail(p, "expected an object");
  const Json* v;
  if ((v = r.member(j, p, "axis", false)) && !readEnum(r, *v, p + ".axis", ax.axis, "x, y, z")) return false;
  if (!readVec3(r, j, p, "origin", false, ax.origin)) return false;
  if ((v = r.member(j, p, "low", false)) && !readFloat(r, *v, p + ".low", ax.low)) return false;
  if ((v = r.member(j, p, "high", false)) && !readFloat(r, *v, p + ".high", ax.high)) return false;
  if ((v = r.member(j, p, "amount", false)) && !readFloat(r, *v, p + ".amount", ax.amount)) return false;
  if (std::string e = ax.validate(); !e.empty()) return r.fail(p, e);
  return true;
}

bool readSoftPull(Reader& r, const Json& j, const std::string& p, SoftPull& pull) {
  if (!j.is_object()) return r.fail(p, "expected an object");
  const Json* v;
  if (!readVec3(r, j, p, "center", true, pull.center) || !readVec3(r, j, p, "offset", false, pull.offset)) return false;
  if ((v = r.member(j, p, "radius", false)) && !readFloat(r, *v, p + ".radius", pull.radius)) return false;
  if ((v = r.member(j, p, "falloff", false)) &&
      !readEnum(r, *v, p + ".falloff", pull.falloff, "smooth, sphere, root, sharp, linear, constant"))
    return false;
  if (std::string e = pull.validate(); !e.empty()) return r.fail(p, e);
  return true;
}

// One entry of mesh_instances[i].deformers (docs/kinema-format.md, "Deformers").
bool readDeformer(Reader& r, const Json& j, const std::string& p, const Skeleton& s, const Mesh& mesh, Deformer& d) {
  if (!j.is_object()) return r.fail(p, "expected an object");
  const Json* v;
  if (!(v = r.member(j, p, "name", true)) || !r.string(*v, p + ".name", d.name)) return false;
  if (d.name.empty() || d.name.find('/') != std::string::npos)
    return r.fail(p + ".name", "a deformer's name must be non-empty and without '/'");
  if (!(v = r.member(j, p, "type", true)) ||
      !readEnum(r, *v, p + ".type", d.type, "lattice, bend, twist, taper, soft_pull"))
    return false;
  if ((v = r.member(j, p, "enabled", false))) {
    if (!v->is_boolean()) return r.fail(p + ".enabled", "expected true or false, found " + std::string(v->type_name()));
    d.enabled = v->get<bool>();
  }
  if ((v = r.member(j, p, "parent", false)) && !readNamedJoint(r, *v, p + ".parent", s, d.parentJoint)) return false;
  if ((v = r.member(j, p, "parent_rest", false)) && !r.floats(*v, p + ".parent_rest", 16, glm::value_ptr(d.parentRest)))
    return false;
  if ((v = r.member(j, p, "weights", false))) {
    if (!v->is_array()) return r.fail(p + ".weights", "expected an array with one list per primitive");
    if (v->size() > mesh.primitives.size())
      return r.fail(p + ".weights", "weights for " + std::to_string(v->size()) + " primitives, the mesh has " +
                                        std::to_string(mesh.primitives.size()));
    d.weights.resize(v->size());
    for (size_t k = 0; k < v->size(); ++k) {
      const std::string wp = p + ".weights[" + std::to_string(k) + "]";
      if (!readFlatFloats(r, (*v)[k], wp, 1, d.weights[k])) return false;
      if (!d.weights[k].empty() && d.weights[k].size() != mesh.primitives[k].positions.size())
        return r.fail(wp, "expected " + std::to_string(mesh.primitives[k].positions.size()) +
                              " weights (one per vertex) or none, found " + std::to_string(d.weights[k].size()));
      for (size_t i = 0; i < d.weights[k].size(); ++i)
        if (!(d.weights[k][i] >= 0.0f && d.weights[k][i] <= 1.0f))
          return r.fail(wp + "[" + std::to_string(i) + "]", "a weight must be in [0, 1]");
    }
  }
  const char* part = d.type == DeformerType::Lattice ? "lattice" : d.type == DeformerType::SoftPull ? "pull" : "axis";
  if (!(v = r.member(j, p, part, true))) return false;
  const std::string pp = p + "." + part;
  switch (d.type) {
    case DeformerType::Lattice:
      if (!readLattice(r, *v, pp, d.lattice)) return false;
      break;
    case DeformerType::SoftPull:
      if (!readSoftPull(r, *v, pp, d.pull)) return false;
      break;
    case DeformerType::Bend:
    case DeformerType::Twist:
    case DeformerType::Taper:
      d.axis.kind = d.type == DeformerType::Bend    ? AxisDeformerKind::Bend
                    : d.type == DeformerType::Twist ? AxisDeformerKind::Twist
                                                    : AxisDeformerKind::Taper;
      if (d.type == DeformerType::Taper) d.axis.amount = 1.0f;  // no taper when "amount" is left out
      if (!readAxisDeformer(r, *v, pp, d.axis)) return false;
      break;
  }
  if (std::string e = d.validate(s.size()); !e.empty()) return r.fail(p, e);
  return true;
}

bool readDeformers(Reader& r, const Json& j, const std::string& p, const Skeleton& s, const Mesh& mesh,
                   DeformerStack& stack) {
  if (!j.is_array()) return r.fail(p, "expected an array of deformers");
  stack.deformers.resize(j.size());
  for (size_t i = 0; i < j.size(); ++i) {
    const std::string dp = p + "[" + std::to_string(i) + "]";
    if (!readDeformer(r, j[i], dp, s, mesh, stack.deformers[i])) return false;
    for (size_t k = 0; k < i; ++k)
      if (stack.deformers[k].name == stack.deformers[i].name)
        return r.fail(dp + ".name", "'" + cutForMessage(stack.deformers[i].name) + "' is the name of deformer " +
                                        std::to_string(k) + " too (names must be unique in a stack)");
  }
  return true;
}

Json deformerJson(const Deformer& d, const Skeleton& s) {
  Json j;
  j["name"] = d.name;
  j["type"] = toString(d.type);
  if (!d.enabled) j["enabled"] = false;
  if (d.parentJoint >= 0) j["parent"] = s.names[d.parentJoint];
  if (d.parentRest != glm::mat4(1.0f)) j["parent_rest"] = vec(glm::value_ptr(d.parentRest), 16);
  if (!d.weights.empty()) {
    Json w = Json::array();
    for (const std::vector<float>& list : d.weights) w.push_back(flatFloats(list, 1));
    j["weights"] = std::move(w);
  }
  switch (d.type) {
    case DeformerType::Lattice: {
      const FfdLattice& l = d.lattice;
      Json axes = Json::array();
      for (const glm::vec3& a : l.axes) axes.push_back(vec(&a.x, 3));
      j["lattice"] = {{"counts", {l.counts[0], l.counts[1], l.counts[2]}},
                      {"origin", vec(&l.origin.x, 3)},
                      {"axes", std::move(axes)},
                      {"points", flatFloats(l.points, 3)}};
      break;
    }
    case DeformerType::SoftPull:
      j["pull"] = {{"center", vec(&d.pull.center.x, 3)},
                   {"offset", vec(&d.pull.offset.x, 3)},
                   {"radius", jsonFloat(d.pull.radius)},
                   {"falloff", toString(d.pull.falloff)}};
      break;
    case DeformerType::Bend:
    case DeformerType::Twist:
    case DeformerType::Taper:
      j["axis"] = {{"axis", toString(d.axis.axis)},
                   {"origin", vec(&d.axis.origin.x, 3)},
                   {"low", jsonFloat(d.axis.low)},
                   {"high", jsonFloat(d.axis.high)},
                   {"amount", jsonFloat(d.axis.amount)}};
      break;
  }
  return j;
}

}  // namespace

bool readSceneAssets(Reader& r, const Json& root, Scene& scene) {
  const Skeleton& s = scene.skeleton;
  if (const Json* v = r.member(root, "", "node_of_joint", false)) {
    if (!v->is_array() || static_cast<int>(v->size()) != s.size())
      return r.fail("node_of_joint", "expected one node index per joint (" + std::to_string(s.size()) + ")");
    std::vector<bool> used(s.size(), false);
    for (int i = 0; i < s.size(); ++i) {
      int node = 0;
      const std::string p = "node_of_joint[" + std::to_string(i) + "]";
      if (!readIndex(r, (*v)[i], p, 0, s.size(), node)) return false;
      if (used[node]) return r.fail(p, "node " + std::to_string(node) + " is given to two joints");
      used[node] = true;
      scene.nodeOfJoint.push_back(node);
    }
  }
  if (const Json* v = r.member(root, "", "node_names", false)) {
    if (!v->is_array()) return r.fail("node_names", "expected an array of strings");
    for (size_t i = 0; i < v->size(); ++i) {
      std::string name;
      if (!r.string((*v)[i], "node_names[" + std::to_string(i) + "]", name)) return false;
      scene.nodeNames.push_back(name);
    }
  }
  auto each = [&](const char* key, const std::function<bool(const Json&, const std::string&)>& f) {
    return readArrayOf(r, root, key, f);
  };
  const bool ok =
      each("images",
           [&](const Json& j, const std::string& p) {
             TextureImage im;
             const Json* v;
             std::string text, png;
             if ((v = r.member(j, p, "name", false)) && !r.string(*v, p + ".name", im.name)) return false;
             if (!(v = r.member(j, p, "png", true)) || !r.string(*v, p + ".png", text)) return false;
             if (!fromBase64(text, png)) return r.fail(p + ".png", "not base64 text");
             // The header's size is checked against the file's image budget before decoding.
             int w = 0, h = 0;
             if (!pngSize(png, w, h)) return r.fail(p + ".png", "not a PNG image");
             const size_t bytes = static_cast<size_t>(w) * static_cast<size_t>(h) * 4;
             if (bytes > r.imageBytesLeft)
               return r.fail(p + ".png", std::to_string(w) + " x " + std::to_string(h) + " pixels would take the file's "
                             "decoded images past the limit of its size + " +
                             std::to_string(r.limits.imageBytesOverFileSize >> 20) +
                             " MB (InputLimits::imageBytesOverFileSize)");
             if (!decodePng(png, im.width, im.height, im.rgba)) return r.fail(p + ".png", "not a PNG image");
             r.imageBytesLeft -= bytes;
             scene.images.push_back(std::move(im));
             return true;
           }) &&
      each("materials",
           [&](const Json& j, const std::string& p) {
             Material m;
             const Json* v;
             if ((v = r.member(j, p, "name", false)) && !r.string(*v, p + ".name", m.name)) return false;
             if ((v = r.member(j, p, "base_color", false)) && !r.floats(*v, p + ".base_color", 4, &m.baseColor.x))
               return false;
             if (!readOptionalIndex(r, j, p, "base_color_image", static_cast<long long>(scene.images.size()),
                                    m.baseColorImage))
               return false;
             if ((v = r.member(j, p, "double_sided", false))) {
               if (!v->is_boolean()) return r.fail(p + ".double_sided", "expected true or false");
               m.doubleSided = v->get<bool>();
             }
             scene.materials.push_back(std::move(m));
             return true;
           }) &&
      each("meshes",
           [&](const Json& j, const std::string& p) {
             Mesh mesh;
             const Json* v;
             if ((v = r.member(j, p, "name", false)) && !r.string(*v, p + ".name", mesh.name)) return false;
             if ((v = r.member(j, p, "morph_weights", false)) &&
                 !readFlatFloats(r, *v, p + ".morph_weights", 1, mesh.morphWeights))
               return false;
             if ((v = r.member(j, p, "target_names", false))) {
               if (!v->is_array()) return r.fail(p + ".target_names", "expected an array of strings");
               for (size_t i = 0; i < v->size(); ++i) {
                 std::string name;
                 if (!r.string((*v)[i], p + ".target_names[" + std::to_string(i) + "]", name)) return false;
                 mesh.targetNames.push_back(name);
               }
             }
             const Json* prims = r.member(j, p, "primitives", true);
             if (!prims) return false;
             if (!prims->is_array()) return r.fail(p + ".primitives", "expected an array");
             for (size_t i = 0; i < prims->size(); ++i) {
               const std::string pp = p + ".primitives[" + std::to_string(i) + "]";
               if (!(*prims)[i].is_object()) return r.fail(pp, "expected an object");
               MeshPrimitive prim;
               if (!readPrimitive(r, (*prims)[i], pp, scene, prim)) return false;
               mesh.primitives.push_back(std::move(prim));
             }
             scene.meshes.push_back(std::move(mesh));
             return true;
           }) &&
      each("skins",
           [&](const Json& j, const std::string& p) {
             Skin skin;
             const Json* v;
             if ((v = r.member(j, p, "name", false)) && !r.string(*v, p + ".name", skin.name)) return false;
             if (!(v = r.member(j, p, "joints", true))) return false;
             if (!v->is_array() || v->empty()) return r.fail(p + ".joints", "expected an array of joint names");
             for (size_t i = 0; i < v->size(); ++i) {
               int joint = -1;
               if (!readNamedJoint(r, (*v)[i], p + ".joints[" + std::to_string(i) + "]", s, joint)) return false;
               skin.joints.push_back(joint);
             }
             if (!readVectors(r, j, p, "inverse_bind", true, skin.inverseBind)) return false;
             if (skin.inverseBind.size() != skin.joints.size())
               return r.fail(p + ".inverse_bind", "expected 16 numbers per joint");
             if ((v = r.member(j, p, "skeleton", false)) &&
                 !readNamedJoint(r, *v, p + ".skeleton", s, skin.skeletonRoot))
               return false;
             scene.skins.push_back(std::move(skin));
             return true;
           }) &&
      each("mesh_instances", [&](const Json& j, const std::string& p) {
        MeshInstance mi;
        const Json* v;
        if (!(v = r.member(j, p, "joint", true)) || !readNamedJoint(r, *v, p + ".joint", s, mi.joint)) return false;
        if (!(v = r.member(j, p, "mesh", true)) ||
            !readIndex(r, *v, p + ".mesh", 0, static_cast<long long>(scene.meshes.size()), mi.mesh))
          return false;
        if (!readOptionalIndex(r, j, p, "skin", static_cast<long long>(scene.skins.size()), mi.skin)) return false;
        if ((v = r.member(j, p, "morph_weights", false)) &&
            !readFlatFloats(r, *v, p + ".morph_weights", 1, mi.morphWeights))
          return false;
        if ((v = r.member(j, p, "skinning", false))) {
          std::string method;
          if (!r.string(*v, p + ".skinning", method)) return false;
          if (method == "linear") mi.skinning = SkinningMethod::LinearBlend;
          else if (method == "dual-quaternion") mi.skinning = SkinningMethod::DualQuaternion;
          else return r.fail(p + ".skinning", "expected \"linear\" or \"dual-quaternion\", found \"" + method + "\"");
        }
        // Influences index the skin's joint list.
        const Mesh& mesh = scene.meshes[mi.mesh];
        const size_t joints = mi.skin >= 0 ? scene.skins[mi.skin].joints.size() : 0;
        for (size_t k = 0; k < mesh.primitives.size(); ++k) {
          const MeshPrimitive& prim = mesh.primitives[k];
          if (prim.skinned() && mi.skin < 0) return r.fail(p + ".skin", "the mesh is skinned: a skin is needed");
          for (size_t i = 0; i < prim.influenceJoints.size(); ++i)
            if (prim.influenceWeights[i] != 0.0f && prim.influenceJoints[i] >= joints)
              return r.fail(p, "meshes[" + std::to_string(mi.mesh) + "].primitives[" + std::to_string(k) + "].joints[" +
                                   std::to_string(i) + "] = " + std::to_string(prim.influenceJoints[i]) +
                                   " is past the skin's " + std::to_string(joints) + " joints");
        }
        DeformerStack stack;
        if ((v = r.member(j, p, "deformers", false)) && !readDeformers(r, *v, p + ".deformers", s, mesh, stack))
          return false;
        if (!stack.empty()) {
          scene.deformers.resize(scene.meshInstances.size());
          scene.deformers.push_back(std::move(stack));
        }
        scene.meshInstances.push_back(std::move(mi));
        return true;
      });
  // One stack per instance, or none at all.
  if (ok && !scene.deformers.empty()) scene.deformers.resize(scene.meshInstances.size());
  return ok;
}

void sceneAssetsToJson(const Scene& scene, Json& root) {
  const Skeleton& s = scene.skeleton;
  if (!scene.nodeOfJoint.empty()) root["node_of_joint"] = scene.nodeOfJoint;
  if (!scene.nodeNames.empty()) root["node_names"] = scene.nodeNames;
  if (!scene.images.empty()) {
    Json a = Json::array();
    for (const TextureImage& im : scene.images) {
      Json j;
      if (!im.name.empty()) j["name"] = im.name;
      j["png"] = toBase64(encodePng(im.width, im.height, im.rgba.data()));
      a.push_back(std::move(j));
    }
    root["images"] = std::move(a);
  }
  if (!scene.materials.empty()) {
    Json a = Json::array();
    for (const Material& m : scene.materials) {
      Json j;
      if (!m.name.empty()) j["name"] = m.name;
      j["base_color"] = vec(&m.baseColor.x, 4);
      if (m.baseColorImage >= 0) j["base_color_image"] = m.baseColorImage;
      if (m.doubleSided) j["double_sided"] = true;
      a.push_back(std::move(j));
    }
    root["materials"] = std::move(a);
  }
  if (!scene.meshes.empty()) {
    Json a = Json::array();
    for (const Mesh& mesh : scene.meshes) {
      Json j;
      if (!mesh.name.empty()) j["name"] = mesh.name;
      if (!mesh.morphWeights.empty()) j["morph_weights"] = flatFloats(mesh.morphWeights, 1);
      if (!mesh.targetNames.empty()) j["target_names"] = mesh.targetNames;
      Json prims = Json::array();
      for (const MeshPrimitive& prim : mesh.primitives) {
        Json pj;
        pj["positions"] = flatFloats(prim.positions, 3);
        if (!prim.normals.empty()) pj["normals"] = flatFloats(prim.normals, 3);
        if (!prim.texcoords.empty()) pj["texcoords"] = flatFloats(prim.texcoords, 2);
        if (!prim.indices.empty()) pj["indices"] = prim.indices;
        if (prim.skinned()) {
          pj["joints"] = prim.influenceJoints;
          pj["weights"] = flatFloats(prim.influenceWeights, 1);
        }
        if (prim.material >= 0) pj["material"] = prim.material;
        if (!prim.targets.empty()) {
          Json targets = Json::array();
          for (const MorphTarget& t : prim.targets) {
            Json tj;
            tj["positions"] = flatFloats(t.positionDeltas, 3);
            if (!t.normalDeltas.empty()) tj["normals"] = flatFloats(t.normalDeltas, 3);
            targets.push_back(std::move(tj));
          }
          pj["targets"] = std::move(targets);
        }
        prims.push_back(std::move(pj));
      }
      j["primitives"] = std::move(prims);
      a.push_back(std::move(j));
    }
    root["meshes"] = std::move(a);
  }
  if (!scene.skins.empty()) {
    Json a = Json::array();
    for (const Skin& skin : scene.skins) {
      Json j;
      if (!skin.name.empty()) j["name"] = skin.name;
      Json joints = Json::array();
      for (int joint : skin.joints) joints.push_back(s.names[joint]);
      j["joints"] = std::move(joints);
      j["inverse_bind"] = flatFloats(skin.inverseBind, 16);
      if (skin.skeletonRoot >= 0) j["skeleton"] = s.names[skin.skeletonRoot];
      a.push_back(std::move(j));
    }
    root["skins"] = std::move(a);
  }
  if (!scene.meshInstances.empty()) {
    Json a = Json::array();
    for (size_t i = 0; i < scene.meshInstances.size(); ++i) {
      const MeshInstance& mi = scene.meshInstances[i];
      Json j;
      j["joint"] = s.names[mi.joint];
      j["mesh"] = mi.mesh;
      if (mi.skin >= 0) j["skin"] = mi.skin;
      if (!mi.morphWeights.empty()) j["morph_weights"] = flatFloats(mi.morphWeights, 1);
      if (mi.skinning == SkinningMethod::DualQuaternion) j["skinning"] = "dual-quaternion";
      if (const DeformerStack* stack = scene.deformerStack(i)) {
        Json list = Json::array();
        for (const Deformer& d : stack->deformers) list.push_back(deformerJson(d, s));
        j["deformers"] = std::move(list);
      }
      a.push_back(std::move(j));
    }
    root["mesh_instances"] = std::move(a);
  }
}

// What saving must refuse: references the file could not express or read back.
std::string sceneAssetsError(const Scene& scene) {
  const int joints = scene.skeleton.size();
  if (!scene.nodeOfJoint.empty()) {
    if (static_cast<int>(scene.nodeOfJoint.size()) != joints) return "node_of_joint must have one entry per joint";
    std::vector<bool> used(joints, false);
    for (int node : scene.nodeOfJoint) {
      if (node < 0 || node >= joints || used[node]) return "node_of_joint must be a permutation of the joints";
      used[node] = true;
    }
  }
  for (size_t i = 0; i < scene.images.size(); ++i) {
    const TextureImage& im = scene.images[i];
    if (isUndecodedImage(im)) continue;  // not saved (withoutUndecodedImages)
    if (im.width <= 0 || im.height <= 0 || im.rgba.size() != static_cast<size_t>(im.width) * im.height * 4)
      return "image " + std::to_string(i) + " is empty or its size is inconsistent";
  }
  for (size_t i = 0; i < scene.materials.size(); ++i)
    if (scene.materials[i].baseColorImage >= static_cast<int>(scene.images.size()))
      return "material " + std::to_string(i) + " names a missing image";
  for (size_t m = 0; m < scene.meshes.size(); ++m)
    for (const MeshPrimitive& prim : scene.meshes[m].primitives) {
      const size_t n = prim.positions.size();
      const std::string at = "mesh " + std::to_string(m) + ": ";
      if ((!prim.normals.empty() && prim.normals.size() != n) || (!prim.texcoords.empty() && prim.texcoords.size() != n) ||
          prim.indices.size() % 3 || prim.influenceJoints.size() != prim.influenceWeights.size() ||
          (prim.skinned() && prim.influenceWeights.size() != n * kMaxInfluences))
        return at + "attribute arrays of different lengths";
      for (uint32_t i : prim.indices)
        if (i >= n) return at + "an index past the vertices";
      if (prim.material >= static_cast<int>(scene.materials.size())) return at + "a missing material";
      for (const MorphTarget& t : prim.targets)
        if (t.positionDeltas.size() != n || (!t.normalDeltas.empty() && t.normalDeltas.size() != n))
          return at + "a morph target of the wrong size";
    }
  for (size_t i = 0; i < scene.skins.size(); ++i) {
    const Skin& skin = scene.skins[i];
    if (skin.joints.empty() || skin.inverseBind.size() != skin.joints.size())
      return "skin " + std::to_string(i) + " needs joints and one inverse bind matrix each";
    for (int j : skin.joints)
      if (j < 0 || j >= joints) return "skin " + std::to_string(i) + " names a missing joint";
    if (skin.skeletonRoot >= joints) return "skin " + std::to_string(i) + " names a missing skeleton root";
  }
  for (size_t i = 0; i < scene.meshInstances.size(); ++i) {
    const MeshInstance& mi = scene.meshInstances[i];
    if (mi.joint < 0 || mi.joint >= joints || mi.mesh < 0 || mi.mesh >= static_cast<int>(scene.meshes.size()) ||
        mi.skin >= static_cast<int>(scene.skins.size()))
      return "mesh instance " + std::to_string(i) + " names a missing joint, mesh or skin";
  }
  if (scene.deformers.size() > scene.meshInstances.size())
    return "deformer stacks for " + std::to_string(scene.deformers.size()) + " mesh instances, the scene has " +
           std::to_string(scene.meshInstances.size());
  for (size_t i = 0; i < scene.deformers.size(); ++i)
    if (std::string e = scene.deformers[i].validate(scene.meshes[scene.meshInstances[i].mesh], joints); !e.empty())
      return "mesh instance " + std::to_string(i) + ": " + e;
  return {};
}

}  // namespace kinema::kinema_format
