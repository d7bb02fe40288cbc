#include "cli/command_line.h"

#include <algorithm>
#include <cstdlib>
#include <CLI/CLI.hpp>
#include <iostream>

#include "anim/channel_modifiers.h"
#include "evaluation/scene_evaluation_job.h"
#include "scene/default_character_scene.h"
#include "io/json_number.h"
#include "io/scene_files.h"

namespace kinema::cli {

int usageError(const std::string& subcommand, const std::string& message) {
  std::cerr << "kinema " << subcommand << ": " << message << "; see --help\n";
  return kExitUsage;
}

int badInput(const std::string& message) {
  std::cerr << "kinema: " << message << "\n";
  return kExitBadInput;
}

Result<Scene> loadSceneOrDefault(const std::string& path, const InputLimits& limits, UpAxis bvhUp) {
  if (!path.empty()) return loadScene(path, limits, bvhUp);
  return makeDefaultCharacterScene();
}

CLI::Option* addUpOption(CLI::App* cmd, std::string& up) {
  return cmd
      ->add_option("--up", up,
                   "Up axis of BVH files: y (default, the BVH convention) or z (Blender's BVH export); other formats are Y-up")
      ->check(CLI::IsMember({"y", "z"}));
}

UpAxis upAxisOf(const std::string& up) { return upAxisFromString(up).value_or(UpAxis::Y); }

void addAllowOutsidePathsFlag(CLI::App* cmd, bool& allowOutsidePaths) {
  cmd->add_flag("--allow-outside-paths", allowOutsidePaths,
                "Let a .gltf's buffer and image uris name files outside its folder (devices, FIFOs and /proc stay refused)");
}

InputLimits inputLimits(bool allowOutsidePaths) {
  InputLimits limits;
  limits.allowOutsidePaths = allowOutsidePaths;
  return limits;
}

std::string clipIndexError(const Scene& scene, int clip) {
  const int clips = static_cast<int>(scene.clips.size());
  if (clip == 0 || (clip > 0 && clip < clips)) return {};
  return scene.source + ": --clip " + std::to_string(clip) + " does not exist (the file has " +
         std::to_string(clips) + " clip" + (clips == 1 ? "" : "s") + ")";
}

bool parseReduce(const std::string& text, double& pos, double& deg) {
  const size_t comma = text.find(',');
  auto number = [](const std::string& s, double& out) {
    if (s.empty()) return false;
    char* end = nullptr;
    out = std::strtod(s.c_str(), &end);
    return end == s.c_str() + s.size();
  };
  if (comma == std::string::npos) {
    deg = kDefaultReduceDegrees;
    return number(text, pos);
  }
  return number(text.substr(0, comma), pos) && number(text.substr(comma + 1), deg);
}

double contractTime(const Scene& scene, int clip, double time) {
  if (clip < 0 || clip >= static_cast<int>(scene.clips.size())) return time;
  const Clip& c = scene.clips[clip];
  // The contract clamps --time to the clip: keys clamp by themselves, but noise and
  // cycles go on past the last key, so a modified clip is evaluated at the clamped time.
  if (!hasChannelModifiers(c)) return time;
  float first = 0.0f;
  for (const Channel& ch : c.channels) first = std::min(first, ch.startTime());
  return std::clamp(time, double(first), double(std::max(first, c.duration())));
}

Pose sampledPose(const Scene& scene, int clip, double time) {
  return evaluatedPose(scene, clip, contractTime(scene, clip, time));  // every stage (evaluation/)
}

nlohmann::ordered_json jointsJson(const Skeleton& skeleton, const std::vector<glm::mat4>& world) {
  nlohmann::ordered_json joints = nlohmann::ordered_json::array();
  for (int i = 0; i < skeleton.size(); ++i) {
    nlohmann::ordered_json j;
    j["name"] = skeleton.names[i];
    j["parent"] = skeleton.parents[i];
    nlohmann::ordered_json m = nlohmann::ordered_json::array();
    const float* p = glm::value_ptr(world[i]);  // column-major, as glTF
    for (int k = 0; k < 16; ++k) m.push_back(jsonFloat(p[k]));
    j["world"] = std::move(m);
    joints.push_back(std::move(j));
  }
  return joints;
}

nlohmann::ordered_json jointsJson(const Scene& scene, const std::vector<glm::mat4>& world) {
  if (scene.nodeOfJoint.empty()) return jointsJson(scene.skeleton, world);
  const int n = scene.skeleton.size();
  std::vector<int> jointOfNode(n, -1);
  for (int j = 0; j < n; ++j) jointOfNode[scene.nodeOfJoint[j]] = j;
  nlohmann::ordered_json joints = nlohmann::ordered_json::array();
  for (int node = 0; node < n; ++node) {
    const int j = jointOfNode[node];
    const int parent = scene.skeleton.parents[j];
    const bool fileName = node < static_cast<int>(scene.nodeNames.size()) && !scene.nodeNames[node].empty();
    nlohmann::ordered_json e;
    e["name"] = fileName ? scene.nodeNames[node] : scene.skeleton.names[j];
    e["node"] = node;
    e["parent"] = parent < 0 ? -1 : scene.nodeOfJoint[parent];
    nlohmann::ordered_json m = nlohmann::ordered_json::array();
    const float* p = glm::value_ptr(world[j]);  // column-major, as glTF
    for (int k = 0; k < 16; ++k) m.push_back(jsonFloat(p[k]));
    e["world"] = std::move(m);
    joints.push_back(std::move(e));
  }
  return joints;
}

}  // namespace kinema::cli
