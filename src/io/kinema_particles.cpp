#include "io/kinema_particles.h"

#include <cmath>
#include <cstdint>

#include "io/json_number.h"
#include "io/message_text.h"

namespace kinema {

using Json = nlohmann::ordered_json;

namespace {

constexpr float kHuge = 1e30f;

// Reads with the path of the value at hand; the first failure keeps its path and message.
struct ParticleReader {
  std::string path, error;

  bool fail(const std::string& p, const std::string& what) {
    path = p;
    error = what;
    return false;
  }
  static std::string at(const std::string& p, const char* key) { return p + "." + key; }
  const Json* member(const Json& obj, const std::string& p, const char* key, bool required) {
    const auto it = obj.find(key);
    if (it == obj.end()) {
      if (required) fail(at(p, key), "missing");
      return nullptr;
    }
    return &*it;
  }
  bool number(const Json& j, const std::string& p, double& out) {
    if (!j.is_number()) return fail(p, "expected a number, found " + std::string(j.type_name()));
    out = j.get<double>();
    if (!std::isfinite(out) || std::abs(out) > 3.4e38) return fail(p, "not a finite float");
    return true;
  }
  // An optional number in [lo, hi]; `range` says so in the message.
  bool optFloat(const Json& obj, const std::string& p, const char* key, float lo, float hi, const char* range, float& out) {
    const Json* v = member(obj, p, key, false);
    if (!v) return true;
    double d = 0.0;
    if (!number(*v, at(p, key), d)) return false;
    if (!(d >= lo && d <= hi)) return fail(at(p, key), std::string("must be ") + range);
    out = static_cast<float>(d);
    return true;
  }
  bool floats(const Json& j, const std::string& p, int n, float* out) {
    if (!j.is_array() || static_cast<int>(j.size()) != n)
      return fail(p, "expected an array of " + std::to_string(n) + " numbers");
    for (int i = 0; i < n; ++i) {
      double d = 0.0;
      if (!number(j[i], p + "[" + std::to_string(i) + "]", d)) return false;
      out[i] = static_cast<float>(d);
    }
    return true;
  }
  bool optVec3(const Json& obj, const std::string& p, const char* key, glm::vec3& out) {
    const Json* v = member(obj, p, key, false);
    return !v || floats(*v, at(p, key), 3, &out.x);
  }
  bool optBool(const Json& obj, const std::string& p, const char* key, bool& out) {
    const Json* v = member(obj, p, key, false);
    if (!v) return true;
    if (!v->is_boolean()) return fail(at(p, key), "expected true or false");
    out = v->get<bool>();
    return true;
  }
  bool optString(const Json& obj, const std::string& p, const char* key, std::string& out) {
    const Json* v = member(obj, p, key, false);
    if (!v) return true;
    if (!v->is_string()) return fail(at(p, key), "expected a string, found " + std::string(v->type_name()));
    out = v->get<std::string>();
    return true;
  }

  // {"mean": M, "spread": S, "distribution": "uniform" | "normal"}
  bool range(const Json& obj, const std::string& p, const char* key, float lo, RandomRange& out) {
    const Json* v = member(obj, p, key, false);
    if (!v) return true;
    const std::string q = at(p, key);
    if (!v->is_object()) return fail(q, "expected an object {\"mean\", \"spread\", \"distribution\"}");
    if (!optFloat(*v, q, "mean", lo, kHuge, lo == 0.0f ? ">= 0" : "a finite number", out.mean) ||
        !optFloat(*v, q, "spread", 0.0f, kHuge, ">= 0", out.spread))
      return false;
    std::string d = out.distribution == RandomDistribution::Normal ? "normal" : "uniform";
    if (!optString(*v, q, "distribution", d)) return false;
    if (d != "uniform" && d != "normal") return fail(at(q, "distribution"), "'" + cutForMessage(d) + "' is not uniform or normal");
    out.distribution = d == "normal" ? RandomDistribution::Normal : RandomDistribution::Uniform;
    return true;
  }

