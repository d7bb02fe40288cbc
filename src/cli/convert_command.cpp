#include "cli/convert_command.h"

#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <iostream>
#include <sstream>

#include "cli/command_line.h"
#include "io/scene_files.h"
#include "bake/bake_deformers.h"

namespace kinema::cli {

namespace {

constexpr long long kLongClipFrames = 500;

}  // namespace

CLI::App* addConvertCommand(CLI::App& app, ConvertOptions& o) {
  CLI::App* cmd = app.add_subcommand("convert", "Convert between .bvh, .gltf, .glb and .kinema (by extension)");
  cmd->add_option("input", o.input, "The file to read")->required();
  addAllowOutsidePathsFlag(cmd, o.allowOutsidePaths);
  cmd->add_option("output", o.output, "The file to write (replaced only when the conversion succeeds)")->required();
  cmd->add_option("--rate", o.rate,
                  "Frames per second: BVH frame rate, and the rate glTF resamples curves it cannot hold "
                  "(default: the clip's own)");
  cmd->add_option("--rotation-order", o.rotationOrder, "Euler order of BVH rotation channels (default ZXY)");
  addUpOption(cmd, o.up);  // the input's; BVH output is always Y-up
  cmd->add_flag("--bake-deformers", o.bakeDeformers,
                "Write deformer stacks as morph targets made at their keys (and report the largest error)");
  return cmd;
}

int runConvert(const ConvertOptions& o) {
  const std::string ext = lowerExtension(o.output);
  if (!canSaveScene(o.output)) {
    std::cerr << "kinema convert: cannot write '" << ext << "' files (use .bvh, .gltf, .glb or .kinema); see --help\n";
    return kExitUsage;
  }
  const std::optional<EulerOrder> order = eulerOrderFromString(o.rotationOrder);
  if (!order) {
    std::cerr << "kinema convert: --rotation-order must be one of XYZ XZY YXZ YZX ZXY ZYX; see --help\n";
    return kExitUsage;
  }
  if (!std::isfinite(o.rate) || o.rate < 0.0) return badInput("--rate must be a positive number of frames per second");

  Result<Scene> loaded = loadScene(o.input, inputLimits(o.allowOutsidePaths), upAxisOf(o.up));
  if (!loaded) return badInput(loaded.error());
  for (const std::string& line : loaded->warnings) std::cerr << "kinema convert: warning: " << o.input << ": " << line << "\n";
  if (o.bakeDeformers && !loaded->deformers.empty()) {
    Scene baked;
    DeformerBakeReport bake;
    BakeDeformersJob job;
    job.scene = &loaded.value();
    job.out = &baked;
    job.report = &bake;
    if (std::string e = job.validate(); !e.empty()) return badInput(o.input + ": " + e);
    if (!job.run()) return badInput(o.input + ": the deformers could not be baked");
    for (const std::string& line : bake.lines) std::cerr << "kinema convert: " << line << "\n";
    std::ostringstream where;
    if (bake.errorClip >= 0) where << " (clip " << bake.errorClip << ", time " << bake.errorTime << " s)";
    std::cerr << "kinema convert: baked deformers: " << bake.targets << " morph target(s), largest error "
              << bake.largestError << " m over " << bake.samples << " sampled pose(s)" << where.str() << "\n";
    loaded.value() = std::move(baked);
  }
  const Scene& scene = loaded.value();

  std::vector<std::string> report;
  SceneSaveOptions options;
  options.bvhRotationOrder = *order;
  options.frameRate = o.rate;
  const bool tty = isatty(STDERR_FILENO) != 0;
  bool shown = false;
  options.progress = [&](long long frame, long long total) {
    if (total < kLongClipFrames) return;
    if (tty) {
      std::cerr << "\rconverting: frame " << frame << "/" << total << std::flush;
      shown = true;
    } else if (frame == total) {
      std::cerr << "converting: frame " << frame << "/" << total << "\n";
    }
  };
  const std::string error = saveScene(o.output, scene, options, &report);
  if (shown) std::cerr << "\n";
  for (const std::string& line : report) std::cerr << "kinema convert: warning: " << line << "\n";
  if (!error.empty()) return badInput(error);
  return kExitOk;
}

}  // namespace kinema::cli
