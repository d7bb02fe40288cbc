#pragma once
#include <CLI/CLI.hpp>

namespace kinema::cli {

// `kinema pose FILE [--clip I] (--time T | --frame N) [--json]`
struct PoseOptions {
  std::string file;
  bool allowOutsidePaths = false;  // --allow-outside-paths: glTF uris may leave the file's folder
  int clip = 0;
  double time = 0.0;
  long long frame = 0;
  bool json = false;
  std::string up = "y";  // --up: BVH files' up axis
  CLI::Option* timeOption = nullptr;
  CLI::Option* frameOption = nullptr;
};

CLI::App* addPoseCommand(CLI::App& app, PoseOptions& options);
int runPose(const PoseOptions& options);

}  // namespace kinema::cli
