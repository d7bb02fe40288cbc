#include "io/kinema_file.h"

#include <algorithm>
#include <climits>
#include <cstdint>
#include <cmath>
#include <cstring>
#include <functional>
#include <unordered_map>
#include <unordered_set>
#include <nlohmann/json.hpp>

#include "anim/channel_modifiers.h"
#include "core/forward_kinematics.h"
#include "core/rotation.h"
#include "io/atomic_write.h"
#include "io/json_depth.h"
#include "io/image.h"
#include "io/json_document.h"
#include "io/kinema_crowds.h"
#include "io/json_number.h"
#include "io/kinema_particles.h"
#include "io/message_text.h"
#include "io/text_file.h"

namespace kinema {

using Json = nlohmann::ordered_json;

namespace {

Json vec(const float* v, int n) {
  Json a = Json::array();
  for (int i = 0; i < n; ++i) a.push_back(jsonFloat(v[i]));
  return a;
}

// Puts arrays that hold only numbers on one line: "[0.0, 0.95, 0.0]" instead of one
// number per line, which keeps clips readable and files a third the size.
std::string collapseNumberArrays(const std::string& in) {
  std::string out;
  out.reserve(in.size());
  bool inString = false;
  for (size_t i = 0; i < in.size(); ++i) {
    if (inString || in[i] == '"') {
      // Copy strings verbatim: a joint may be called "arm[ 1 ]".
      if (inString && in[i] == '\\') {
        out += in[i++];
      } else if (in[i] == '"') {
        inString = !inString;
      }
      out += in[i];
      continue;
    }
    if (in[i] != '[') {
      out += in[i];
      continue;
    }
    size_t end = i + 1;
    while (end < in.size() && in[end] != ']' && in[end] != '[' && in[end] != '{' && in[end] != '"') ++end;
    if (end >= in.size() || in[end] != ']') {
      out += in[i];
      continue;
    }
    out += '[';
    bool space = false;
    for (size_t k = i + 1; k < end; ++k) {
      const char c = in[k];
      if (c == '\n' || c == '\t' || c == ' ') {
        space = true;
        continue;
      }
      if (space && out.back() == ',') out += ' ';
      space = false;
      out += c;
    }
    out += ']';
    i = end;
  }
  return out;
}

// Doubles at or beyond 2^128 - 2^103 (halfway between FLT_MAX and the next power of two)
// round to infinity as floats; everything below rounds to a finite float.
const double kFloatOverflow = std::ldexp(1.0, 128) - std::ldexp(1.0, 103);

// Messages are one line: control characters from the file (a joint name with a newline)
// are shown escaped.
std::string oneLine(const std::string& s) {
  std::string out;
  for (char c : s) {
    if (static_cast<unsigned char>(c) < 0x20 || c == 0x7f) {
      static const char hex[] = "0123456789abcdef";
      out += "\\x";
      out += hex[(c >> 4) & 0xf];
      out += hex[c & 0xf];
    } else {
      out += c;
    }
  }
  return out;
}

// Reads with the JSON path of every value at hand, so errors can point at it.
class Reader {
 public:
  explicit Reader(std::string source, const InputLimits& limits = {}, size_t inputBytes = 0)
      : limits(limits), imageBytesLeft(imageBudgetBytes(inputBytes, limits)), source_(std::move(source)) {}
  const std::string& error() const { return error_; }
  const InputLimits limits;
  size_t imageBytesLeft;  // decoded images still allowed (InputLimits::imageBytesOverFileSize)
  // Joint name -> index, filled as the skeleton is read: lookups by name stay constant time
  // (Skeleton::find is a linear scan, quadratic over a 200,000-joint file).
  std::unordered_map<std::string, int> jointIndex;
  int joint(const Skeleton& s, const std::string& name) const {
    if (jointIndex.size() != static_cast<size_t>(s.size())) return s.find(name);  // another skeleton
    const auto it = jointIndex.find(name);
    return it == jointIndex.end() ? -1 : it->second;
  }

  bool fail(const std::string& path, const std::string& what) {
    error_ = oneLineMessage(source_ + ": " + (path.empty() ? "" : path + ": ") + what);
    return false;
  }

  const Json* member(const Json& obj, const std::string& path, const char* key, bool required) {
    const std::string p = path.empty() ? key : path + "." + key;
    auto it = obj.find(key);
    if (it == obj.end()) {
      if (required) fail(p, "missing");
      return nullptr;
    }
    return &*it;
  }

  bool number(const Json& j, const std::string& path, double& out) {
    if (!j.is_number()) return fail(path, "expected a number, found " + std::string(j.type_name()));
    out = j.get<double>();
    if (!std::isfinite(out)) return fail(path, "not a finite number");
    return true;
  }

  bool floats(const Json& j, const std::string& path, int n, float* out) {
    if (!j.is_array() || static_cast<int>(j.size()) != n)
      return fail(path, "expected an array of " + std::to_string(n) + " numbers");
    for (int i = 0; i < n; ++i) {
      double v = 0.0;
      if (!number(j[i], path + "[" + std::to_string(i) + "]", v)) return false;
      if (std::abs(v) >= kFloatOverflow) return fail(path + "[" + std::to_string(i) + "]", "number out of float range");
      out[i] = static_cast<float>(v);
    }
    return true;
  }

  bool string(const Json& j, const std::string& path, std::string& out) {
    if (!j.is_string()) return fail(path, "expected a string, found " + std::string(j.type_name()));
    out = j.get<std::string>();
    return true;
  }

  bool integer(const Json& j, const std::string& path, long long& out) {
    if (!j.is_number_integer()) return fail(path, "expected an integer, found " + std::string(j.type_name()));
    // Unsigned values above LLONG_MAX would wrap (2^64 - 1 would read as -1).
    if (j.is_number_unsigned() && j.get<unsigned long long>() > static_cast<unsigned long long>(LLONG_MAX))
      return fail(path, "integer " + std::to_string(j.get<unsigned long long>()) + " is out of range");
    out = j.get<long long>();
    return true;
  }

