#pragma once
// `kinema simulate` on a file's crowds (simulation.crowds; bake/crowd_scene.h).
#include <string>

#include <nlohmann/json.hpp>

#include "io/input_limits.h"
#include "scene/scene.h"

namespace kinema::cli {

struct CrowdSimulation {
  Scene characters;                     // every crowd as many skinned characters (glTF output)
  nlohmann::ordered_json parts = nlohmann::ordered_json::array();  // the report's part per crowd
};

// Runs and bakes every crowd of `scene` (read from `file`): frames first..last when
// `framesGiven`, else each crowd's clip's own frames. For a .kinema OUT each member's clip is
// appended to scene.clips (the crowd's character must then be the file's own); for glTF the
// members go into `result.characters`, also when `drawn` (--render draws that scene).
// Returns "" or the one-line reason it failed.
std::string simulateCrowds(Scene& scene, const std::string& file, const std::string& outExtension, bool framesGiven,
                           long long first, long long last, const InputLimits& limits, CrowdSimulation& result,
                           bool drawn = false);

}  // namespace kinema::cli
