#pragma once
#include <CLI/CLI.hpp>

namespace kinema::cli {

// `kinema plot-curves --out IMAGE.png [--columns N] [--panel WxH]`: draws every
// interpolation mode over the same keys (docs/images/interpolation_modes.png), headless.
struct PlotCurvesOptions {
  std::string out;
  int columns = 4;
  std::string panel = "320x210";
};

CLI::App* addPlotCurvesCommand(CLI::App& app, PlotCurvesOptions& options);
int runPlotCurves(const PlotCurvesOptions& options);

}  // namespace kinema::cli
