// Teaching figures: the raster mapping, and that a step's drawing puts the chain and the
// target where the comparison says they are.
#include <gtest/gtest.h>

#include "render/solver_figure.h"
#include "test_support.h"

namespace kinema {
namespace {

bool isWhite(const Image& img, glm::vec2 p) {
  const std::uint8_t* px = img.pixel(static_cast<int>(p.x), static_cast<int>(p.y));
  return px[0] == 255 && px[1] == 255 && px[2] == 255;
}

bool near(const Image& img, glm::vec2 p, Rgba c, int tol) {
  const std::uint8_t* px = img.pixel(static_cast<int>(p.x), static_cast<int>(p.y));
  for (int i = 0; i < 3; ++i)
    if (std::abs(px[i] - c[i]) > tol) return false;
  return true;
}

TEST(SolverFigure, MappingFitsTheBoundsCentredWithYUp) {
  Figure f;
  f.min = {0.0f, 0.0f};
  f.max = {2.0f, 1.0f};
  // 400 x 100: the scale is 100 px per unit (height-bound), 200 px of drawing centred.
  EXPECT_NEAR(figureToPixel(f, 400, 100, {0.0f, 0.0f}).x, 100.0f, 1e-4f);
  EXPECT_NEAR(figureToPixel(f, 400, 100, {0.0f, 0.0f}).y, 100.0f, 1e-4f);
  EXPECT_NEAR(figureToPixel(f, 400, 100, {2.0f, 1.0f}).x, 300.0f, 1e-4f);
  EXPECT_NEAR(figureToPixel(f, 400, 100, {2.0f, 1.0f}).y, 0.0f, 1e-4f);
}

TEST(SolverFigure, RasterisesLinesPolygonsAndDotsWhereTheyAre) {
  Figure f;
  f.min = {0.0f, 0.0f};
  f.max = {10.0f, 10.0f};
  f.lines.push_back({{1.0f, 5.0f}, {9.0f, 5.0f}, {255, 0, 0, 255}, 3.0f, false});
  f.polygons.push_back({{{1.0f, 1.0f}, {4.0f, 1.0f}, {4.0f, 3.0f}, {1.0f, 3.0f}}, {0, 0, 255, 255}});
  FigureCircle dot;
  dot.center = {7.0f, 2.0f};
  dot.pixelRadius = 5.0f;
  dot.filled = true;
  dot.color = {0, 160, 0, 255};
  f.circles.push_back(dot);
  const Image img = rasterizeFigure(f, 100, 100, true);
  // 10 px per unit, y flipped: the line is row 50, x 10..90.
  EXPECT_TRUE(near(img, {50.0f, 50.0f}, {255, 0, 0, 255}, 10));
  EXPECT_TRUE(isWhite(img, {50.0f, 55.0f}));
  EXPECT_TRUE(near(img, {25.0f, 80.0f}, {0, 0, 255, 255}, 10));  // inside (1..4, 1..3)
  EXPECT_TRUE(isWhite(img, {25.0f, 65.0f}));
  EXPECT_TRUE(near(img, {70.0f, 80.0f}, {0, 160, 0, 255}, 10));
  EXPECT_TRUE(isWhite(img, {70.0f, 72.0f}));  // 8 px from the dot's centre
}

TEST(SolverFigure, StepFigureDrawsTheChainAndTheTargetFromTheTrace) {
  SolverComparison cmp;
  ASSERT_EQ(startComparison(*findTeachingPreset("ccd-steps"), cmp, 1), "");
  FigureStyle style;
  cmp.runs[0].cursor = 1;  // CCD's first turn
  const Figure f = drawSolverStep(cmp, 0, style);
  const Image img = rasterizeFigure(f, 640, 480, true);
  const IkTraceEntry& e = cmp.runs[0].current();
  // The middle of every bone is in CCD's colour; the target's centre is red.
  for (int b = 0; b < 3; ++b) {
    const glm::vec3 mid = 0.5f * (e.positions[b] + e.positions[b + 1]);
    EXPECT_TRUE(near(img, figureToPixel(f, 640, 480, {mid.x, mid.y}), solverColor(IkSolver::Ccd), 40)) << "bone " << b;
  }
  const glm::vec2 t = figureToPixel(f, 640, 480, {cmp.setup.target.x, cmp.setup.target.y});
  const std::uint8_t* px = img.pixel(static_cast<int>(t.x), static_cast<int>(t.y));
  EXPECT_GT(px[0], 180);
  EXPECT_LT(px[1], 110);
  // Below the base, inside the reach circle, nothing is drawn.
  const float reach = cmp.setup.chain.reach();
  EXPECT_TRUE(isWhite(img, figureToPixel(f, 640, 480, {-0.5f * reach, -0.5f * reach})));
  // Drawing is deterministic: the same step gives the same pixels.
  EXPECT_EQ(rasterizeFigure(drawSolverStep(cmp, 0, style), 640, 480, true).rgba, img.rgba);
}

TEST(SolverFigure, TwoBoneFiguresShadeTheNoSolutionRegions) {
  SolverComparison cmp;
  ASSERT_EQ(startComparison(*findTeachingPreset("two-bone-unreachable"), cmp, 1), "");
  FigureStyle style;
  style.showReach = false;
  const Figure f = drawSolverStep(cmp, 0, style);
  const Image img = rasterizeFigure(f, 640, 480, true);
  const float l1 = cmp.setup.chain.boneLengths[0], l2 = cmp.setup.chain.boneLengths[1];
  const float inner = std::abs(l1 - l2), outer = l1 + l2;
  auto shaded = [&](glm::vec2 p) {
    const std::uint8_t* px = img.pixel(static_cast<int>(p.x), static_cast<int>(p.y));
    return px[0] > 200 && px[1] < 245 && px[0] > px[1] + 10;  // pale red over white
  };
  // Inside |l1 - l2| and outside l1 + l2: shaded; in the ring: white (down and left of
  // the base, away from the chain and the labels).
  EXPECT_TRUE(shaded(figureToPixel(f, 640, 480, {-0.6f * inner, -0.6f * inner})));
  EXPECT_TRUE(shaded(figureToPixel(f, 640, 480, {-0.75f * outer, -0.75f * outer})));
  const float mid = 0.5f * (inner + outer) * 0.7071f;
  EXPECT_TRUE(isWhite(img, figureToPixel(f, 640, 480, {-mid, -mid})));
}

}  // namespace
}  // namespace kinema
