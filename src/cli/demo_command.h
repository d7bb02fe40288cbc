#pragma once
#include <CLI/CLI.hpp>

namespace kinema::cli {

// `kinema demo list [--json]`, `kinema demo NAME --out DIR [--size WxH] [--max-steps N]`,
// `kinema demo solver-table --out DIR [--targets N] [--seed S]`: the teaching presets'
// figures (every solver step as PNG, the convergence chart, the numbers, the case as
// .kinema with the `kinema ik` commands that reproduce each trace) and the FABRIK paper's
// solver comparison table; `kinema demo stiff-springs --out DIR [--zeta Z]`: four integrators
// on a damped spring chain at growing time steps (cli/stiff_springs_demo.h).
struct DemoOptions {
  std::string name;  // a preset, "list" or "solver-table"
  std::string out;
  std::string size = "640x480";
  int maxSteps = 0;  // > 0: at most this many step images per solver (plus the last one)
  int targets = 100;
  unsigned seed = 1;
  double zeta = 0.3;  // stiff-springs: damping ratio of the chain's highest mode
  bool json = false;
};

CLI::App* addDemoCommand(CLI::App& app, DemoOptions& options);
int runDemo(const DemoOptions& options);

}  // namespace kinema::cli
