#include "cli/convert_command.h"

#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <iostream>
#include <sstream>

#include "cli/command_line.h"
#include "io/bvh_writer.h"
#include "io/gltf_writer.h"
#include "io/kinema_file.h"
#include "io/scene.h"
#include "skin/bake_deformers.h"

namespace kinema::cli {

namespace {

bool writable(const std::string& ext) { return ext == ".bvh" || ext == ".gltf" || ext == ".glb" || ext == ".kinema"; }

// Clips at least this many frames long show a progress line.
constexpr long long kLongClipFrames = 500;

// What a BVH file cannot hold, beyond what the writer itself reports.
std::vector<std::string> bvhLosses(const Scene& scene) {
  std::vector<std::string> lost;
  if (!scene.meshes.empty())
    lost.push_back(std::to_string(scene.meshes.size()) + " mesh(es), their skins and materials dropped (BVH holds a skeleton and one motion)");
  if (scene.clips.size() > 1)
    lost.push_back("only clip 0 ('" + scene.clips[0].name + "') written; " + std::to_string(scene.clips.size() - 1) +
                   " more dropped (BVH holds one motion)");
  if (!scene.ik.empty()) lost.push_back("IK limits and targets dropped (BVH has no place for them)");
  return lost;
}

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
  if (!writable(ext)) {
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
  std::string error;
  if (ext == ".bvh") {
    report = bvhLosses(scene);
    BvhWriteOptions options;
    options.order = *order;
    options.frameRate = o.rate;
    const bool tty = isatty(STDERR_FILENO) != 0;
    bool shown = false;
    options.progress = [&](long long frame, long long total) {
      if (total < kLongClipFrames) return;
      // On a terminal the line updates in place; in a log only the last one is written.
      if (tty) {
        std::cerr << "\rconverting: frame " << frame << "/" << total << std::flush;
        shown = true;
      } else if (frame == total) {
        std::cerr << "converting: frame " << frame << "/" << total << "\n";
      }
    };
    error = saveBvh(o.output, scene.skeleton, scene.clips.empty() ? nullptr : &scene.clips[0], options, &report);
    if (shown) std::cerr << "\n";
  } else if (ext == ".gltf" || ext == ".glb") {
    GltfWriteOptions options;
    options.binary = ext == ".glb";
    options.resampleRate = o.rate;
    error = saveGltf(o.output, scene, options, &report);
  } else {
    error = saveKinemaFile(o.output, scene);
  }
  for (const std::string& line : report) std::cerr << "kinema convert: warning: " << line << "\n";
  if (!error.empty()) return badInput(error);
  return kExitOk;
}

}  // namespace kinema::cli
