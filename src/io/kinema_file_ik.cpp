// The .kinema file's "ik" section: joint limits and saved targets; angles are degrees in the
// file (as in the UI), radians in memory.
#include "io/kinema_file_sections.h"

#include <optional>

#include "core/math.h"
#include "io/json_number.h"

namespace kinema::kinema_format {

namespace {


bool readDegrees(Reader& r, const Json& obj, const std::string& p, const char* key, float& out) {
  const Json* v = r.member(obj, p, key, true);
  double d = 0.0;
  if (!v || !r.number(*v, p + "." + key, d)) return false;
  out = static_cast<float>(d) * kDegree;
  return true;
}

Json degrees(const float* v, int n) {
  float d[3];
  for (int i = 0; i < n; ++i) d[i] = v[i] / kDegree;
  if (n == 1) return Json(jsonFloat(d[0]));
  return vec(d, n);
}

}  // namespace

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
    l.eulerMin *= kDegree;
    l.eulerMax *= kDegree;
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

}  // namespace kinema::kinema_format
