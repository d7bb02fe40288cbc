#include "cli/lsystem_command.h"

#include <cmath>
#include <cstdio>
#include <iostream>
#include <sstream>

#include "cli/command_line.h"
#include "io/gltf_writer.h"
#include "io/kinema_file.h"
#include "sim/lsystem_derivation.h"
#include "io/lsystem_grammar_file.h"
#include "scene/lsystem_scene.h"
#include "sim/lsystem_skeleton.h"
#include "io/scene_files.h"

namespace kinema::cli {

namespace {

// "0,0,1" -> {0, 0, 1}; false on anything but comma-separated whole numbers.
bool parseChoices(const std::string& text, std::vector<int>& out) {
  out.clear();
  if (text.empty()) return true;
  std::stringstream ss(text);
  std::string item;
  while (std::getline(ss, item, ',')) {
    if (item.empty() || item.size() > 9 || item.find_first_not_of("0123456789") != std::string::npos) return false;
    out.push_back(std::stoi(item));
  }
  return text.back() != ',';
}

}  // namespace

CLI::App* addLSystemCommand(CLI::App& app, LSystemOptions& o) {
  CLI::App* cmd = app.add_subcommand("lsystem", "Grow a plant skeleton (with skinned tube geometry) from an L-system grammar");
  cmd->add_option("grammar", o.grammar, "The grammar file: rules `A -> [+B]fA`, `(p)` probabilities, `angle DEG`")
      ->required();
  cmd->add_option("--generations", o.generations, "Rewriting steps (>= 0)")->required();
  cmd->add_option("--out", o.out, "The plant to write: .kinema, .gltf or .glb")->required();
  cmd->add_option("--seed", o.seed, "Seed of the stochastic rule choices (default 1)");
  cmd->add_option("--choices", o.choices, "Forced rule indices (0-based) at each rewrite of a symbol with several rules, e.g. 0,0,1");
  cmd->add_option("--segment-length", o.segmentLength, "Length of one `f` segment in metres (default 1)");
  cmd->add_option("--radius", o.radius, "Tube radius in metres (default a tenth of the segment length)");
  cmd->add_flag("--json", o.json, "Print the derivation and joint count as JSON");
  return cmd;
}

int runLSystem(const LSystemOptions& o) {
  const std::string ext = lowerExtension(o.out);
  if (ext != ".kinema" && ext != ".gltf" && ext != ".glb")
    return usageError("lsystem", "cannot write '" + ext + "' files (use .kinema, .gltf or .glb)");
  LSystemDerivationJob job;
  if (!parseChoices(o.choices, job.choices)) return usageError("lsystem", "--choices '" + o.choices + "' is not a list like 0,0,1");
  if (o.generations < 0 || o.generations > 10000)
    return badInput("--generations must be in 0 .. 10000, found " + std::to_string(o.generations));
  if (!(o.segmentLength > 0.0) || !std::isfinite(o.segmentLength))
    return badInput("--segment-length must be a positive finite number of metres");
  if (!(o.radius >= 0.0) || !std::isfinite(o.radius)) return badInput("--radius must be a finite number >= 0");
  Result<LSystemGrammar> grammar = loadLSystemGrammar(o.grammar);
  if (!grammar) return badInput(grammar.error());
  job.grammar = &grammar.value();
  job.generations = o.generations;
  job.seed = o.seed;
  std::string error;
  if (!job.run(error)) return badInput(o.grammar + ": " + error);
  Result<Scene> plant = makeLSystemScene(job.strings.back(), grammar->angleDegrees, static_cast<float>(o.segmentLength),
                                         static_cast<float>(o.radius));
  if (!plant) return badInput(o.grammar + ": generation " + std::to_string(o.generations) + ": " + plant.error());
  plant->source = o.out;
  const std::string bad = saveScene(o.out, plant.value());
  if (!bad.empty()) return badInput(bad);
  const int joints = plant->skeleton.size();
  if (o.json) {
    nlohmann::ordered_json j;
    nlohmann::ordered_json gens = nlohmann::ordered_json::array();
    for (size_t g = 0; g < job.strings.size(); ++g) {
      nlohmann::ordered_json e;
      e["generation"] = g;
      e["string"] = job.strings[g];
      gens.push_back(std::move(e));
    }
    j["generations"] = std::move(gens);
    j["choices"] = job.choicesMade;
    j["seed"] = o.seed;
    j["angle"] = grammar->angleDegrees;
    j["segment_length"] = o.segmentLength;
    j["joints"] = joints;
    j["leaves"] = std::count(job.strings.back().begin(), job.strings.back().end(), '@');
    j["out"] = o.out;
    std::cout << j.dump() << "\n";
  } else {
    std::printf("wrote %s: %d joints after %d generations\n", o.out.c_str(), joints, o.generations);
  }
  return kExitOk;
}

}  // namespace kinema::cli
