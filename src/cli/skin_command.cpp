#include "cli/skin_command.h"

#include <cmath>
#include <cstdio>
#include <iostream>

#include "cli/command_line.h"
#include "cli/finite_results.h"
#include "core/forward_kinematics.h"
#include "io/json_number.h"
#include "evaluation/scene_evaluation_job.h"
#include "io/scene_files.h"

namespace kinema::cli {

CLI::App* addSkinCommand(CLI::App& app, SkinOptions& o) {
  CLI::App* cmd = app.add_subcommand("skin", "Deform a file's skinned meshes at a time into world-space vertices");
  cmd->add_option("file", o.file, "A .gltf, .glb or .kinema file (others have no meshes)")->required();
  addAllowOutsidePathsFlag(cmd, o.allowOutsidePaths);
  cmd->add_option("--clip", o.clip, "Clip index (default 0)");
  CLI::Option* timeOption = cmd->add_option("--time", o.time, "Time in seconds (default 0, clamped to the clip)");
  o.frameOption = cmd->add_option("--frame", o.frame, "Frame number (time = N x frame time)");
  timeOption->excludes(o.frameOption);
  cmd->add_option("--method", o.method,
                  "Skinning for every mesh: linear (linear blend) or dq (dual quaternions); default: each mesh's own")
      ->check(CLI::IsMember({"linear", "dq"}));
  cmd->add_flag("--json", o.json, "Print JSON (the stable contract) instead of a summary");
  addUpOption(cmd, o.up);
  return cmd;
}

int runSkin(const SkinOptions& o) {
  if (!std::isfinite(o.time)) return badInput("--time must be a finite number");
  Result<Scene> loaded = loadScene(o.file, inputLimits(o.allowOutsidePaths), upAxisOf(o.up));
  if (!loaded) return badInput(loaded.error());
  Scene& scene = loaded.value();
  for (const std::string& line : scene.warnings) std::cerr << "kinema skin: warning: " << o.file << ": " << line << "\n";
  if (const std::string bad = clipIndexError(scene, o.clip); !bad.empty()) return badInput(bad);
  if (!o.method.empty())
    for (MeshInstance& inst : scene.meshInstances)
      inst.skinning = o.method == "dq" ? SkinningMethod::DualQuaternion : SkinningMethod::LinearBlend;
  const double time = o.frameOption->count() ? static_cast<double>(o.frame) * scene.frameGrid(o.clip).secondsPerFrame : o.time;
  // Every stage of the evaluation (evaluation/scene_evaluation_job.h), meshes included.
  Pose pose;
  std::vector<glm::mat4> world;
  std::vector<DeformedPrimitive> deformed;
  SceneEvaluationJob job;
  job.scene = &scene;
  job.clip = o.clip;
  job.time = contractTime(scene, o.clip, time);
  job.pose = &pose;
  job.world = &world;
  job.meshes = &deformed;
  job.skinnedOnly = true;
  if (const std::string bad = job.validate(); !bad.empty()) return badInput(scene.source + ": " + bad);
  const bool ran = job.run();
  if (const std::string bad = nonFiniteWorldError(scene, world, time); !bad.empty()) return badInput(bad);
  if (!ran) return badInput(scene.source + ": the meshes could not be deformed");
  if (const std::string bad = nonFiniteVerticesError(scene, deformed, time); !bad.empty()) return badInput(bad);

  if (o.json) {
    nlohmann::ordered_json meshes = nlohmann::ordered_json::array();
    for (const DeformedPrimitive& d : deformed) {
      const MeshInstance& inst = scene.meshInstances[d.instance];
      nlohmann::ordered_json m;
      m["node"] = scene.fileIndexOf(inst.joint);
      m["mesh"] = inst.mesh;
      m["primitive"] = d.primitive;
      nlohmann::ordered_json positions = nlohmann::ordered_json::array();
      for (const glm::vec3& p : d.positions)
        positions.push_back(nlohmann::ordered_json::array({jsonFloat(p.x), jsonFloat(p.y), jsonFloat(p.z)}));
      m["positions"] = std::move(positions);
      meshes.push_back(std::move(m));
    }
    nlohmann::ordered_json out;
    out["meshes"] = std::move(meshes);
    std::cout << out.dump(-1, ' ', false, nlohmann::ordered_json::error_handler_t::replace) << "\n";
    return kExitOk;
  }
  std::printf("%s at t = %g s: %zu skinned primitive%s\n", scene.source.c_str(), time, deformed.size(),
              deformed.size() == 1 ? "" : "s");
  for (const DeformedPrimitive& d : deformed) {
    const MeshInstance& inst = scene.meshInstances[d.instance];
    glm::vec3 lo(INFINITY), hi(-INFINITY);
    for (const glm::vec3& p : d.positions) lo = glm::min(lo, p), hi = glm::max(hi, p);
    std::printf("node %d mesh %d primitive %d (%s): %zu vertices", scene.fileIndexOf(inst.joint), inst.mesh,
                d.primitive, inst.skinning == SkinningMethod::DualQuaternion ? "dual quaternion" : "linear blend",
                d.positions.size());
    if (!d.positions.empty())
      std::printf(", bounds (%g, %g, %g) .. (%g, %g, %g)", lo.x, lo.y, lo.z, hi.x, hi.y, hi.z);
    std::printf("\n");
  }
  return kExitOk;
}

}  // namespace kinema::cli
