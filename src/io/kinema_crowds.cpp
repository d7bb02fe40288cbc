#include "io/kinema_crowds.h"

#include <cmath>

#include "io/json_number.h"

namespace kinema {

namespace {

using Json = nlohmann::ordered_json;

// Reads one crowd; each check fails with the path of the value it looked at.
class CrowdReader {
 public:
  std::string path, what;

  bool fail(const std::string& p, const std::string& w) {
    path = p;
    what = w;
    return false;
  }
  bool number(const Json& obj, const std::string& p, const char* key, double lo, double hi, const char* range,
              float& out) {
    auto it = obj.find(key);
    if (it == obj.end()) return true;
    const std::string kp = p + "." + key;
    if (!it->is_number()) return fail(kp, "expected a number");
    const double d = it->get<double>();
    if (!std::isfinite(d) || d < lo || d > hi) return fail(kp, std::string("must be ") + range);
    out = static_cast<float>(d);
    return true;
  }
  bool integer(const Json& obj, const std::string& p, const char* key, long long lo, long long hi, int& out) {
    auto it = obj.find(key);
    if (it == obj.end()) return true;
    const std::string kp = p + "." + key;
    if (!it->is_number_integer()) return fail(kp, "expected a whole number");
    const long long v = it->is_number_unsigned() && it->get<unsigned long long>() > 1ull << 62
                            ? hi + 1
                            : it->get<long long>();
    if (v < lo || v > hi) return fail(kp, "must be " + std::to_string(lo) + " to " + std::to_string(hi));
    out = static_cast<int>(v);
    return true;
  }
  bool vec3(const Json& v, const std::string& p, glm::vec3& out) {
    if (!v.is_array() || v.size() != 3) return fail(p, "expected an array of 3 numbers");
    for (int i = 0; i < 3; ++i) {
      if (!v[i].is_number() || !std::isfinite(v[i].get<double>()) || std::abs(v[i].get<double>()) > 1e30)
        return fail(p + "[" + std::to_string(i) + "]", "expected a finite number");
      out[i] = static_cast<float>(v[i].get<double>());
    }
    return true;
  }
  bool vec3(const Json& obj, const std::string& p, const char* key, glm::vec3& out) {
    auto it = obj.find(key);
    return it == obj.end() || vec3(*it, p + "." + key, out);
  }
  bool string(const Json& obj, const std::string& p, const char* key, std::string& out) {
    auto it = obj.find(key);
    if (it == obj.end()) return true;
    if (!it->is_string()) return fail(p + "." + key, "expected a string");
    out = it->get<std::string>();
    return true;
  }

