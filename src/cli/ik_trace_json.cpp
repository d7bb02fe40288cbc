#include "cli/ik_trace_json.h"

#include "io/json_number.h"

namespace kinema {

nlohmann::ordered_json ikTraceJson(const IkTrace& trace) {
  nlohmann::ordered_json steps = nlohmann::ordered_json::array();
  for (const IkTraceEntry& e : trace.entries) {
    nlohmann::ordered_json s;
    s["iteration"] = e.iteration;
    s["step"] = toString(e.step);
    if (e.joint >= 0) s["joint"] = e.joint;
    s["error"] = jsonFloat(e.error);
    nlohmann::ordered_json ps = nlohmann::ordered_json::array();
    for (const glm::vec3& p : e.positions) ps.push_back({jsonFloat(p.x), jsonFloat(p.y), jsonFloat(p.z)});
    s["positions"] = std::move(ps);
    steps.push_back(std::move(s));
  }
  return steps;
}

}  // namespace kinema
