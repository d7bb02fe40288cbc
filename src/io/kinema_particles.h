#pragma once
// The .kinema "simulation.particles" array (docs/kinema-format.md): particle systems read
// and written with an exact round trip. Called from io/kinema_file_simulation.cpp.
#include <string>
#include <vector>
#include <nlohmann/json.hpp>

#include "sim/particle_system.h"

namespace kinema {

// Reads `list` (found at JSON path `path`, e.g. "simulation.particles") into `out`. On a
// problem returns false with `errorPath` the JSON path of the bad value and `error` what is
// wrong with it (one line, no path).
bool readParticleSystems(const nlohmann::ordered_json& list, const std::string& path, const Skeleton& skeleton,
                         std::vector<ParticleSystemSettings>& out, std::string& errorPath, std::string& error);
nlohmann::ordered_json particleSystemsToJson(const std::vector<ParticleSystemSettings>& systems, const Skeleton& skeleton);

}  // namespace kinema
