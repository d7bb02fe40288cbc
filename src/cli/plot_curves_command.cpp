#include "cli/plot_curves_command.h"

#include <cstdio>
#include <iostream>

#include "cli/command_line.h"
#include "render/curve_plot.h"

namespace kinema::cli {

CLI::App* addPlotCurvesCommand(CLI::App& app, PlotCurvesOptions& o) {
  CLI::App* cmd = app.add_subcommand("plot-curves", "Draw every interpolation mode over the same keys into a PNG");
  cmd->add_option("--out", o.out, "Output PNG path")->required();
  cmd->add_option("--columns", o.columns, "Panels per row (default 4)");
  cmd->add_option("--panel", o.panel, "Panel size WxH in pixels (default 320x210)");
  return cmd;
}

int runPlotCurves(const PlotCurvesOptions& o) {
  int w = 0, h = 0;
  char tail = 0;
  if (std::sscanf(o.panel.c_str(), "%dx%d%c", &w, &h, &tail) != 2 || w < 120 || h < 90 || w > 4000 || h > 4000)
    return badInput("--panel: expected WxH with 120 <= W <= 4000 and 90 <= H <= 4000, found '" + o.panel + "'");
  if (o.columns < 1 || o.columns > 64) return badInput("--columns must be between 1 and 64");
  const std::vector<PlotPanel> panels = interpolationModePanels();
  const Image image = plotPanels(panels, o.columns, w, h);
  const std::string error = savePng(o.out, image);
  if (!error.empty()) return badInput(error);
  std::printf("wrote %s (%dx%d, %zu panels)\n", o.out.c_str(), image.width, image.height, panels.size());
  return kExitOk;
}

}  // namespace kinema::cli
