// The CPU curve plot: lines, key dots and labels land where the data says.
#include <gtest/gtest.h>

#include "render/curve_plot.h"
#include "test_support.h"

namespace kinema {
namespace KINEMA_UNITY_ID {

TEST(CurvePlot, DrawsCurvesAndKeysWhereTheDataIs) {
  PlotPanel p;
  p.title = "t";
  p.min = {0, 0};
  p.max = {1, 1};
  p.curves.push_back({"", Rgb{0, 0, 255}, {{0, 0.5f}, {1, 0.5f}}});  // horizontal, mid-height
  p.keys = {{0.5f, 0.25f}};
  const Image img = plotPanels({p}, 1, 200, 130);
  ASSERT_EQ(img.width, 200);
  ASSERT_EQ(img.height, 130);
  // Plot area: x in [14, 190], y in [30, 116]; y = 0.5 maps to row 73, y = 0.25 to 94.5.
  const std::uint8_t* onLine = img.pixel(100, 73);
  EXPECT_LT(onLine[0], 60);
  EXPECT_GT(onLine[2], 200);
  const std::uint8_t* key = img.pixel(102, 94);
  EXPECT_GT(key[0], 180);  // the red key dot
  EXPECT_LT(key[2], 80);
  const std::uint8_t* empty = img.pixel(60, 105);
  EXPECT_GT(empty[0] + empty[1] + empty[2], 600);  // background (or a light grid line)
  // The title is ink in the top-left corner.
  int dark = 0;
  for (int y = 0; y < 28; ++y)
    for (int x = 0; x < 40; ++x) dark += img.pixel(x, y)[0] < 100;
  EXPECT_GT(dark, 5);
}

TEST(CurvePlot, DocumentationPlotCoversEveryMode) {
  const std::vector<PlotPanel> panels = interpolationModePanels();
  std::string titles;
  for (const PlotPanel& p : panels) titles += p.title + "|";
  for (const char* mode : {"step", "linear", "hermite", "catmull-rom", "tcb: tension", "tcb: continuity", "tcb: bias",
                           "bezier: auto", "bezier: auto-clamped", "bezier: vector", "aligned / free", "ease: sine",
                           "ease: elastic", "ease: bounce", "rotation", "motion control"})
    EXPECT_NE(titles.find(mode), std::string::npos) << mode;
  // Every scalar-mode curve passes through the panel's keys.
  for (const PlotPanel& p : panels) {
    if (p.title.rfind("ease:", 0) == 0 || p.title.rfind("rotation", 0) == 0 || p.title.rfind("motion", 0) == 0) continue;
    for (const glm::vec2& k : p.keys)
      for (const PlotCurve& c : p.curves) {
        float best = 1e9f;
        for (const glm::vec2& q : c.points) best = std::min(best, glm::length(q - k));
        EXPECT_LT(best, 0.02f) << p.title << " " << c.label;
      }
  }
}

}  // namespace
}  // namespace kinema
