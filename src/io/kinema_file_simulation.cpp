// The .kinema file's "simulation" section: dynamic chains and ragdolls here, crowds and
// particle systems through io/kinema_crowds.h and io/kinema_particles.h.
#include "io/kinema_file_sections.h"

#include "io/json_number.h"
#include "io/kinema_crowds.h"
#include "io/kinema_particles.h"

namespace kinema::kinema_format {

namespace {

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

}  // namespace

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

}  // namespace kinema::kinema_format
