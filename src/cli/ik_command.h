#pragma once
#include <CLI/CLI.hpp>

namespace kinema::cli {

// `kinema ik FILE --effector NAME --target X,Y,Z [--root NAME] ... [--solver S] [--json]`
struct IkOptions {
  std::string file;
  bool allowOutsidePaths = false;  // --allow-outside-paths: glTF uris may leave the file's folder
  std::vector<std::string> effectors, targets, roots;
  std::string rig;
  std::string solver = "fabrik";
  std::string pole;
  double tolerance = 1e-3;
  int maxIterations = -1;  // -1: 100, or 2000 for jacobian-transpose
  double lambda = 0.1;
  double soften = 0.0;
  int fabrikFinishAfter = 10;  // IkSettings::fabrikFinishAfter
  int clip = 0;
  double time = 0.0;
  long long frame = 0;
  bool trace = false;
  bool json = false;
  std::string up = "y";  // --up: BVH files' up axis
  CLI::Option* timeOption = nullptr;
  CLI::Option* frameOption = nullptr;
};

CLI::App* addIkCommand(CLI::App& app, IkOptions& options);
int runIk(const IkOptions& options);

}  // namespace kinema::cli
