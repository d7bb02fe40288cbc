#pragma once
#include <CLI/CLI.hpp>
#include <string>

namespace kinema::cli {

struct ConvertOptions {
  std::string input, output;
  bool allowOutsidePaths = false;  // --allow-outside-paths: glTF uris may leave the file's folder
  double rate = 0.0;  // frames per second for BVH output and glTF resampling; 0: the clip's
  std::string rotationOrder = "ZXY";
  std::string up = "y";  // --up: BVH files' up axis
  bool bakeDeformers = false;  // --bake-deformers: deformer stacks become morph targets (BakeDeformersJob)
};

CLI::App* addConvertCommand(CLI::App& app, ConvertOptions& options);
// IN -> OUT by extension (.bvh, .gltf, .glb, .kinema). What OUT cannot hold is listed on
// stderr as "kinema convert: warning: ..." lines; a failure leaves OUT untouched.
int runConvert(const ConvertOptions& options);

}  // namespace kinema::cli
