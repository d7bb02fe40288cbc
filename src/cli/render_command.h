#pragma once
#include <CLI/CLI.hpp>

#include "scene/scene.h"

namespace kinema::cli {

// `kinema render [FILE] [--clip I] [--time T | --frame N | --frames A:B] [--size WxH]
//  [--camera AZ,EL[,DIST]] [--backend egl|osmesa] [--select JOINT] [--bones none|on|xray]
//  [--weights JOINT] [--mesh on|off] --out PATH`
struct RenderOptions {
  std::string file;
  bool allowOutsidePaths = false;  // --allow-outside-paths: glTF uris may leave the file's folder
  int clip = 0;
  double time = 0.0;
  long long frame = 0;
  std::string frames;
  std::string size = "1280x720";
  std::string camera;
  std::string backend = "egl";
  std::string select;
  std::string bones = "on";
  std::string weights;
  std::string mesh = "on";
  std::string out;
  std::string up = "y";  // --up: BVH files' up axis
  CLI::Option* timeOption = nullptr;
  CLI::Option* frameOption = nullptr;
  CLI::Option* framesOption = nullptr;
};

CLI::App* addRenderCommand(CLI::App& app, RenderOptions& options);
int runRender(const RenderOptions& options);
// The same for a scene already in memory (`options.file` is then only named in messages):
// `kinema simulate --render` draws the simulated scene with it. Scenes with particles
// (.kinema "simulation.particles") show them at each frame.
int runRenderOn(const RenderOptions& options, const Scene* scene);

// Plain `kinema` without a display: renders the default character to `path` with EGL,
// prints where, and returns the exit code.
int renderDefaultCharacterHeadless(const std::string& path);

// Expands a sequence pattern: "%04d" (or "%d", "%5d"...) becomes the frame number, "%%" a
// percent sign. Returns "" when the pattern has no number or anything else after a '%'.
std::string expandFramePattern(const std::string& pattern, long long frame);

}  // namespace kinema::cli