  bool surface(const Json& obj, const std::string& p, ParticleEmitter& e) {
    const Json* v = member(obj, p, "surface", true);
    if (!v) return false;
    const std::string q = at(p, "surface");
    if (!v->is_object()) return fail(q, "expected an object {\"positions\", \"indices\"}");
    const Json* pos = member(*v, q, "positions", true);
    if (!pos) return false;
    if (!pos->is_array() || pos->empty() || pos->size() % 3 != 0 || pos->size() > (size_t{3} << 22))
      return fail(at(q, "positions"), "expected x, y, z of each vertex (a flat array of 3 numbers a vertex)");
    e.surfacePositions.resize(pos->size() / 3);
    if (!floats(*pos, at(q, "positions"), static_cast<int>(pos->size()), &e.surfacePositions[0].x)) return false;
    const Json* idx = member(*v, q, "indices", true);
    if (!idx) return false;
    if (!idx->is_array() || idx->empty() || idx->size() % 3 != 0 || idx->size() > (size_t{3} << 22))
      return fail(at(q, "indices"), "expected whole triangles (3 vertex indices each)");
    for (size_t i = 0; i < idx->size(); ++i) {
      const Json& k = (*idx)[i];
      if (!k.is_number_integer() || k.get<long long>() < 0 || k.get<long long>() >= static_cast<long long>(e.surfacePositions.size()))
        return fail(at(q, "indices") + "[" + std::to_string(i) + "]",
                    "expected a vertex index 0 to " + std::to_string(e.surfacePositions.size() - 1));
      e.surfaceIndices.push_back(static_cast<uint32_t>(k.get<long long>()));
    }
    return true;
  }

  bool emitter(const Json& j, const std::string& p, const Skeleton& s, ParticleEmitter& e) {
    if (!j.is_object()) return fail(p, "expected an object");
    std::string kind;
    const Json* v = member(j, p, "kind", true);
    if (!v) return false;
    if (!v->is_string()) return fail(at(p, "kind"), "expected a string, found " + std::string(v->type_name()));
    kind = v->get<std::string>();
    if (kind == "point") e.shape = EmitterShape::Point;
    else if (kind == "sphere") e.shape = EmitterShape::Sphere;
    else if (kind == "mesh_surface") e.shape = EmitterShape::MeshSurface;
    else if (kind == "joint") e.shape = EmitterShape::Joint;
    else return fail(at(p, "kind"), "'" + cutForMessage(kind) + "' is not one of point, sphere, mesh_surface, joint");
    // The joint and the surface are kept whatever the kind (an editor may switch kinds and
    // back), required where the kind needs them.
    if ((v = member(j, p, "joint", e.shape == EmitterShape::Joint))) {
      if (!v->is_string()) return fail(at(p, "joint"), "expected a joint name");
      e.joint = s.find(v->get<std::string>());
      if (e.joint < 0) return fail(at(p, "joint"), "no joint named '" + cutForMessage(v->get<std::string>()) + "'");
    } else if (e.shape == EmitterShape::Joint) {
      return false;
    }
    if ((e.shape == EmitterShape::MeshSurface || j.contains("surface")) && !surface(j, p, e)) return false;
    if (!optBool(j, p, "along_normal", e.alongNormal)) return false;
    if (!optVec3(j, p, "position", e.position) || !optFloat(j, p, "radius", 1e-30f, kHuge, "above 0", e.radius) ||
        !optVec3(j, p, "direction", e.direction) ||
        !optFloat(j, p, "cone_deg", 0.0f, 180.0f, "0 to 180 (degrees)", e.coneDegrees) ||
        !range(j, p, "speed", 0.0f, e.speed) || !range(j, p, "rate", 0.0f, e.rate) ||
        !range(j, p, "lifetime", 0.0f, e.lifetime))
      return false;
    if (!(glm::length(e.direction) > 1e-6f)) return fail(at(p, "direction"), "must not be zero");
    return true;
  }

