#pragma once
#include <CLI/CLI.hpp>
#include <string>

namespace kinema::cli {

// `kinema skin FILE [--clip I] [--time T | --frame N] [--method linear|dq] [--json]`
struct SkinOptions {
  std::string file;
  bool allowOutsidePaths = false;  // --allow-outside-paths: glTF uris may leave the file's folder
  int clip = 0;
  double time = 0.0;
  long long frame = 0;
  std::string method;  // "", "linear" or "dq": "" keeps each instance's own setting
  bool json = false;
  std::string up = "y";  // --up: BVH files' up axis
  CLI::Option* frameOption = nullptr;
};

CLI::App* addSkinCommand(CLI::App& app, SkinOptions& options);
// World-space vertices of every skinned node x primitive (morph targets, then skinning).
// Load warnings go to stderr as "kinema skin: warning: FILE: ..." lines.
int runSkin(const SkinOptions& options);

}  // namespace kinema::cli
