#pragma once
// The .kinema file's crowds (simulation.crowds; docs/kinema-format.md): reading with one-line
// errors that name the JSON path of the bad value, and writing (an exact round trip).
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "sim/crowd_settings.h"

namespace kinema {

// Reads the array `list` found at JSON path `at` ("simulation.crowds"). On failure returns
// false with `errorPath` (the JSON path of the bad value) and `errorWhat` (what is wrong).
bool readCrowdsJson(const nlohmann::ordered_json& list, const std::string& at, std::vector<CrowdSettings>& out,
                    std::string& errorPath, std::string& errorWhat);
nlohmann::ordered_json crowdsToJson(const std::vector<CrowdSettings>& crowds);

}  // namespace kinema
