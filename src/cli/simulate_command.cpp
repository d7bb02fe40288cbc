#include "cli/simulate_command.h"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <iostream>

#include "cli/command_line.h"
#include "cli/render_command.h"
#include "cli/simulate_crowds.h"
#include "cli/simulate_particles.h"
#include "core/math.h"
#include "io/bvh_writer.h"
#include "io/gltf_writer.h"
#include "io/json_number.h"
#include "io/kinema_file.h"
#include "io/scene_files.h"
#include "sim/baked_keys.h"
#include "sim/simulation_bake.h"

namespace kinema::cli {

namespace {



// "A:B" as two integers; false on any other text.
bool parseFrames(const std::string& text, long long& first, long long& last) {
  const size_t colon = text.find(':');
  if (colon == std::string::npos) return false;
  auto integer = [](const std::string& s, long long& out) {
    if (s.empty()) return false;
    char* end = nullptr;
    errno = 0;
    out = std::strtoll(s.c_str(), &end, 10);
    return errno == 0 && end == s.c_str() + s.size();
  };
  return integer(text.substr(0, colon), first) && integer(text.substr(colon + 1), last);
}


}  // namespace

CLI::App* addSimulateCommand(CLI::App& app, SimulateOptions& o) {
  CLI::App* cmd = app.add_subcommand(
      "simulate", "Bake a file's dynamic chains (spring bones) and ragdolls into keys on its clip, and run its crowds");
  cmd->add_option("file", o.file, "A .kinema file with simulation settings (docs/kinema-format.md)")->required();
  o.framesOption = cmd->add_option("--frames", o.frames, "Frame range A:B (inclusive) to simulate (default: the clip's frames)");
  cmd->add_option("--out", o.out, "The file to write: .kinema, .gltf, .glb or .bvh (replaced only on success)");
  cmd->add_option("--clip", o.clip, "The clip to bake into, by index (default 0; a file without clips gets one)");
  cmd->add_option("--reduce", o.reduce,
                  "POS[,DEG]: thin the baked keys, keeping every joint within POS file units and every rotation within "
                  "DEG degrees (default 0.5) at every frame (default: POS = 1/1000 of the character's size)");
  cmd->add_flag("--every-frame", o.everyFrame, "Keep a key per frame on the simulated joints (no key reduction)");
  cmd->add_flag("--json", o.json, "Print the report as JSON (each simulated part, steps, largest joint-limit excess)");
  addAllowOutsidePathsFlag(cmd, o.allowOutsidePaths);
  addSimulateRenderOptions(cmd, o);
  return cmd;
}

std::string saveSimulatedScene(const std::string& out, const Scene& scene, int clip, std::vector<std::string>& report) {
  SceneSaveOptions options;
  options.bvhClip = clip;
  options.bvhStages.dynamics = false;  // the clip holds the chains' bake: not simulated again
  return saveScene(out, scene, options, &report);
}

int runSimulate(const SimulateOptions& o) {
  if (o.out.empty() && o.render.empty()) {
    std::cerr << "kinema simulate: give --out FILE, --render DIR or both; see --help\n";
    return kExitUsage;
  }
  const std::string ext = lowerExtension(o.out);
  if (!o.out.empty() && !canSaveScene(o.out)) {
    std::cerr << "kinema simulate: cannot write '" << ext << "' files (use .kinema, .gltf, .glb or .bvh); see --help\n";
    return kExitUsage;
  }
  if (!o.render.empty() && !simulateRenderSyntaxOk(o)) return kExitUsage;
  long long first = 0, last = 0;
  const bool framesGiven = o.framesOption && o.framesOption->count() > 0;
  if (framesGiven && !parseFrames(o.frames, first, last)) {
    std::cerr << "kinema simulate: --frames takes A:B (whole numbers), e.g. 0:119; see --help\n";
    return kExitUsage;
  }
  double reducePos = 0.0, reduceDeg = 0.0;
  const bool customReduce = !o.reduce.empty();
  if (customReduce && !parseReduce(o.reduce, reducePos, reduceDeg)) {
    std::cerr << "kinema simulate: --reduce takes POS or POS,DEG (numbers), not '" << o.reduce << "'; see --help\n";
    return kExitUsage;
  }
  if (customReduce && o.everyFrame) {
    std::cerr << "kinema simulate: --reduce and --every-frame exclude each other; see --help\n";
    return kExitUsage;
  }
  if (customReduce && (!std::isfinite(reducePos) || !std::isfinite(reduceDeg) || reducePos <= 0.0 || reduceDeg <= 0.0))
    return badInput("--reduce " + o.reduce + ": both tolerances must be positive finite numbers");
  if (framesGiven && first < 0) return badInput("--frames " + o.frames + ": frames start at 0");
  if (framesGiven && last < first) return badInput("--frames " + o.frames + ": the first frame comes after the last");
  if (framesGiven && last - first > 1000000) return badInput("--frames " + o.frames + ": more than 1,000,001 frames");

  Result<Scene> loaded = loadScene(o.file, inputLimits(o.allowOutsidePaths));
  if (!loaded) return badInput(loaded.error());
  Scene scene = std::move(loaded.value());
  if (scene.simulation.empty())
    return badInput(o.file + ": has nothing to simulate (no simulation.spring_chains, simulation.ragdolls or "
                    "simulation.crowds or simulation.particles; see docs/kinema-format.md)");
  const bool crowds = !scene.simulation.crowds.empty();
  if (crowds && ext == ".bvh")
    return badInput(o.file + ": has crowds, and a BVH file holds one skeleton, not a crowd of characters; write "
                    ".kinema (a clip per member) or .gltf/.glb (a character per member)");
  if (std::string e = clipIndexError(scene, o.clip); !e.empty()) return badInput(e);
  const bool bakes = !scene.simulation.springChains.empty() || !scene.simulation.ragdolls.empty();
  if (!bakes && !crowds) {  // particles alone: played, nothing baked
    if (!framesGiven) defaultParticleFrames(scene, o.clip, first, last);
    return runParticlesOnly(o, scene, first, last);
  }
  if (scene.clips.empty()) {  // a still character: one clip to hold the keys, at the document's rate
    Clip clip;
    clip.name = "simulation";
    clip.frameTime = scene.frameGrid(-1).secondsPerFrame;
    scene.clips.push_back(clip);
  }
  const Clip& clip = scene.clips[o.clip];
  if (!framesGiven) {
    first = 0;
    last = std::max(0LL, scene.frameGrid(o.clip).nearestFrame(clip.duration()));
  }

  SimulationBakeInput in;
  in.skeleton = &scene.skeleton;
  in.clip = &clip;
  in.documentFrameRate = scene.frameRate;
  in.settings = &scene.simulation;
  in.rig = &scene.ik;
  if (!scene.meshes.empty()) {
    in.meshes = &scene.meshes;
    in.skins = &scene.skins;
    in.instances = &scene.meshInstances;
  }
  in.firstFrame = first;
  in.lastFrame = last;
  in.reduceKeys = !o.everyFrame;
  in.reduction = bakedKeyTolerances(scene.skeleton);
  if (customReduce) {
    in.reduction.positionTolerance = static_cast<float>(reducePos);
    in.reduction.angleTolerance = static_cast<float>(reduceDeg) * kDegree;
  }
  // Progress: a line per part when it starts, and every tenth of the frames.
  std::string current;
  long long lastShown = -1;
  const long long span = last - first + 1;
  in.progress = [&](const SimulatedPart& part, long long frame) {
    const std::string label = part.kind + " '" + part.name + "'";
    if (label != current) {
      current = label;
      lastShown = -1;
    }
    const long long done = frame - first + 1;
    const long long tenth = std::max(1LL, span / 10);
    if (done == span || lastShown < 0 || done - lastShown >= tenth) {
      std::fprintf(stderr, "kinema simulate: %s: frame %lld of %lld..%lld\n", label.c_str(), frame, first, last);
      lastShown = done;
    }
  };
  const bool bodies = !scene.simulation.springChains.empty() || !scene.simulation.ragdolls.empty();
  Result<SimulationBake> bake = bodies ? bakeSimulation(in) : Result<SimulationBake>(SimulationBake{});
  if (!bake) return badInput(o.file + ": " + bake.error());

  if (bodies) scene.clips[o.clip] = std::move(bake->clip);
  CrowdSimulation crowdRun;  // the crowds, after the chains and ragdolls: a crowd of this file's character moves with them
  if (crowds) {
    if (std::string e = simulateCrowds(scene, o.file, ext, framesGiven, first, last, inputLimits(o.allowOutsidePaths), crowdRun,
                                       !o.render.empty());
        !e.empty())
      return badInput(o.file + ": " + e);
  }
  std::vector<std::string> report;
  const bool gltf = ext == ".gltf" || ext == ".glb";
  if (gltf && crowds && bodies) report.push_back("the file's own character is left out: a crowd's glTF holds its members");
  const std::string error =
      o.out.empty() ? std::string() : saveSimulatedScene(o.out, gltf && crowds ? crowdRun.characters : scene, o.clip, report);
  for (const std::string& line : report) std::cerr << "kinema simulate: warning: " << line << "\n";
  if (!error.empty()) return badInput(error);
  // --render draws the crowd's members (and its obstacles) where the file has crowds.
  if (const int code = renderSimulatedFrames(o, crowds ? crowdRun.characters : scene, first, last); code != kExitOk)
    return code;

  if (o.json) {
    const Skeleton& s = scene.skeleton;
    nlohmann::ordered_json j;
    j["file"] = o.file;
    if (!o.out.empty()) j["out"] = o.out;
    j["clip"] = o.clip;
    j["frames"] = {first, last};
    nlohmann::ordered_json parts = nlohmann::ordered_json::array();
    long long steps = 0;
    float worst = 0.0f;
    for (const SimulatedPart& p : bake->parts) {
      nlohmann::ordered_json pj;
      pj["kind"] = p.kind;
      pj["name"] = p.name;
      nlohmann::ordered_json joints = nlohmann::ordered_json::array();
      for (int joint : p.joints) joints.push_back(s.names[joint]);
      pj["joints"] = std::move(joints);
      pj["frames"] = p.lastFrame >= p.firstFrame ? nlohmann::ordered_json{p.firstFrame, p.lastFrame}
                                                 : nlohmann::ordered_json::array();
      pj["steps"] = p.steps;
      if (p.kind == "ragdoll") pj["bodies"] = p.bodies;
      pj["largestLimitExcessDegrees"] = jsonFloat(p.largestLimitExcess / kDegree);
      if (p.worstJoint >= 0 && p.largestLimitExcess > 0.0f) pj["worstJoint"] = s.names[p.worstJoint];
      parts.push_back(std::move(pj));
      steps += p.steps;
      worst = std::max(worst, p.largestLimitExcess);
    }
    for (nlohmann::ordered_json& part : crowdRun.parts) parts.push_back(std::move(part));
    if (!scene.simulation.particles.empty())
      for (nlohmann::ordered_json& pj : particleReport(scene, o.clip, first, last)) {
        steps += pj["steps"].get<long long>();
        parts.push_back(std::move(pj));
      }
    j["parts"] = std::move(parts);
    j["steps"] = steps;
    j["largestLimitExcessDegrees"] = jsonFloat(worst / kDegree);
    j["keys"] = {{"before", bake->keysBefore}, {"after", bake->keysAfter}};
    if (!o.render.empty()) j["render"] = o.render;
    std::cout << j.dump(-1, ' ', false, nlohmann::ordered_json::error_handler_t::replace) << "\n";
  }
  return kExitOk;
}

}  // namespace kinema::cli