  bool forces(const Json& obj, const std::string& p, ParticleForces& f) {
    const Json* v = member(obj, p, "forces", false);
    if (!v) return true;
    const std::string q = at(p, "forces");
    if (!v->is_object()) return fail(q, "expected an object");
    if (!optVec3(*v, q, "gravity", f.gravity) || !optVec3(*v, q, "wind", f.wind) ||
        !optFloat(*v, q, "drag", 0.0f, kHuge, ">= 0 (per second)", f.drag) || !optBool(*v, q, "ground", f.ground) ||
        !optFloat(*v, q, "ground_height", -kHuge, kHuge, "a finite number", f.groundHeight) ||
        !optFloat(*v, q, "restitution", 0.0f, 1.0f, "0 to 1", f.restitution) ||
        !optFloat(*v, q, "friction", 0.0f, 1.0f, "0 to 1", f.friction))
      return false;
    const Json* list = member(*v, q, "spheres", false);
    if (!list) return true;
    if (!list->is_array()) return fail(at(q, "spheres"), "expected an array");
    for (size_t i = 0; i < list->size(); ++i) {
      const std::string sp = at(q, "spheres") + "[" + std::to_string(i) + "]";
      const Json& sj = (*list)[i];
      if (!sj.is_object()) return fail(sp, "expected an object {\"centre\", \"radius\"}");
      ParticleSphere sphere;
      if (!optVec3(sj, sp, "centre", sphere.centre)) return false;
      if (!member(sj, sp, "radius", true) || !optFloat(sj, sp, "radius", 1e-30f, kHuge, "above 0", sphere.radius)) return false;
      f.spheres.push_back(sphere);
    }
    return true;
  }

