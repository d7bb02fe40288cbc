#include "cli/pose_command.h"

#include <cmath>
#include <cstdio>
#include <iostream>

#include "cli/command_line.h"
#include "cli/finite_results.h"
#include "core/forward_kinematics.h"
#include "io/json_number.h"

namespace kinema::cli {

CLI::App* addPoseCommand(CLI::App& app, PoseOptions& o) {
  CLI::App* cmd = app.add_subcommand("pose", "Evaluate a file at a time or frame into world joint transforms");
  cmd->add_option("file", o.file, "A .bvh, .kinema, .gltf or .glb file")->required();
  addAllowOutsidePathsFlag(cmd, o.allowOutsidePaths);
  cmd->add_option("--clip", o.clip, "Clip index (default 0)");
  o.timeOption = cmd->add_option("--time", o.time, "Time in seconds (clamped to the clip)");
  o.frameOption = cmd->add_option("--frame", o.frame, "Frame number (time = N x frame time)");
  o.timeOption->excludes(o.frameOption);
  cmd->add_flag("--json", o.json, "Print JSON (the stable contract) instead of a table");
  addUpOption(cmd, o.up);
  return cmd;
}

int runPose(const PoseOptions& o) {
  if (!o.timeOption->count() && !o.frameOption->count()) {
    std::cerr << "kinema pose: give --time SECONDS or --frame N; see --help\n";
    return kExitUsage;
  }
  if (!std::isfinite(o.time)) return badInput("--time must be a finite number");
  Result<Scene> loaded = loadSceneOrDefault(o.file, inputLimits(o.allowOutsidePaths), upAxisOf(o.up));
  if (!loaded) return badInput(loaded.error());
  const Scene& scene = loaded.value();
  if (const std::string bad = clipIndexError(scene, o.clip); !bad.empty()) return badInput(bad);
  const double time = o.frameOption->count() ? static_cast<double>(o.frame) * scene.frameGrid(o.clip).secondsPerFrame : o.time;
  const Pose pose = sampledPose(scene, o.clip, time);
  const std::vector<glm::mat4> world = computeWorld(scene.skeleton, pose);
  if (const std::string bad = nonFiniteWorldError(scene, world, time); !bad.empty()) return badInput(bad);

  if (o.json) {
    nlohmann::ordered_json out;
    out["time"] = time;
    out["joints"] = jointsJson(scene, world);
    std::cout << out.dump(-1, ' ', false, nlohmann::ordered_json::error_handler_t::replace) << "\n";
    return kExitOk;
  }
  std::printf("%s at t = %g s: %d joints\n", scene.source.c_str(), time, scene.skeleton.size());
  std::printf("%4s  %-24s %6s  %12s %12s %12s\n", "#", "joint", "parent", "x", "y", "z");
  for (int i = 0; i < scene.skeleton.size(); ++i)
    std::printf("%4d  %-24s %6d  %12.6g %12.6g %12.6g\n", i, scene.skeleton.names[i].c_str(),
                scene.skeleton.parents[i], world[i][3].x, world[i][3].y, world[i][3].z);
  return kExitOk;
}

}  // namespace kinema::cli
