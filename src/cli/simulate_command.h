#pragma once
#include <CLI/CLI.hpp>
#include <string>
#include <vector>

#include "scene/scene.h"

namespace kinema::cli {

struct SimulateOptions {
  std::string file, out;
  std::string frames;   // --frames A:B (default: the clip's frames)
  int clip = 0;         // --clip I
  std::string reduce;   // --reduce POS[,DEG]
  bool everyFrame = false;  // --every-frame: keep a key per frame
  bool json = false;
  bool allowOutsidePaths = false;
  // --render DIR: one PNG a frame (DIR/frame_NNNN.png), drawn as `kinema render` draws.
  std::string render, size = "1280x720", camera, backend = "egl";
  CLI::Option* framesOption = nullptr;
};

CLI::App* addSimulateCommand(CLI::App& app, SimulateOptions& options);
// Bakes FILE's dynamic chains and ragdolls (its .kinema "simulation") into its clip and
// writes OUT (.kinema, .gltf, .glb or .bvh). Nothing is written unless every part succeeds.
// Its particle systems are played over the frames (reported; drawn with --render DIR).
int runSimulate(const SimulateOptions& options);
// Writes `scene` to `out` by its extension: .bvh (the skeleton and clip `clip`), .gltf /
// .glb, else .kinema; warnings go to `report`. Empty on success, else the error.
std::string saveSimulatedScene(const std::string& out, const Scene& scene, int clip, std::vector<std::string>& report);

}  // namespace kinema::cli
