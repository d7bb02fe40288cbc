#pragma once
#include <cstdint>
#include <string>

#include <CLI/CLI.hpp>

namespace kinema::cli {

// `kinema lsystem GRAMMAR_FILE --generations N --out OUT [--seed S] [--choices LIST]
//  [--segment-length L] [--radius R] [--json]`: derives the grammar's string N times
// (sim/lsystem_derivation.h), grows the plant skeleton with skinned tube geometry from
// the last string (sim/lsystem_skeleton.h) and writes it as .kinema, .gltf or .glb.
struct LSystemOptions {
  std::string grammar;
  std::string out;
  int generations = -1;
  uint64_t seed = 1;
  std::string choices;  // "0,0,1"
  double segmentLength = 1.0;
  double radius = 0.0;  // 0: a tenth of the segment length
  bool json = false;
};

CLI::App* addLSystemCommand(CLI::App& app, LSystemOptions& options);
int runLSystem(const LSystemOptions& options);

}  // namespace kinema::cli