  bool system(const Json& j, const std::string& p, const Skeleton& s, ParticleSystemSettings& out) {
    if (!j.is_object()) return fail(p, "expected an object");
    if (!optString(j, p, "name", out.name)) return false;
    if (const Json* v = member(j, p, "seed", false)) {
      if (!v->is_number_integer() || (v->is_number_integer() && !v->is_number_unsigned() && v->get<long long>() < 0))
        return fail(at(p, "seed"), "expected a whole number 0 to 18446744073709551615");
      out.seed = v->get<uint64_t>();
    }
    if (const Json* v = member(j, p, "max_particles", false)) {
      if (!v->is_number_integer() || v->get<long long>() < 1 || v->get<long long>() > (1 << 22))
        return fail(at(p, "max_particles"), "expected a whole number 1 to 4194304");
      out.maxParticles = static_cast<int>(v->get<long long>());
    }
    const Json* list = member(j, p, "emitters", true);
    if (!list) return false;
    if (!list->is_array()) return fail(at(p, "emitters"), "expected an array");
    for (size_t i = 0; i < list->size(); ++i) {
      ParticleEmitter e;
      if (!emitter((*list)[i], at(p, "emitters") + "[" + std::to_string(i) + "]", s, e)) return false;
      out.emitters.push_back(std::move(e));
    }
    if (!forces(j, p, out.forces)) return false;
    if (const Json* d = member(j, p, "draw", false)) {
      const std::string q = at(p, "draw");
      if (!d->is_object()) return fail(q, "expected an object {\"style\", \"size\", \"colour\"}");
      std::string style = toString(out.style);
      if (!optString(*d, q, "style", style)) return false;
      if (style != "points" && style != "quads") return fail(at(q, "style"), "'" + cutForMessage(style) + "' is not points or quads");
      out.style = style == "points" ? ParticleDrawStyle::Points : ParticleDrawStyle::Quads;
      if (!optFloat(*d, q, "size", 1e-30f, 1e6f, "above 0 and at most 1e6", out.size)) return false;
      if (const Json* c = member(*d, q, "colour", false)) {
        if (!floats(*c, at(q, "colour"), 4, &out.colour.x)) return false;
        for (int k = 0; k < 4; ++k)
          if (!(out.colour[k] >= 0.0f && out.colour[k] <= 1.0f))
            return fail(at(q, "colour") + "[" + std::to_string(k) + "]", "must be 0 to 1");
      }
    }
    if (std::string bad = out.validate(s); !bad.empty()) return fail(p, bad);
    return true;
  }
};

Json vec(const float* v, int n) {
  Json a = Json::array();
  for (int i = 0; i < n; ++i) a.push_back(jsonFloat(v[i]));
  return a;
}

Json rangeJson(const RandomRange& r) {
  Json j;
  j["mean"] = jsonFloat(r.mean);
  j["spread"] = jsonFloat(r.spread);
  j["distribution"] = r.distribution == RandomDistribution::Normal ? "normal" : "uniform";
  return j;
}

}  // namespace

bool readParticleSystems(const Json& list, const std::string& path, const Skeleton& skeleton,
                         std::vector<ParticleSystemSettings>& out, std::string& errorPath, std::string& error) {
  ParticleReader r;
  if (!list.is_array()) {
    errorPath = path;
    error = "expected an array";
    return false;
  }
  for (size_t i = 0; i < list.size(); ++i) {
    ParticleSystemSettings s;
    if (!r.system(list[i], path + "[" + std::to_string(i) + "]", skeleton, s)) {
      errorPath = r.path;
      error = r.error;
      return false;
    }
    out.push_back(std::move(s));
  }
  return true;
}

Json particleSystemsToJson(const std::vector<ParticleSystemSettings>& systems, const Skeleton& skeleton) {
  Json list = Json::array();
  for (const ParticleSystemSettings& s : systems) {
    Json j;
    j["name"] = s.name;
    j["seed"] = s.seed;
    j["max_particles"] = s.maxParticles;
    Json emitters = Json::array();
    for (const ParticleEmitter& e : s.emitters) {
      Json ej;
      ej["kind"] = toString(e.shape);
      if (e.joint >= 0 && e.joint < skeleton.size()) ej["joint"] = skeleton.names[e.joint];
      ej["position"] = vec(&e.position.x, 3);
      ej["radius"] = jsonFloat(e.radius);
      if (!e.surfacePositions.empty() && !e.surfaceIndices.empty()) {
        Json positions = Json::array();
        for (const glm::vec3& q : e.surfacePositions)
          for (int k = 0; k < 3; ++k) positions.push_back(jsonFloat(q[k]));
        ej["surface"] = {{"positions", std::move(positions)}, {"indices", e.surfaceIndices}};
      }
      ej["along_normal"] = e.alongNormal;
      ej["direction"] = vec(&e.direction.x, 3);
      ej["cone_deg"] = jsonFloat(e.coneDegrees);
      ej["speed"] = rangeJson(e.speed);
      ej["rate"] = rangeJson(e.rate);
      ej["lifetime"] = rangeJson(e.lifetime);
      emitters.push_back(std::move(ej));
    }
    j["emitters"] = std::move(emitters);
    const ParticleForces& f = s.forces;
    Json fj;
    fj["gravity"] = vec(&f.gravity.x, 3);
    fj["wind"] = vec(&f.wind.x, 3);
    fj["drag"] = jsonFloat(f.drag);
    fj["ground"] = f.ground;
    fj["ground_height"] = jsonFloat(f.groundHeight);
    fj["restitution"] = jsonFloat(f.restitution);
    fj["friction"] = jsonFloat(f.friction);
    Json spheres = Json::array();
    for (const ParticleSphere& sphere : f.spheres)
      spheres.push_back(Json{{"centre", vec(&sphere.centre.x, 3)}, {"radius", jsonFloat(sphere.radius)}});
    fj["spheres"] = std::move(spheres);
    j["forces"] = std::move(fj);
    j["draw"] = {{"style", toString(s.style)}, {"size", jsonFloat(s.size)}, {"colour", vec(&s.colour.x, 4)}};
    list.push_back(std::move(j));
  }
  return list;
}

}  // namespace kinema