 private:
  std::string source_;
  std::string error_;
};

// Normalise only quaternions that are visibly off unit length, so a saved unit
// quaternion reads back bit for bit.
glm::quat normalizeIfNeeded(const glm::quat& q) {
  const float len2 = glm::dot(q, q);
  if (std::abs(len2 - 1.0f) < 1e-6f) return q;
  return safeNormalize(q);  // glm::normalize overflows to zero for components near 1e20 and up
}

// The optional "translation", "rotation" ([x, y, z, w], normalised) and "scale" members of a
// joint or pose entry at `p`, over what `t` holds.
bool readTransform(Reader& r, const Json& j, const std::string& p, Transform& t) {
  const Json* v;
  if ((v = r.member(j, p, "translation", false)) && !r.floats(*v, p + ".translation", 3, &t.translation.x))
    return false;
  if ((v = r.member(j, p, "rotation", false))) {
    float q[4];
    if (!r.floats(*v, p + ".rotation", 4, q)) return false;
    if (q[0] == 0 && q[1] == 0 && q[2] == 0 && q[3] == 0) return r.fail(p + ".rotation", "zero quaternion");
    t.rotation = normalizeIfNeeded(glm::quat(q[3], q[0], q[1], q[2]));
  }
  if ((v = r.member(j, p, "scale", false)) && !r.floats(*v, p + ".scale", 3, &t.scale.x)) return false;
  return true;
}

// The transform's members as readTransform reads them, into `j`.
void writeTransform(const Transform& t, Json& j) {
  j["translation"] = vec(&t.translation.x, 3);
  const float q[4] = {t.rotation.x, t.rotation.y, t.rotation.z, t.rotation.w};
  j["rotation"] = vec(q, 4);
  j["scale"] = vec(&t.scale.x, 3);
}

bool readSkeleton(Reader& r, const Json& root, Skeleton& s) {
  const Json* sk = r.member(root, "", "skeleton", true);
  if (!sk) return false;
  if (!sk->is_object()) return r.fail("skeleton", "expected an object");
  const Json* joints = r.member(*sk, "skeleton", "joints", true);
  if (!joints) return false;
  if (!joints->is_array()) return r.fail("skeleton.joints", "expected an array");
  if (joints->size() > static_cast<size_t>(r.limits.maxJoints))
    return r.fail("skeleton.joints",
                  limitExceeded(static_cast<long long>(joints->size()), r.limits.maxJoints, "joints", "maxJoints"));
  for (size_t i = 0; i < joints->size(); ++i) {
    const std::string p = "skeleton.joints[" + std::to_string(i) + "]";
    const Json& j = (*joints)[i];
    if (!j.is_object()) return r.fail(p, "expected an object");
    std::string name;
    long long parent = -1;
    Transform t;
    const Json* v;
    if (!(v = r.member(j, p, "name", true)) || !r.string(*v, p + ".name", name)) return false;
    if (name.empty()) return r.fail(p + ".name", "empty joint name");
    if (!(v = r.member(j, p, "parent", true)) || !r.integer(*v, p + ".parent", parent)) return false;
    if (parent < -1 || parent >= static_cast<long long>(i))
      return r.fail(p + ".parent", "parent " + std::to_string(parent) + " must be -1 or an earlier joint (0.." +
                                       std::to_string(static_cast<long long>(i) - 1) + ")");
    if (!readTransform(r, j, p, t)) return false;
    if (!r.jointIndex.emplace(name, s.size()).second)
      return r.fail(p + ".name", "joint name '" + cutForMessage(name) + "' is used twice");
    s.addJoint(name, static_cast<int>(parent), t);
  }
  return true;
}

// ---- IK rig: joint limits and saved targets (the optional top-level "ik" key) ----
// Angles are degrees in the file (as in the UI), radians in memory.

constexpr float kDeg = 3.14159265358979323846f / 180.0f;

bool readDegrees(Reader& r, const Json& obj, const std::string& p, const char* key, float& out) {
  const Json* v = r.member(obj, p, key, true);
  double d = 0.0;
  if (!v || !r.number(*v, p + "." + key, d)) return false;
  out = static_cast<float>(d) * kDeg;
  return true;
}

bool readJointName(Reader& r, const Json& obj, const std::string& p, const char* key, const Skeleton& s,
                   bool required, int& out) {
  const Json* v = r.member(obj, p, key, required);
  if (!v) return !required;
  std::string name;
  if (!r.string(*v, p + "." + key, name)) return false;
  out = r.joint(s, name);
  if (out < 0) return r.fail(p + "." + key, "no joint named '" + cutForMessage(name) + "'");
  return true;
}

bool readLimit(Reader& r, const Json& j, const std::string& p, Scene& scene) {
  if (!j.is_object()) return r.fail(p, "expected an object");
  int joint = -1;
  if (!readJointName(r, j, p, "joint", scene.skeleton, true, joint)) return false;
  std::string type;
  const Json* v = r.member(j, p, "type", true);
  if (!v || !r.string(*v, p + ".type", type)) return false;
  JointLimit l;
  if (type == "hinge" || type == "cone") {
    l.type = type == "hinge" ? JointLimitType::Hinge : JointLimitType::Cone;
    if (!(v = r.member(j, p, "axis", true)) || !r.floats(*v, p + ".axis", 3, &l.axis.x)) return false;
    if (!(glm::length(l.axis) > 1e-6f)) return r.fail(p + ".axis", "zero axis");
    l.axis = glm::normalize(l.axis);
    if (l.type == JointLimitType::Hinge) {
      if (!readDegrees(r, j, p, "min_deg", l.minAngle) || !readDegrees(r, j, p, "max_deg", l.maxAngle)) return false;
    } else {
      if (!readDegrees(r, j, p, "cone_deg", l.coneAngle) || !readDegrees(r, j, p, "twist_min_deg", l.twistMin) ||
          !readDegrees(r, j, p, "twist_max_deg", l.twistMax))
        return false;
    }
  } else if (type == "euler") {
    l.type = JointLimitType::Euler;
    std::string order = "XYZ";
    if ((v = r.member(j, p, "order", false)) && !r.string(*v, p + ".order", order)) return false;
    const std::optional<EulerOrder> o = eulerOrderFromString(order);
    if (!o) return r.fail(p + ".order", "'" + cutForMessage(order) + "' is not an Euler order (XYZ, ZXY, ...)");
    l.order = *o;
    if (!(v = r.member(j, p, "min_deg", true)) || !r.floats(*v, p + ".min_deg", 3, &l.eulerMin.x)) return false;
    if (!(v = r.member(j, p, "max_deg", true)) || !r.floats(*v, p + ".max_deg", 3, &l.eulerMax.x)) return false;
    l.eulerMin *= kDeg;
    l.eulerMax *= kDeg;
  } else {
    return r.fail(p + ".type", "'" + cutForMessage(type) + "' is not one of hinge, cone, euler");
  }
  const std::string bad = l.validate();
  if (!bad.empty()) return r.fail(p, bad);
  scene.ik.setLimit(scene.skeleton.size(), joint, l);
  return true;
}

bool readIkTarget(Reader& r, const Json& j, const std::string& p, Scene& scene) {
  if (!j.is_object()) return r.fail(p, "expected an object");
  IkTarget t;
  const Json* v;
  if (!readJointName(r, j, p, "effector", scene.skeleton, true, t.effector) ||
      !readJointName(r, j, p, "root", scene.skeleton, false, t.root) ||
      !readJointName(r, j, p, "mid", scene.skeleton, false, t.mid))
    return false;
  if (!(v = r.member(j, p, "position", true)) || !r.floats(*v, p + ".position", 3, &t.position.x)) return false;
  if ((v = r.member(j, p, "orientation", false))) {
    float q[4];
    if (!r.floats(*v, p + ".orientation", 4, q)) return false;
    if (q[0] == 0 && q[1] == 0 && q[2] == 0 && q[3] == 0) return r.fail(p + ".orientation", "zero quaternion");
    t.hasOrientation = true;
    t.orientation = normalizeIfNeeded(glm::quat(q[3], q[0], q[1], q[2]));
  }
  if ((v = r.member(j, p, "pole", false))) {
    if (!r.floats(*v, p + ".pole", 3, &t.pole.x)) return false;
    t.hasPole = true;
  }
  if ((v = r.member(j, p, "weight", false))) {
    double w = 0.0;
    if (!r.number(*v, p + ".weight", w)) return false;
    if (!(w > 0.0)) return r.fail(p + ".weight", "must be positive");
    t.weight = static_cast<float>(w);
  }
  const std::string bad = t.validate(scene.skeleton);
  if (!bad.empty()) return r.fail(p, bad);
  // Editor options, all optional: solver, chain_length, pinned, active.
  IkTargetOptions o;
  bool hasOptions = false;
  if ((v = r.member(j, p, "solver", false))) {
    const std::optional<IkSolver> solver = v->is_string() ? ikSolverFromString(v->get<std::string>()) : std::nullopt;
    if (!solver) return r.fail(p + ".solver", "expected a solver name (two-bone, ccd, fabrik, jacobian-dls, ...)");
    o.solver = *solver;
    hasOptions = true;
  }
  if ((v = r.member(j, p, "chain_length", false))) {
    double n = 0.0;
    if (!r.number(*v, p + ".chain_length", n)) return false;
    if (!(n >= 0.0 && n <= 1e6 && n == static_cast<double>(static_cast<long>(n))))
      return r.fail(p + ".chain_length", "expected a whole number >= 0");
    o.chainLength = static_cast<int>(n);
    hasOptions = true;
  }
  for (const char* key : {"pinned", "active"}) {
    if (!(v = r.member(j, p, key, false))) continue;
    if (!v->is_boolean()) return r.fail(p + "." + key, "expected true or false");
    (key[0] == 'p' ? o.pinned : o.active) = v->get<bool>();
    hasOptions = true;
  }
  scene.ik.targets.push_back(t);
  // targetOptions is empty until some target has options; then one per target, defaults elsewhere.
  if (hasOptions || !scene.ik.targetOptions.empty()) scene.ik.targetOptions.resize(scene.ik.targets.size());
  if (hasOptions) scene.ik.targetOptions.back() = o;
  return true;
}

// Reads {"limits": [...], "targets": [...]} at JSON path `at` ("ik" in .kinema files).
bool readIkObject(Reader& r, const Json& ik, const std::string& at, Scene& scene) {
  if (!ik.is_object()) return r.fail(at, "expected an object");
  for (const char* key : {"limits", "targets"}) {
    const Json* list = r.member(ik, at, key, false);
    if (!list) continue;
    const std::string p = at.empty() ? std::string(key) : at + "." + key;
    if (!list->is_array()) return r.fail(p, "expected an array");
    for (size_t i = 0; i < list->size(); ++i) {
      const std::string ip = p + "[" + std::to_string(i) + "]";
      if (key[0] == 'l' ? !readLimit(r, (*list)[i], ip, scene) : !readIkTarget(r, (*list)[i], ip, scene)) return false;
    }
  }
  return true;
}

bool readIk(Reader& r, const Json& root, Scene& scene) {
  const Json* ik = r.member(root, "", "ik", false);
  return !ik || readIkObject(r, *ik, "ik", scene);
}

// ---- simulation settings: dynamic chains and ragdolls (the optional "simulation" key) ----

bool readOptionalFloat(Reader& r, const Json& obj, const std::string& p, const char* key, float lo, float hi,
                       const char* range, float& out) {
  const Json* v = r.member(obj, p, key, false);
  if (!v) return true;
  double d = 0.0;
  if (!r.number(*v, p + "." + key, d)) return false;
  if (!(d >= lo && d <= hi)) return r.fail(p + "." + key, std::string("must be ") + range);
  out = static_cast<float>(d);
  return true;
}

constexpr float kHuge = 1e30f;

bool readSpringCollider(Reader& r, const Json& j, const std::string& p, const Skeleton& s, SpringCollider& k) {
  if (!j.is_object()) return r.fail(p, "expected an object");
  if (!readJointName(r, j, p, "joint", s, false, k.joint)) return false;
  const Json* v;
  if (!(v = r.member(j, p, "a", true)) || !r.floats(*v, p + ".a", 3, &k.a.x)) return false;
  if (!(v = r.member(j, p, "b", true)) || !r.floats(*v, p + ".b", 3, &k.b.x)) return false;
  if (!r.member(j, p, "radius", true)) return false;
  return readOptionalFloat(r, j, p, "radius", 1e-30f, kHuge, "above 0", k.radius);
}

bool readSpringChain(Reader& r, const Json& j, const std::string& p, const Skeleton& s, SpringBoneChain& c) {
  if (!j.is_object()) return r.fail(p, "expected an object");
  const Json* v;
  if ((v = r.member(j, p, "name", false)) && !r.string(*v, p + ".name", c.name)) return false;
  if (!(v = r.member(j, p, "joints", true))) return false;
  if (!v->is_array() || v->empty()) return r.fail(p + ".joints", "expected a non-empty array of joint names");
  for (size_t i = 0; i < v->size(); ++i) {
    const std::string ip = p + ".joints[" + std::to_string(i) + "]";
    std::string name;
    if (!r.string((*v)[i], ip, name)) return false;
    const int joint = r.joint(s, name);
    if (joint < 0) return r.fail(ip, "no joint named '" + cutForMessage(name) + "'");
    if (i > 0 && s.parents[joint] != c.joints.back())
      return r.fail(ip, "'" + cutForMessage(name) + "' is not a child of '" + cutForMessage(s.names[c.joints.back()]) +
                            "' (a chain runs parent to child)");
    c.joints.push_back(joint);
  }
  if (!readOptionalFloat(r, j, p, "stiffness", 0.0f, kHuge, ">= 0", c.stiffness) ||
      !readOptionalFloat(r, j, p, "damping", 0.0f, kHuge, ">= 0", c.damping) ||
      !readOptionalFloat(r, j, p, "drag", 0.0f, kHuge, ">= 0", c.drag) ||
      !readOptionalFloat(r, j, p, "radius", 0.0f, kHuge, ">= 0", c.radius))
    return false;
  if ((v = r.member(j, p, "gravity", false)) && !r.floats(*v, p + ".gravity", 3, &c.gravity.x)) return false;
  if ((v = r.member(j, p, "colliders", false))) {
    if (!v->is_array()) return r.fail(p + ".colliders", "expected an array");
    for (size_t i = 0; i < v->size(); ++i) {
      SpringCollider k;
      if (!readSpringCollider(r, (*v)[i], p + ".colliders[" + std::to_string(i) + "]", s, k)) return false;
      c.colliders.push_back(k);
    }
  }
  return true;
}

bool readRagdoll(Reader& r, const Json& j, const std::string& p, const Skeleton& s, RagdollSettings& d) {
  if (!j.is_object()) return r.fail(p, "expected an object");
  const Json* v;
  if ((v = r.member(j, p, "name", false)) && !r.string(*v, p + ".name", d.name)) return false;
  if (!readJointName(r, j, p, "root", s, true, d.root)) return false;
  if ((v = r.member(j, p, "start_frame", false))) {
    if (!r.integer(*v, p + ".start_frame", d.startFrame)) return false;
    if (d.startFrame < 0 || d.startFrame > 1000000000LL) return r.fail(p + ".start_frame", "must be 0 to 1000000000");
  }
  if ((v = r.member(j, p, "gravity", false)) && !r.floats(*v, p + ".gravity", 3, &d.gravity.x)) return false;
  return readOptionalFloat(r, j, p, "mass", 1e-30f, kHuge, "above 0", d.mass) &&
         readOptionalFloat(r, j, p, "ground_height", -kHuge, kHuge, "a float", d.groundHeight) &&
         readOptionalFloat(r, j, p, "friction", 0.0f, kHuge, ">= 0", d.friction) &&
         readOptionalFloat(r, j, p, "restitution", 0.0f, 1.0f, "0 to 1", d.restitution) &&
         readOptionalFloat(r, j, p, "damping", 0.0f, 1.0f, "0 to 1", d.damping);
}

bool readSimulation(Reader& r, const Json& root, Scene& scene) {
  const Json* sim = r.member(root, "", "simulation", false);
  if (!sim) return true;
  if (!sim->is_object()) return r.fail("simulation", "expected an object");
  const Skeleton& s = scene.skeleton;
  SimulationSettings out;
  for (const char* key : {"spring_chains", "ragdolls"}) {
    const Json* list = r.member(*sim, "simulation", key, false);
    if (!list) continue;
    const std::string p = std::string("simulation.") + key;
    if (!list->is_array()) return r.fail(p, "expected an array");
    for (size_t i = 0; i < list->size(); ++i) {
      const std::string ip = p + "[" + std::to_string(i) + "]";
      if (key[0] == 's') {
        SpringBoneChain c;
        if (!readSpringChain(r, (*list)[i], ip, s, c)) return false;
        out.springChains.push_back(std::move(c));
      } else {
        RagdollSettings d;
        if (!readRagdoll(r, (*list)[i], ip, s, d)) return false;
        out.ragdolls.push_back(std::move(d));
      }
    }
  }
  if (const Json* crowds = r.member(*sim, "simulation", "crowds", false)) {  // io/kinema_crowds.h
    std::string path, what;
    if (!readCrowdsJson(*crowds, "simulation.crowds", out.crowds, path, what)) return r.fail(path, what);
  }
  if (const Json* list = r.member(*sim, "simulation", "particles", false)) {
    std::string where, what;
    if (!readParticleSystems(*list, "simulation.particles", s, out.particles, where, what)) return r.fail(where, what);
  }
  // What one part cannot see: a joint in two chains, ragdolls that overlap.
  if (std::string e = out.validate(s); !e.empty()) return r.fail("simulation", e);
  scene.simulation = std::move(out);
  return true;
}

Json simulationToJson(const Scene& scene) {
  const Skeleton& s = scene.skeleton;
  Json chains = Json::array();
  for (const SpringBoneChain& c : scene.simulation.springChains) {
    Json j;
    j["name"] = c.name;
    Json joints = Json::array();
    for (int joint : c.joints) joints.push_back(s.names[joint]);
    j["joints"] = std::move(joints);
    j["stiffness"] = jsonFloat(c.stiffness);
    j["damping"] = jsonFloat(c.damping);
    j["drag"] = jsonFloat(c.drag);
    j["gravity"] = vec(&c.gravity.x, 3);
    j["radius"] = jsonFloat(c.radius);
    Json colliders = Json::array();
    for (const SpringCollider& k : c.colliders) {
      Json kj;
      if (k.joint >= 0) kj["joint"] = s.names[k.joint];
      kj["a"] = vec(&k.a.x, 3);
      kj["b"] = vec(&k.b.x, 3);
      kj["radius"] = jsonFloat(k.radius);
      colliders.push_back(std::move(kj));
    }
    j["colliders"] = std::move(colliders);
    chains.push_back(std::move(j));
  }
  Json ragdolls = Json::array();
  for (const RagdollSettings& d : scene.simulation.ragdolls) {
    Json j;
    j["name"] = d.name;
    j["root"] = s.names[d.root];
    j["start_frame"] = d.startFrame;
    j["mass"] = jsonFloat(d.mass);
    j["gravity"] = vec(&d.gravity.x, 3);
    j["ground_height"] = jsonFloat(d.groundHeight);
    j["friction"] = jsonFloat(d.friction);
    j["restitution"] = jsonFloat(d.restitution);
    j["damping"] = jsonFloat(d.damping);
    ragdolls.push_back(std::move(j));
  }
  Json sim;
  sim["spring_chains"] = std::move(chains);
  sim["ragdolls"] = std::move(ragdolls);
  if (!scene.simulation.crowds.empty()) sim["crowds"] = crowdsToJson(scene.simulation.crowds);
  if (!scene.simulation.particles.empty()) sim["particles"] = particleSystemsToJson(scene.simulation.particles, s);
  return sim;
}

// ---- the editor's working pose (optional top-level "pose" key) ----
// [{"joint": NAME, "translation": [3], "rotation": [x, y, z, w], "scale": [3]}, ...]; a
// member or a joint left out keeps its rest value.
bool readPose(Reader& r, const Json& root, Scene& scene) {
  const Json* list = r.member(root, "", "pose", false);
  if (!list) return true;
  if (!list->is_array()) return r.fail("pose", "expected an array");
  const Skeleton& s = scene.skeleton;
  Pose pose = Pose::rest(s);
  std::vector<bool> seen(s.size(), false);
  for (size_t i = 0; i < list->size(); ++i) {
    const std::string p = "pose[" + std::to_string(i) + "]";
    const Json& j = (*list)[i];
    if (!j.is_object()) return r.fail(p, "expected an object");
    int joint = -1;
    if (!readJointName(r, j, p, "joint", s, true, joint)) return false;
    if (seen[joint]) return r.fail(p + ".joint", "joint '" + cutForMessage(s.names[joint]) + "' is listed twice");
    seen[joint] = true;
    if (!readTransform(r, j, p, pose.local[joint])) return false;
  }
  scene.pose = std::move(pose);
  return true;
}

// ---- the editor's playhead (optional top-level "playhead" key) ----
// {"clip": INDEX, "time": SECONDS}: the clip must exist (0 when the file has none), the
// time be finite.
bool readPlayhead(Reader& r, const Json& root, Scene& scene) {
  const Json* object = r.member(root, "", "playhead", false);
  if (!object) return true;
  if (!object->is_object()) return r.fail("playhead", "expected an object");
  ScenePlayhead playhead;
  long long clip = 0;
  const Json* v;
  if (!(v = r.member(*object, "playhead", "clip", true)) || !r.integer(*v, "playhead.clip", clip)) return false;
  const long long clips = static_cast<long long>(scene.clips.size());
  if (clip < 0 || (clip >= clips && clip != 0))
    return r.fail("playhead.clip", std::to_string(clip) + " is not a clip of the file (it has " + std::to_string(clips) + ")");
  playhead.clip = static_cast<int>(clip);
  if (!(v = r.member(*object, "playhead", "time", true)) || !r.number(*v, "playhead.time", playhead.time)) return false;
  scene.playhead = playhead;
  return true;
}

// ---- the document's frame rate (optional top-level "frame_rate" key) ----
// Frames per second, kMinFrameRate..kMaxFrameRate; absent: kDefaultFrameRate.
bool readFrameRate(Reader& r, const Json& root, Scene& scene) {
  const Json* v = r.member(root, "", "frame_rate", false);
  if (!v) return true;
  double rate = 0.0;
  if (!r.number(*v, "frame_rate", rate)) return false;
  if (!(rate >= kMinFrameRate && rate <= kMaxFrameRate)) return r.fail("frame_rate", "must be 1 to 1000 frames per second");
  scene.frameRate = rate;
  return true;
}

Json poseToJson(const Scene& scene) {
  Json list = Json::array();
  for (int i = 0; i < scene.pose.size(); ++i) {
    const Transform& t = scene.pose.local[i];
    Json j;
    j["joint"] = scene.skeleton.names[i];
    writeTransform(t, j);
    list.push_back(std::move(j));
  }
  return list;
}

Json degrees(const float* v, int n) {
  float d[3];
  for (int i = 0; i < n; ++i) d[i] = v[i] / kDeg;
  if (n == 1) return Json(jsonFloat(d[0]));
  return vec(d, n);
}

Json ikToJson(const Scene& scene) {
  const Skeleton& s = scene.skeleton;
  Json limits = Json::array();
  for (size_t i = 0; i < scene.ik.limits.size(); ++i) {
    const JointLimit& l = scene.ik.limits[i];
    if (!l.active()) continue;
    Json j;
    j["joint"] = s.names[i];
    j["type"] = toString(l.type);
    if (l.type == JointLimitType::Euler) {
      j["order"] = toString(l.order);
      j["min_deg"] = degrees(&l.eulerMin.x, 3);
      j["max_deg"] = degrees(&l.eulerMax.x, 3);
    } else {
      j["axis"] = vec(&l.axis.x, 3);
      if (l.type == JointLimitType::Hinge) {
        j["min_deg"] = degrees(&l.minAngle, 1);
        j["max_deg"] = degrees(&l.maxAngle, 1);
      } else {
        j["cone_deg"] = degrees(&l.coneAngle, 1);
        j["twist_min_deg"] = degrees(&l.twistMin, 1);
        j["twist_max_deg"] = degrees(&l.twistMax, 1);
      }
    }
    limits.push_back(std::move(j));
  }
  Json targets = Json::array();
  for (size_t ti = 0; ti < scene.ik.targets.size(); ++ti) {
    const IkTarget& t = scene.ik.targets[ti];
    Json j;
    j["effector"] = s.names[t.effector];
    if (t.root >= 0) j["root"] = s.names[t.root];
    if (t.mid >= 0) j["mid"] = s.names[t.mid];
    j["position"] = vec(&t.position.x, 3);
    if (t.hasOrientation) {
      const float q[4] = {t.orientation.x, t.orientation.y, t.orientation.z, t.orientation.w};
      j["orientation"] = vec(q, 4);
    }
    if (t.hasPole) j["pole"] = vec(&t.pole.x, 3);
    j["weight"] = jsonFloat(t.weight);
    if (ti < scene.ik.targetOptions.size()) {
      const IkTargetOptions& o = scene.ik.targetOptions[ti];
      j["solver"] = toString(o.solver);
      j["chain_length"] = o.chainLength;
      j["pinned"] = o.pinned;
      j["active"] = o.active;
    }
    targets.push_back(std::move(j));
  }
  Json ik;
  ik["limits"] = std::move(limits);
  ik["targets"] = std::move(targets);
  return ik;
}

// An enum named by a string, with the list of accepted names in the error.
template <typename E>
bool readEnum(Reader& r, const Json& j, const std::string& path, E& out, const char* accepted) {
  std::string text;
  if (!r.string(j, path, text)) return false;
  if (!fromString(text, out)) return r.fail(path, "'" + cutForMessage(text) + "' is not one of " + accepted);
  return true;
}

const char* const kInterpolationNames = "step, linear, hermite, catmull-rom, tcb, bezier, ease, nlerp, squad";
const char* const kHandleNames = "free, aligned, vector, auto, auto-clamped";

bool readFloat(Reader& r, const Json& j, const std::string& path, float& out) {
  double v = 0.0;
  if (!r.number(j, path, v)) return false;
  if (std::abs(v) >= kFloatOverflow) return r.fail(path, "number out of float range");
  out = static_cast<float>(v);
  return true;
}

// Per-key settings: every member is optional and defaults to KeySettings' default, so a
// writer may leave out whatever equals the default.
bool readKeySettings(Reader& r, const Json& j, const std::string& p, int n, KeySettings& k) {
  if (!j.is_object()) return r.fail(p, "expected an object");
  const Json* v;
  if ((v = r.member(j, p, "interpolation", false)) &&
      !readEnum(r, *v, p + ".interpolation", k.interpolation, kInterpolationNames))
    return false;
  if ((v = r.member(j, p, "easing", false)) &&
      !readEnum(r, *v, p + ".easing", k.easing, "sine, quad, cubic, quart, quint, expo, circ, back, bounce, elastic"))
    return false;
  if ((v = r.member(j, p, "easing_mode", false)) && !readEnum(r, *v, p + ".easing_mode", k.easingMode, "in, out, in-out"))
    return false;
  if ((v = r.member(j, p, "tension", false)) && !readFloat(r, *v, p + ".tension", k.tension)) return false;
  if ((v = r.member(j, p, "continuity", false)) && !readFloat(r, *v, p + ".continuity", k.continuity)) return false;
  if ((v = r.member(j, p, "bias", false)) && !readFloat(r, *v, p + ".bias", k.bias)) return false;
  if ((v = r.member(j, p, "in_tangent", false)) && !r.floats(*v, p + ".in_tangent", n, &k.inTangent.x)) return false;
  if ((v = r.member(j, p, "out_tangent", false)) && !r.floats(*v, p + ".out_tangent", n, &k.outTangent.x)) return false;
  if ((v = r.member(j, p, "left_handle_type", false)) &&
      !readEnum(r, *v, p + ".left_handle_type", k.leftHandleType, kHandleNames))
    return false;
  if ((v = r.member(j, p, "right_handle_type", false)) &&
      !readEnum(r, *v, p + ".right_handle_type", k.rightHandleType, kHandleNames))
    return false;
  if ((v = r.member(j, p, "left_handle_time", false)) && !readFloat(r, *v, p + ".left_handle_time", k.leftHandleTime))
    return false;
  if (k.leftHandleTime > 0) return r.fail(p + ".left_handle_time", "must not be positive (seconds before the key)");
  if ((v = r.member(j, p, "right_handle_time", false)) &&
      !readFloat(r, *v, p + ".right_handle_time", k.rightHandleTime))
    return false;
  if (k.rightHandleTime < 0) return r.fail(p + ".right_handle_time", "must not be negative (seconds after the key)");
  if ((v = r.member(j, p, "left_handle_value", false)) && !r.floats(*v, p + ".left_handle_value", n, &k.leftHandleValue.x))
    return false;
  if ((v = r.member(j, p, "right_handle_value", false)) &&
      !r.floats(*v, p + ".right_handle_value", n, &k.rightHandleValue.x))
    return false;
  return true;
}

bool isRotationMode(Interpolation i) { return i == Interpolation::Nlerp || i == Interpolation::Squad; }
bool onlyVectorMode(Interpolation i) { return i == Interpolation::CatmullRom || i == Interpolation::TCB; }

bool checkMode(Reader& r, const std::string& path, Interpolation i, ChannelTarget t) {
  if (t == ChannelTarget::Rotation && onlyVectorMode(i))
    return r.fail(path, std::string("'") + toString(i) +
                            "' does not apply to rotation (use bezier, linear, nlerp, squad, hermite, ease or step)");
  if (t != ChannelTarget::Rotation && isRotationMode(i))
    return r.fail(path, std::string("'") + toString(i) + "' applies to rotation channels only");
  return true;
}

// channels[k].modifiers: the channel's modifier stack (anim/channel_modifier.h), in order.
// Every parameter is optional and defaults to the modifier's default; a wave without
// "rest_position" takes the joint's rest position from the file's skeleton.
const char* const kComponentLetters = "xyzw";

bool readComponents(Reader& r, const Json& j, const std::string& path, uint32_t& mask) {
  std::string text;
  if (!r.string(j, path, text)) return false;
  mask = 0;
  for (char c : text) {
    const char* at = c ? std::strchr(kComponentLetters, c) : nullptr;
    if (!at || (mask & (1u << (at - kComponentLetters))))
      return r.fail(path, "'" + cutForMessage(text) + "' is not a set of distinct letters from x, y, z, w");
    mask |= 1u << (at - kComponentLetters);
  }
  if (!mask) return r.fail(path, "names no component (letters from x, y, z, w)");
  return true;
}

bool readBoundedInt(Reader& r, const Json& j, const std::string& path, long long lo, long long hi, long long& out) {
  if (!r.integer(j, path, out)) return false;
  if (out < lo || out > hi)
    return r.fail(path, std::to_string(out) + " is out of range (" + std::to_string(lo) + " to " + std::to_string(hi) + ")");
  return true;
}

bool readModifier(Reader& r, const Json& j, const std::string& p, const Skeleton& s, int joint, ChannelModifier& m) {
  if (!j.is_object()) return r.fail(p, "expected an object");
  const Json* v;
  if (!(v = r.member(j, p, "type", true)) || !readEnum(r, *v, p + ".type", m.kind, "noise, cycles, wave")) return false;
  if ((v = r.member(j, p, "enabled", false))) {
    if (!v->is_boolean()) return r.fail(p + ".enabled", "expected true or false, found " + std::string(v->type_name()));
    m.enabled = v->get<bool>();
  }
  if ((v = r.member(j, p, "components", false)) && !readComponents(r, *v, p + ".components", m.components)) return false;
  long long n = 0;
  switch (m.kind) {
    case ChannelModifierKind::Noise:
      if ((v = r.member(j, p, "strength", false)) && !readFloat(r, *v, p + ".strength", m.noise.strength)) return false;
      if (m.noise.strength < 0) return r.fail(p + ".strength", "must not be negative");
      if ((v = r.member(j, p, "scale", false)) && !readFloat(r, *v, p + ".scale", m.noise.scale)) return false;
      if (!(m.noise.scale > 0)) return r.fail(p + ".scale", "must be positive (seconds per noise cell)");
      if ((v = r.member(j, p, "phase", false)) && !readFloat(r, *v, p + ".phase", m.noise.phase)) return false;
      if ((v = r.member(j, p, "octaves", false))) {
        if (!readBoundedInt(r, *v, p + ".octaves", 1, 8, n)) return false;
        m.noise.octaves = static_cast<int>(n);
      }
      if ((v = r.member(j, p, "roughness", false)) && !readFloat(r, *v, p + ".roughness", m.noise.roughness)) return false;
      if (!(m.noise.roughness >= 0 && m.noise.roughness <= 1)) return r.fail(p + ".roughness", "must be in [0, 1]");
      if ((v = r.member(j, p, "seed", false))) {
        if (!readBoundedInt(r, *v, p + ".seed", 0, UINT32_MAX, n)) return false;
        m.noise.seed = static_cast<uint32_t>(n);
      }
      break;
    case ChannelModifierKind::Cycles: {
      const char* const modes = "hold, repeat, repeat_offset, mirror";
      if ((v = r.member(j, p, "before", false)) && !readEnum(r, *v, p + ".before", m.cycles.before, modes)) return false;
      if ((v = r.member(j, p, "after", false)) && !readEnum(r, *v, p + ".after", m.cycles.after, modes)) return false;
      if ((v = r.member(j, p, "before_count", false))) {
        if (!readBoundedInt(r, *v, p + ".before_count", 0, INT_MAX, n)) return false;
        m.cycles.beforeCount = static_cast<int>(n);
      }
      if ((v = r.member(j, p, "after_count", false))) {
        if (!readBoundedInt(r, *v, p + ".after_count", 0, INT_MAX, n)) return false;
        m.cycles.afterCount = static_cast<int>(n);
      }
      break;
    }
    case ChannelModifierKind::Wave:
      if ((v = r.member(j, p, "amplitude", false)) && !readFloat(r, *v, p + ".amplitude", m.wave.amplitude)) return false;
      if ((v = r.member(j, p, "omega", false)) && !readFloat(r, *v, p + ".omega", m.wave.omega)) return false;
      if ((v = r.member(j, p, "k", false)) && !r.floats(*v, p + ".k", 3, &m.wave.k.x)) return false;
      if ((v = r.member(j, p, "phi", false)) && !readFloat(r, *v, p + ".phi", m.wave.phi)) return false;
      if ((v = r.member(j, p, "rest_position", false))) {
        if (!r.floats(*v, p + ".rest_position", 3, &m.wave.position.x)) return false;
      } else if (joint >= 0 && joint < s.size()) {
        m.wave.position = glm::vec3(computeWorld(s, Pose::rest(s))[joint][3]);
      }
      break;
  }
  // Anything the checks above let through (none today) is still caught here, with the path.
  if (std::string bad = m.validate(); !bad.empty()) return r.fail(p, bad);
  return true;
}

bool readModifiers(Reader& r, const Json& j, const std::string& p, const Skeleton& s, Channel& ch) {
  if (!j.is_array()) return r.fail(p, "expected an array of modifier objects");
  ch.modifiers.resize(j.size());
  for (size_t i = 0; i < j.size(); ++i)
    if (!readModifier(r, j[i], p + "[" + std::to_string(i) + "]", s, ch.joint, ch.modifiers[i])) return false;
  if (std::string bad = validateModifierStack(ch.modifiers); !bad.empty()) return r.fail(p, bad);
  return true;
}

bool readChannel(Reader& r, const Json& j, const std::string& p, const Skeleton& s, Channel& ch) {
  if (!j.is_object()) return r.fail(p, "expected an object");
  const Json* v;
  std::string text;
  if (!(v = r.member(j, p, "target", true)) ||
      !readEnum(r, *v, p + ".target", ch.target, "translation, rotation, scale, euler, scalar"))
    return false;
  // Scalar channels may belong to no joint.
  const bool scalar = ch.target == ChannelTarget::Scalar;
  if ((v = r.member(j, p, "joint", !scalar))) {
    if (!r.string(*v, p + ".joint", text)) return false;
    ch.joint = r.joint(s, text);
    if (ch.joint < 0) return r.fail(p + ".joint", "no joint named '" + cutForMessage(text) + "'");
  } else if (!scalar) {
    return false;
  }
  if ((v = r.member(j, p, "property", false)) && !r.string(*v, p + ".property", ch.property)) return false;
  if ((v = r.member(j, p, "euler_order", false))) {
    if (!r.string(*v, p + ".euler_order", text)) return false;
    const std::optional<EulerOrder> order = eulerOrderFromString(text);
    if (!order) return r.fail(p + ".euler_order", "'" + cutForMessage(text) + "' is not one of XYZ, XZY, YXZ, YZX, ZXY, ZYX");
    ch.eulerOrder = *order;
  }
  if ((v = r.member(j, p, "interpolation", false))) {
    if (!readEnum(r, *v, p + ".interpolation", ch.interpolation, kInterpolationNames)) return false;
    if (!checkMode(r, p + ".interpolation", ch.interpolation, ch.target)) return false;
  }
  const Json* times = r.member(j, p, "times", true);
  const Json* values = times ? r.member(j, p, "values", true) : nullptr;
  if (!values) return false;
  if (!times->is_array() || times->empty()) return r.fail(p + ".times", "expected a non-empty array of numbers");
  if (!values->is_array() || values->size() != times->size())
    return r.fail(p + ".values", "expected an array with one value per key time (" + std::to_string(times->size()) + ")");
  const int n = ch.valueSize();
  for (size_t k = 0; k < times->size(); ++k) {
    const std::string tp = p + ".times[" + std::to_string(k) + "]";
    double t = 0.0;
    if (!r.number((*times)[k], tp, t)) return false;
    if (std::abs(t) >= kFloatOverflow) return r.fail(tp, "number out of float range");
    if (k > 0 && !(static_cast<float>(t) > ch.times.back())) return r.fail(tp, "key times must increase");
    ch.times.push_back(static_cast<float>(t));
    glm::vec4 value(0.0f);
    if (!r.floats((*values)[k], p + ".values[" + std::to_string(k) + "]", n, &value.x)) return false;
    if (ch.target == ChannelTarget::Rotation) {
      // Checked before normalising: glm::normalize turns a zero quaternion into identity.
      if (value == glm::vec4(0.0f)) return r.fail(p + ".values[" + std::to_string(k) + "]", "zero quaternion");
      const glm::quat q = normalizeIfNeeded(glm::quat(value.w, value.x, value.y, value.z));
      value = glm::vec4(q.x, q.y, q.z, q.w);
    }
    ch.values.push_back(value);
  }
  if ((v = r.member(j, p, "keys", false))) {
    if (!v->is_array() || v->size() != times->size())
      return r.fail(p + ".keys", "expected an array with one object per key time (" + std::to_string(times->size()) + ")");
    KeySettings base;
    base.interpolation = ch.interpolation;
    ch.keys.assign(times->size(), base);
    for (size_t k = 0; k < v->size(); ++k) {
      const std::string kp = p + ".keys[" + std::to_string(k) + "]";
      if (!readKeySettings(r, (*v)[k], kp, n, ch.keys[k])) return false;
      if (!checkMode(r, kp + ".interpolation", ch.keys[k].interpolation, ch.target)) return false;
    }
  }
  if ((v = r.member(j, p, "modifiers", false)) && !readModifiers(r, *v, p + ".modifiers", s, ch)) return false;
  return true;
}

// clips[c].foot_contacts: {"left": [[first, last], ...], "right": [...]} in frames, each list
// in order without overlaps (FootContacts::validate).
bool readFootContacts(Reader& r, const Json& j, const std::string& p, FootContacts& out) {
  if (!j.is_object()) return r.fail(p, "expected an object with \"left\" and \"right\" lists");
  for (int f = 0; f < 2; ++f) {
    const char* side = toString(static_cast<Foot>(f));
    const Json* list = r.member(j, p, side, false);
    if (!list) continue;
    const std::string lp = p + "." + side;
    if (!list->is_array()) return r.fail(lp, "expected an array of [first, last] frame pairs");
    for (size_t i = 0; i < list->size(); ++i) {
      const std::string ip = lp + "[" + std::to_string(i) + "]";
      const Json& pair = (*list)[i];
      if (!pair.is_array() || pair.size() != 2) return r.fail(ip, "expected [first, last] (two frame numbers)");
      long long frame[2];
      for (int k = 0; k < 2; ++k) {
        if (!r.integer(pair[k], ip + "[" + std::to_string(k) + "]", frame[k])) return false;
        if (frame[k] < 0 || frame[k] > INT_MAX)
          return r.fail(ip + "[" + std::to_string(k) + "]", "frame " + std::to_string(frame[k]) + " is outside 0.." +
                                                                 std::to_string(INT_MAX));
      }
      if (frame[1] < frame[0]) return r.fail(ip, "ends (frame " + std::to_string(frame[1]) + ") before it starts (frame " +
                                                     std::to_string(frame[0]) + ")");
      std::vector<ContactInterval>& foot = out.feet[f];
      if (!foot.empty() && frame[0] <= foot.back().last)
        return r.fail(ip, "starts at frame " + std::to_string(frame[0]) + ", not after the previous contact ends (frame " +
                              std::to_string(foot.back().last) + ")");
      foot.push_back(ContactInterval{static_cast<int>(frame[0]), static_cast<int>(frame[1])});
    }
  }
  return true;
}

// clips[c].bone_map: {"file": PATH, "clip": I, "pairs": [[source name, target joint], ...]}.
bool readSourceMap(Reader& r, const Json& j, const std::string& p, const Skeleton& s, ClipSourceMap& out) {
  if (!j.is_object()) return r.fail(p, "expected an object");
  const Json* v;
  if ((v = r.member(j, p, "file", false)) && !r.string(*v, p + ".file", out.file)) return false;
  if ((v = r.member(j, p, "clip", false))) {
    long long clip = 0;
    if (!r.integer(*v, p + ".clip", clip)) return false;
    if (clip < 0 || clip > INT_MAX) return r.fail(p + ".clip", "clip " + std::to_string(clip) + " is outside 0.." + std::to_string(INT_MAX));
    out.clip = static_cast<int>(clip);
  }
  const Json* pairs = r.member(j, p, "pairs", true);
  if (!pairs) return false;
  if (!pairs->is_array() || pairs->empty())
    return r.fail(p + ".pairs", "expected a non-empty array of [source joint, target joint] pairs");
  std::unordered_set<std::string> sources;
  std::unordered_set<int> targets;
  for (size_t i = 0; i < pairs->size(); ++i) {
    const std::string ip = p + ".pairs[" + std::to_string(i) + "]";
    const Json& pair = (*pairs)[i];
    if (!pair.is_array() || pair.size() != 2) return r.fail(ip, "expected [source joint, target joint] (two names)");
    SourceMapPair sp;
    std::string target;
    if (!r.string(pair[0], ip + "[0]", sp.source) || !r.string(pair[1], ip + "[1]", target)) return false;
    if (sp.source.empty()) return r.fail(ip + "[0]", "empty source joint name");
    sp.target = r.joint(s, target);
    if (sp.target < 0) return r.fail(ip + "[1]", "no joint named '" + cutForMessage(target) + "'");
    // Sets, not a scan of the earlier pairs: a file may map a 200,000-joint skeleton.
    if (!sources.insert(sp.source).second)
      return r.fail(ip + "[0]", "source joint '" + cutForMessage(sp.source) + "' is mapped twice");
    if (!targets.insert(sp.target).second) return r.fail(ip + "[1]", "joint '" + cutForMessage(target) + "' is mapped twice");
    out.pairs.push_back(std::move(sp));
  }
  return true;
}

bool readClips(Reader& r, const Json& root, Scene& scene) {
  const Json* clips = r.member(root, "", "clips", false);
  if (!clips) return true;
  if (!clips->is_array()) return r.fail("clips", "expected an array");
  for (size_t c = 0; c < clips->size(); ++c) {
    const std::string p = "clips[" + std::to_string(c) + "]";
    const Json& j = (*clips)[c];
    if (!j.is_object()) return r.fail(p, "expected an object");
    Clip clip;
    const Json* v;
    if ((v = r.member(j, p, "name", false)) && !r.string(*v, p + ".name", clip.name)) return false;
    if ((v = r.member(j, p, "frame_time", false))) {
      if (!r.number(*v, p + ".frame_time", clip.frameTime)) return false;
      if (clip.frameTime < 0) return r.fail(p + ".frame_time", "must not be negative");
    }
    if ((v = r.member(j, p, "loop", false))) {
      if (!v->is_boolean()) return r.fail(p + ".loop", "expected true or false, found " + std::string(v->type_name()));
      clip.loop = v->get<bool>();
    }
    if ((v = r.member(j, p, "range", false))) {
      float range[2];
      if (!r.floats(*v, p + ".range", 2, range)) return false;
      if (range[0] > range[1]) return r.fail(p + ".range", "start comes after end");
      clip.hasRange = true;
      clip.rangeStart = range[0];
      clip.rangeEnd = range[1];
    }
    const Json* channels = r.member(j, p, "channels", true);
    if (!channels) return false;
    if (!channels->is_array()) return r.fail(p + ".channels", "expected an array");
    long long keys = 0;  // counted before any channel is read
    for (const Json& c : *channels)
      if (const Json* t = c.is_object() && c.contains("times") ? &c["times"] : nullptr; t && t->is_array())
        keys += static_cast<long long>(t->size());
    if (keys > r.limits.maxKeys)
      return r.fail(p + ".channels", limitExceeded(keys, r.limits.maxKeys, "keys", "maxKeys"));
    for (size_t k = 0; k < channels->size(); ++k) {
      Channel ch;
      if (!readChannel(r, (*channels)[k], p + ".channels[" + std::to_string(k) + "]", scene.skeleton, ch))
        return false;
      clip.channels.push_back(std::move(ch));
    }
    if ((v = r.member(j, p, "foot_contacts", false)) && !readFootContacts(r, *v, p + ".foot_contacts", clip.contacts))
      return false;
    if ((v = r.member(j, p, "bone_map", false)) &&
        !readSourceMap(r, *v, p + ".bone_map", scene.skeleton, clip.sourceMap))
      return false;
    scene.clips.push_back(std::move(clip));
  }
  return true;
}

// ---- Meshes, skins, materials and images (optional top-level keys; glTF scenes) ----
// Vertex data are flat number arrays (x, y, z, x, y, z, ...); joints are named as in
// channels; images are base64 PNG. See docs/kinema-format.md.

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

// A channel's modifier stack: every parameter of each modifier's kind is written, so the
// file says exactly what plays; "enabled" only when false, "components" only when not xyz.
Json modifiersJson(const std::vector<ChannelModifier>& stack) {
  Json list = Json::array();
  for (const ChannelModifier& m : stack) {
    Json o = Json::object();
    o["type"] = toString(m.kind);
    if (!m.enabled) o["enabled"] = false;
    if (m.components != ChannelModifier().components) {
      std::string letters;
      for (int c = 0; c < 4; ++c)
        if (m.components & (1u << c)) letters += kComponentLetters[c];
      o["components"] = letters;
    }
    switch (m.kind) {
      case ChannelModifierKind::Noise:
        o["strength"] = jsonFloat(m.noise.strength);
        o["scale"] = jsonFloat(m.noise.scale);
        o["phase"] = jsonFloat(m.noise.phase);
        o["octaves"] = m.noise.octaves;
        o["roughness"] = jsonFloat(m.noise.roughness);
        o["seed"] = m.noise.seed;
        break;
      case ChannelModifierKind::Cycles:
        o["before"] = toString(m.cycles.before);
        o["after"] = toString(m.cycles.after);
        o["before_count"] = m.cycles.beforeCount;
        o["after_count"] = m.cycles.afterCount;
        break;
      case ChannelModifierKind::Wave:
        o["amplitude"] = jsonFloat(m.wave.amplitude);
        o["omega"] = jsonFloat(m.wave.omega);
        o["k"] = vec(&m.wave.k.x, 3);
        o["phi"] = jsonFloat(m.wave.phi);
        o["rest_position"] = vec(&m.wave.position.x, 3);
        break;
    }
    list.push_back(std::move(o));
  }
  return list;
}

// A channel; per-key settings list only what differs from KeySettings' defaults (which
// the reader fills in), so simple keys stay small and every setting round-trips exactly.
Json channelJson(const Channel& ch, const Skeleton& s) {
  const int n = ch.valueSize();
  Json k;
  if (ch.joint >= 0) k["joint"] = s.names[ch.joint];
  k["target"] = toString(ch.target);
  if (!ch.property.empty()) k["property"] = ch.property;
  if (ch.target == ChannelTarget::Euler) k["euler_order"] = toString(ch.eulerOrder);
  k["interpolation"] = toString(ch.interpolation);
  Json times = Json::array(), values = Json::array();
  for (float t : ch.times) times.push_back(jsonFloat(t));
  for (const glm::vec4& v : ch.values) values.push_back(vec(&v.x, n));
  k["times"] = std::move(times);
  k["values"] = std::move(values);
  if (!ch.keys.empty()) {
    KeySettings d;
    d.interpolation = ch.interpolation;
    Json keys = Json::array();
    for (const KeySettings& ks : ch.keys) {
      Json o = Json::object();
      if (ks.interpolation != d.interpolation) o["interpolation"] = toString(ks.interpolation);
      if (ks.easing != d.easing) o["easing"] = toString(ks.easing);
      if (ks.easingMode != d.easingMode) o["easing_mode"] = toString(ks.easingMode);
      if (ks.tension != d.tension) o["tension"] = jsonFloat(ks.tension);
      if (ks.continuity != d.continuity) o["continuity"] = jsonFloat(ks.continuity);
      if (ks.bias != d.bias) o["bias"] = jsonFloat(ks.bias);
      if (ks.inTangent != d.inTangent) o["in_tangent"] = vec(&ks.inTangent.x, n);
      if (ks.outTangent != d.outTangent) o["out_tangent"] = vec(&ks.outTangent.x, n);
      if (ks.leftHandleType != d.leftHandleType) o["left_handle_type"] = toString(ks.leftHandleType);
      if (ks.rightHandleType != d.rightHandleType) o["right_handle_type"] = toString(ks.rightHandleType);
      if (ks.leftHandleTime != d.leftHandleTime) o["left_handle_time"] = jsonFloat(ks.leftHandleTime);
      if (ks.rightHandleTime != d.rightHandleTime) o["right_handle_time"] = jsonFloat(ks.rightHandleTime);
      if (ks.leftHandleValue != d.leftHandleValue) o["left_handle_value"] = vec(&ks.leftHandleValue.x, n);
      if (ks.rightHandleValue != d.rightHandleValue) o["right_handle_value"] = vec(&ks.rightHandleValue.x, n);
      keys.push_back(std::move(o));
    }
    k["keys"] = std::move(keys);
  }
  // Only channels that carry modifiers get the key, so files without them are unchanged.
  if (!ch.modifiers.empty()) k["modifiers"] = modifiersJson(ch.modifiers);
  return k;
}

}  // namespace

std::string toKinemaJson(const Scene& scene) {
  Json root;
  root["format"] = "kinema";
  root["version"] = kKinemaFormatVersion;
  Json joints = Json::array();
  const Skeleton& s = scene.skeleton;
  for (int i = 0; i < s.size(); ++i) {
    const Transform& t = s.rest[i];
    Json j;
    j["name"] = s.names[i];
    j["parent"] = s.parents[i];
    writeTransform(t, j);
    joints.push_back(std::move(j));
  }
  root["skeleton"]["joints"] = std::move(joints);
  Json clips = Json::array();
  for (const Clip& clip : scene.clips) {
    Json c;
    c["name"] = clip.name;
    if (clip.frameTime > 0) c["frame_time"] = clip.frameTime;
    if (clip.loop) c["loop"] = true;
    if (clip.hasRange) {
      const float range[2] = {clip.rangeStart, clip.rangeEnd};
      c["range"] = vec(range, 2);
    }
    Json channels = Json::array();
    for (const Channel& ch : clip.channels) channels.push_back(channelJson(ch, s));
    c["channels"] = std::move(channels);
    // Optional: what the retargeting and the timeline's contact edits left on the clip.
    if (!clip.contacts.empty()) {
      Json contacts = Json::object();
      for (int f = 0; f < 2; ++f) {
        Json list = Json::array();
        for (const ContactInterval& ci : clip.contacts.feet[f]) list.push_back(Json::array({ci.first, ci.last}));
        contacts[toString(static_cast<Foot>(f))] = std::move(list);
      }
      c["foot_contacts"] = std::move(contacts);
    }
    if (!clip.sourceMap.empty()) {
      Json pairs = Json::array();
      for (const SourceMapPair& sp : clip.sourceMap.pairs) pairs.push_back(Json::array({sp.source, s.names[sp.target]}));
      c["bone_map"] = {{"file", clip.sourceMap.file}, {"clip", clip.sourceMap.clip}, {"pairs", std::move(pairs)}};
    }
    clips.push_back(std::move(c));
  }
  root["clips"] = std::move(clips);
  // Optional: written when it is not the default, so files of other rates keep theirs.
  if (scene.frameRate != kDefaultFrameRate) root["frame_rate"] = scene.frameRate;
  // Optional: the editor's working pose; files without one load as the rest pose.
  if (!scene.pose.local.empty()) root["pose"] = poseToJson(scene);
  // Optional: where the timeline stood; the time as a double, which JSON keeps exactly.
  if (scene.playhead) root["playhead"] = {{"clip", scene.playhead->clip}, {"time", scene.playhead->time}};
  if (!scene.ik.empty()) root["ik"] = ikToJson(scene);  // optional: files without IK data stay as they were
  if (!scene.simulation.empty()) root["simulation"] = simulationToJson(scene);  // optional, as "ik"
  sceneAssetsToJson(scene, root);  // optional too: only scenes with meshes (glTF) have them
  return collapseNumberArrays(root.dump(1, '\t')) + "\n";
}

namespace {

// The scene in a parsed .kinema tree; `inputBytes` (the file's size) sets its image budget.
Result<Scene> readKinemaTree(const Json& root, const std::string& source, const InputLimits& limits, size_t inputBytes);

}  // namespace

Result<Scene> parseKinemaJson(const std::string& text, const std::string& source, const InputLimits& limits) {
  Json root;
  if (std::string e = parseJsonDocument(text, source, limits, root); !e.empty()) return Result<Scene>::failure(e);
  return readKinemaTree(root, source, limits, text.size());
}

namespace {

Result<Scene> readKinemaTree(const Json& root, const std::string& source, const InputLimits& limits, size_t inputBytes) {
  Reader r(source, limits, inputBytes);
  if (!root.is_object()) return Result<Scene>::failure(source + ": expected a JSON object at the top");
  std::string format;
  const Json* v;
  if (!(v = r.member(root, "", "format", true)) || !r.string(*v, "format", format))
    return Result<Scene>::failure(r.error());
  if (format != "kinema")
    return Result<Scene>::failure(oneLineMessage(source + ": format: expected \"kinema\", found \"" + cutForMessage(format) + "\""));
  long long version = 0;
  if (!(v = r.member(root, "", "version", true)) || !r.integer(*v, "version", version))
    return Result<Scene>::failure(r.error());
  if (version > kKinemaFormatVersion)
    return Result<Scene>::failure(oneLineMessage(source + ": version: the file is version " + std::to_string(version) +
                                          ", newer than this Kinema reads (up to version " +
                                          std::to_string(kKinemaFormatVersion) + "); update Kinema to open it"));
  if (version < 1)
    return Result<Scene>::failure(oneLineMessage(source + ": version: " + std::to_string(version) +
                                          " is not a Kinema format version (they start at 1)"));
  Scene scene;
  scene.source = source;
  if (!readSkeleton(r, root, scene.skeleton) || !readClips(r, root, scene))
    return Result<Scene>::failure(r.error());
  if (!readIk(r, root, scene)) return Result<Scene>::failure(r.error());
  if (!readSimulation(r, root, scene)) return Result<Scene>::failure(r.error());
  if (!readPose(r, root, scene)) return Result<Scene>::failure(r.error());
  if (!readPlayhead(r, root, scene)) return Result<Scene>::failure(r.error());
  if (!readFrameRate(r, root, scene)) return Result<Scene>::failure(r.error());
  if (!readSceneAssets(r, root, scene)) return Result<Scene>::failure(r.error());
  const std::string bad = scene.skeleton.validate();
  if (!bad.empty()) return Result<Scene>::failure(oneLineMessage(source + ": skeleton: " + bad));
  return scene;
}

}  // namespace

Result<IkRig> parseIkRigJson(const std::string& text, const std::string& source, const Skeleton& skeleton) {
  const InputLimits limits;
  Json root;
  if (std::string e = parseJsonDocument(text, source, limits, root); !e.empty()) return Result<IkRig>::failure(e);
  Reader r(source);
  Scene scene;
  scene.skeleton = skeleton;
  if (!readIkObject(r, root, "", scene)) return Result<IkRig>::failure(r.error());
  return std::move(scene.ik);
}

Result<Scene> loadKinemaFile(const std::string& path, const InputLimits& limits) {
  std::string text;
  const std::string error = readTextFile(path, text, limits.maxFileBytes);
  if (!error.empty()) return Result<Scene>::failure(error);
  Json root;
  if (std::string e = parseJsonDocument(text, path, limits, root); !e.empty()) return Result<Scene>::failure(e);
  const size_t inputBytes = text.size();
  std::string().swap(text);  // the tree holds it all now: the text's memory goes before the scene is built
  return readKinemaTree(root, path, limits, inputBytes);
}

std::string saveKinemaFile(const std::string& path, const Scene& scene) {
  std::string bad = scene.skeleton.validate();
  if (bad.empty())
    for (size_t c = 0; c < scene.clips.size() && bad.empty(); ++c) {
      bad = scene.clips[c].validate(scene.skeleton);
      if (!bad.empty()) bad = "clip " + std::to_string(c) + ": " + bad;
    }
  // JSON text is UTF-8 (our readers convert Latin-1 names; a caller may not have).
  for (int i = 0; i < scene.skeleton.size() && bad.empty(); ++i)
    if (!isValidUtf8(scene.skeleton.names[i])) bad = "joint " + std::to_string(i) + " name is not valid UTF-8";
  for (size_t c = 0; c < scene.clips.size() && bad.empty(); ++c)
    if (!isValidUtf8(scene.clips[c].name)) bad = "clip " + std::to_string(c) + " name is not valid UTF-8";
  if (bad.empty() && !scene.ik.empty()) {
    bad = scene.ik.validate(scene.skeleton);
    if (!bad.empty()) bad = "ik: " + bad;
  }
  if (bad.empty() && !scene.simulation.empty()) {
    bad = scene.simulation.validate(scene.skeleton);
    if (!bad.empty()) bad = "simulation: " + bad;
  }
  if (bad.empty() && !scene.pose.local.empty()) {
    bad = scene.pose.validate(scene.skeleton);
    if (!bad.empty()) bad = "pose: " + bad;
  }
  if (bad.empty() && scene.playhead) {
    const int clips = static_cast<int>(scene.clips.size());
    if (!std::isfinite(scene.playhead->time)) bad = "playhead: the time is not finite";
    else if (scene.playhead->clip < 0 || (scene.playhead->clip >= clips && scene.playhead->clip != 0))
      bad = "playhead: clip " + std::to_string(scene.playhead->clip) + " does not exist";
  }
  if (bad.empty()) bad = sceneAssetsError(scene);
  if (!bad.empty()) return oneLine(path + ": not saved: " + bad);
  std::string text;
  try {
    // An image that failed to decode on loading (with a warning) is left out, not refused.
    text = hasUndecodedImages(scene) ? toKinemaJson(withoutUndecodedImages(scene)) : toKinemaJson(scene);
  } catch (const Json::exception& e) {
    return oneLine(path + ": not saved: " + e.what());
  }
  return writeFileAtomically(path, text);
}

}  // namespace kinema
