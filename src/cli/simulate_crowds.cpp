#include "cli/simulate_crowds.h"

#include <algorithm>
#include <cstdio>

#include "io/json_number.h"
#include "bake/crowd_scene.h"

namespace kinema::cli {

std::string simulateCrowds(Scene& scene, const std::string& file, const std::string& ext, bool framesGiven,
                           long long first, long long last, const InputLimits& limits, CrowdSimulation& result,
                           bool drawn) {
  const bool kinemaOut = ext == ".kinema";
  const std::vector<CrowdSettings> crowds = scene.simulation.crowds;
  for (const CrowdSettings& crowd : crowds) {
    if (kinemaOut && !crowd.character.empty())
      return "crowd '" + crowd.name + "': its character is another file ('" + crowd.character +
             "'), so its members' clips do not fit this file's skeleton; write .gltf or .glb for it";
    Result<Scene> character = loadCrowdCharacter(crowd, scene, file, limits);
    if (!character) return character.error();
    const Clip& clip = character->clips[static_cast<size_t>(crowd.clip)];
    long long a = first, b = last;
    if (!framesGiven) {
      a = 0;
      b = std::max(0LL, character->frameGrid(crowd.clip).nearestFrame(clip.duration()));
    }
    std::fprintf(stderr, "kinema simulate: crowd '%s': %d members, frames %lld..%lld\n", crowd.name.c_str(),
                 crowd.members, a, b);
    Result<CrowdBake> bake = bakeCrowd(crowd, character.value(), a, b);
    if (!bake) return bake.error();
    nlohmann::ordered_json part;
    part["kind"] = "crowd";
    part["name"] = crowd.name;
    part["character"] = crowd.character.empty() ? file : crowd.character;
    part["clip"] = clip.name;
    part["members"] = crowd.members;
    part["frames"] = {a, b};
    part["steps"] = bake->run.frames;
    // What the crowd read from the clip: the ground speed of rate 1 and the way the character faces.
    part["strideSpeed"] = jsonFloat(bake->motion.naturalSpeed);
    part["forwardDegrees"] = jsonFloat(glm::degrees(bake->motion.forwardYaw));
    nlohmann::ordered_json names = nlohmann::ordered_json::array();
    for (const Clip& c : bake->clips) names.push_back(c.name);
    part[kinemaOut ? "clips" : "characters"] = std::move(names);
    result.parts.push_back(std::move(part));
    if (!kinemaOut || drawn) {
      appendCrowdCharacters(result.characters, crowd, character.value(), bake.value());
      appendCrowdObstacles(result.characters, crowd);
    }
    if (kinemaOut)
      for (Clip& c : bake->clips) scene.clips.push_back(std::move(c));
  }
  return "";
}

}  // namespace kinema::cli
