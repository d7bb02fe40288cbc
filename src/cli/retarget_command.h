#pragma once
#include <CLI/CLI.hpp>
#include <string>

namespace kinema::cli {

struct RetargetOptions {
  std::string source, target, out;
  std::string clip;           // --clip NAME|INDEX; empty: clip 0
  std::string map;            // --map FILE; empty: the automatic humanoid map
  bool inPlace = false;       // --in-place
  bool fixFeet = false;       // --fix-feet
  std::string reduce;         // --reduce POS[,DEG]
  bool json = false;
  bool allowOutsidePaths = false;
  std::string up = "y";
};

CLI::App* addRetargetCommand(CLI::App& app, RetargetOptions& options);
// SOURCE's clip onto TARGET's skeleton (the default character without TARGET), saved to OUT
// with TARGET's meshes and skins. Nothing is written unless every step succeeds.
int runRetarget(const RetargetOptions& options);

}  // namespace kinema::cli
