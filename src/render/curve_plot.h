#pragma once
#include <array>
#include <string>
#include <vector>

#include "core/math.h"
#include "io/image.h"

namespace kinema {

// Plots of animation curves drawn on the CPU (anti-aliased lines and dots, stb_easy_font
// labels) into an Image: for documentation and headless checks, no OpenGL needed.
using Rgb = std::array<std::uint8_t, 3>;

struct PlotCurve {
  std::string label;
  Rgb color{40, 90, 200};
  std::vector<glm::vec2> points;  // a polyline in data coordinates
};

struct PlotPanel {
  std::string title;
  std::vector<PlotCurve> curves;
  std::vector<glm::vec2> keys;                              // drawn as dots
  std::vector<std::array<glm::vec2, 2>> handles;            // Bezier handles: key -> handle end
  glm::vec2 min{0.0f}, max{1.0f};                           // data range shown
  bool legendAtBottom = false;                              // where the curves leave room
};

// Panels in a grid, `columns` wide, each panelWidth x panelHeight pixels, white background.
Image plotPanels(const std::vector<PlotPanel>& panels, int columns, int panelWidth, int panelHeight);

// One panel per interpolation mode (and per easing preset, rotation mode and distance-time
// function), all scalar modes over the same keys: the README's interpolation_modes.png.
std::vector<PlotPanel> interpolationModePanels();

}  // namespace kinema