  bool crowd(const Json& j, const std::string& p, CrowdSettings& c) {
    if (!j.is_object()) return fail(p, "expected an object");
    constexpr double kBig = 1e30;
    BoidsSettings& b = c.boids;
    if (!string(j, p, "name", c.name) || !string(j, p, "character", c.character) ||
        !integer(j, p, "clip", 0, 1000000, c.clip) || !integer(j, p, "members", 1, kCrowdMaxMembers, c.members) ||
        !vec3(j, p, "spawn_centre", c.spawnCentre) ||
        !number(j, p, "stride_speed", 0.0, kBig, ">= 0", c.strideSpeed) ||
        !number(j, p, "forward_degrees", -kBig, kBig, "a finite number", c.forwardDegrees) ||
        !number(j, p, "separation_distance", 1e-30, kBig, "above 0", b.separationDistance) ||
        !number(j, p, "neighbour_radius", 1e-30, kBig, "above 0", b.neighbourRadius) ||
        !number(j, p, "field_of_view_degrees", 1e-30, 360.0, "above 0 and at most 360", b.fieldOfViewDegrees) ||
        !number(j, p, "avoidance_distance", 0.0, kBig, ">= 0", b.avoidanceDistance) ||
        !number(j, p, "max_speed", 1e-30, kBig, "above 0", b.maxSpeed) ||
        !number(j, p, "cruise_speed", 0.0, kBig, ">= 0", b.cruiseSpeed) ||
        !number(j, p, "max_acceleration", 1e-30, kBig, "above 0", b.maxAcceleration))
      return false;
    if (auto it = j.find("seed"); it != j.end()) {
      if (!it->is_number_unsigned() && !(it->is_number_integer() && it->get<long long>() >= 0))
        return fail(p + ".seed", "expected a whole number >= 0");
      c.seed = it->get<uint64_t>();
    }
    if (auto it = j.find("debug_member"); it != j.end()) {
      if (!integer(j, p, "debug_member", 0, c.members - 1, c.debugMember)) return false;
    }
    if (auto it = j.find("weights"); it != j.end()) {
      const std::string wp = p + ".weights";
      if (!it->is_object()) return fail(wp, "expected an object");
      if (!number(*it, wp, "separation", 0.0, kBig, ">= 0", b.separationWeight) ||
          !number(*it, wp, "alignment", 0.0, kBig, ">= 0", b.alignmentWeight) ||
          !number(*it, wp, "cohesion", 0.0, kBig, ">= 0", b.cohesionWeight) ||
          !number(*it, wp, "avoidance", 0.0, kBig, ">= 0", b.avoidanceWeight) ||
          !number(*it, wp, "goal", 0.0, kBig, ">= 0", b.goalWeight))
        return false;
    }
    if (auto it = j.find("goal"); it != j.end()) {
      if (!it->is_null()) {
        if (!vec3(*it, p + ".goal", b.goal)) return false;
        b.hasGoal = true;
      }
    }
    if (auto it = j.find("allocation"); it != j.end()) {
      if (*it == "priority") b.allocation = AccelerationAllocation::Priority;
      else if (*it == "average") b.allocation = AccelerationAllocation::Average;
      else return fail(p + ".allocation", "expected \"priority\" or \"average\"");
    }
    if (auto it = j.find("obstacles"); it != j.end()) {
      const std::string op = p + ".obstacles";
      if (!it->is_object()) return fail(op, "expected an object");
      if (auto s = it->find("spheres"); s != it->end()) {
        if (!s->is_array()) return fail(op + ".spheres", "expected an array");
        for (size_t i = 0; i < s->size(); ++i) {
          const std::string sp = op + ".spheres[" + std::to_string(i) + "]";
          const Json& o = (*s)[i];
          if (!o.is_object()) return fail(sp, "expected an object");
          BoidSphere sphere;
          if (!o.contains("centre") || !o.contains("radius")) return fail(sp, "expected \"centre\" and \"radius\"");
          if (!vec3(o, sp, "centre", sphere.centre) || !number(o, sp, "radius", 1e-30, kBig, "above 0", sphere.radius))
            return false;
          b.spheres.push_back(sphere);
        }
      }
      if (auto s = it->find("boxes"); s != it->end()) {
        if (!s->is_array()) return fail(op + ".boxes", "expected an array");
        for (size_t i = 0; i < s->size(); ++i) {
          const std::string bp = op + ".boxes[" + std::to_string(i) + "]";
          const Json& o = (*s)[i];
          if (!o.is_object()) return fail(bp, "expected an object");
          BoidBox box;
          if (!o.contains("min") || !o.contains("max")) return fail(bp, "expected \"min\" and \"max\"");
          if (!vec3(o, bp, "min", box.min) || !vec3(o, bp, "max", box.max)) return false;
          if (box.min.x > box.max.x || box.min.y > box.max.y || box.min.z > box.max.z)
            return fail(bp, "min must not pass max on any axis");
          b.boxes.push_back(box);
        }
      }
    }
    b.planar = true;
    if (std::string e = c.validate(); !e.empty()) return fail(p, e);
    return true;
  }
};

Json vec3Json(const glm::vec3& v) { return Json::array({jsonFloat(v.x), jsonFloat(v.y), jsonFloat(v.z)}); }

}  // namespace

bool readCrowdsJson(const Json& list, const std::string& at, std::vector<CrowdSettings>& out, std::string& errorPath,
                    std::string& errorWhat) {
  CrowdReader r;
  if (!list.is_array()) {
    errorPath = at;
    errorWhat = "expected an array";
    return false;
  }
  for (size_t i = 0; i < list.size(); ++i) {
    CrowdSettings c;
    c.boids.planar = true;
    if (!r.crowd(list[i], at + "[" + std::to_string(i) + "]", c)) {
      errorPath = r.path;
      errorWhat = r.what;
      return false;
    }
    out.push_back(std::move(c));
  }
  return true;
}

Json crowdsToJson(const std::vector<CrowdSettings>& crowds) {
  Json list = Json::array();
  for (const CrowdSettings& c : crowds) {
    const BoidsSettings& b = c.boids;
    Json j;
    j["name"] = c.name;
    j["character"] = c.character;
    j["clip"] = c.clip;
    j["members"] = c.members;
    j["seed"] = c.seed;
    j["spawn_centre"] = vec3Json(c.spawnCentre);
    j["stride_speed"] = jsonFloat(c.strideSpeed);
    j["forward_degrees"] = jsonFloat(c.forwardDegrees);
    j["debug_member"] = c.debugMember;
    j["separation_distance"] = jsonFloat(b.separationDistance);
    j["neighbour_radius"] = jsonFloat(b.neighbourRadius);
    j["field_of_view_degrees"] = jsonFloat(b.fieldOfViewDegrees);
    j["weights"] = {{"separation", jsonFloat(b.separationWeight)}, {"alignment", jsonFloat(b.alignmentWeight)},
                    {"cohesion", jsonFloat(b.cohesionWeight)},     {"avoidance", jsonFloat(b.avoidanceWeight)},
                    {"goal", jsonFloat(b.goalWeight)}};
    j["avoidance_distance"] = jsonFloat(b.avoidanceDistance);
    j["max_speed"] = jsonFloat(b.maxSpeed);
    j["cruise_speed"] = jsonFloat(b.cruiseSpeed);
    j["max_acceleration"] = jsonFloat(b.maxAcceleration);
    if (b.hasGoal) j["goal"] = vec3Json(b.goal);
    j["allocation"] = b.allocation == AccelerationAllocation::Priority ? "priority" : "average";
    Json spheres = Json::array(), boxes = Json::array();
    for (const BoidSphere& s : b.spheres) spheres.push_back({{"centre", vec3Json(s.centre)}, {"radius", jsonFloat(s.radius)}});
    for (const BoidBox& x : b.boxes) boxes.push_back({{"min", vec3Json(x.min)}, {"max", vec3Json(x.max)}});
    j["obstacles"] = {{"spheres", std::move(spheres)}, {"boxes", std::move(boxes)}};
    list.push_back(std::move(j));
  }
  return list;
}

}  // namespace kinema
