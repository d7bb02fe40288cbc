// Teaching figures: the raster mapping, and that a step's drawing puts the chain and the
// target where the comparison says they are.
#include <gtest/gtest.h>

#include "render/solver_figure.h"
#include "test_support.h"

namespace kinema {
namespace KINEMA_UNITY_ID {

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

bool sameColor(const Rgba& a, const Rgba& b) { return a[0] == b[0] && a[1] == b[1] && a[2] == b[2]; }

// The plot drawn at a cursor holds only what the cursor has reached: one dot per revealed
// iteration (none beyond the cursor's iteration), a ring at the cursor's point while the
// run is under way; at the end the whole curve.
TEST(SolverFigure, ConvergencePlotRevealsTheCurvesUpToTheCursor) {
  SolverComparison cmp;
  ASSERT_EQ(startComparison(*findTeachingPreset("ccd-steps"), cmp, 1), "");
  FigureStyle style;
  auto countOf = [](const Figure& f, Rgba col, float pixelRadius, bool filled) {
    int n = 0;
    for (const FigureCircle& c : f.circles) n += sameColor(c.color, col) && c.pixelRadius == pixelRadius && c.filled == filled;
    return n;
  };
  auto rightmostDot = [](const Figure& f, Rgba col) {
    float x = -1e9f;
    for (const FigureCircle& c : f.circles)
      if (sameColor(c.color, col) && c.filled) x = std::max(x, c.center.x);
    return x;
  };
  float previousX = -1e9f;
  for (int step = 0; step < 4; ++step) {
    const Figure f = drawConvergencePlot(cmp, style);
    for (const SolverRun& run : cmp.runs) {
      const Rgba col = solverColor(run.solver);
      const int iteration = run.current().iteration;
      EXPECT_EQ(countOf(f, col, 3.0f, true), iteration + 1) << toString(run.solver) << " step " << step;
      EXPECT_EQ(countOf(f, col, 7.0f, false), run.finished() ? 0 : 1) << "one ring at the cursor while under way";
    }
    const float x = rightmostDot(f, solverColor(cmp.runs[0].solver));
    EXPECT_GE(x, previousX) << "the curve grows to the right";
    previousX = x;
    stepIteration(cmp);
  }
  // The axes do not move while the curves grow: the same grid lines at the start and the end.
  resetCursors(cmp);
  const Figure start = drawConvergencePlot(cmp, style);
  runToEnd(cmp);
  const Figure end = drawConvergencePlot(cmp, style);
  for (const SolverRun& run : cmp.runs)
    EXPECT_EQ(countOf(end, solverColor(run.solver), 3.0f, true), static_cast<int>(run.convergence().size()));
  ASSERT_FALSE(start.lines.empty());
  EXPECT_EQ(start.lines.front().a, end.lines.front().a);
  EXPECT_EQ(start.lines.front().b, end.lines.front().b);
  EXPECT_GT(end.lines.size(), start.lines.size());
}

// The 3D view's ground grid and axes: off by default (the board and the slides); on, the
// axes are Blender's red X, green Y, blue Z through the base, along the projected axes.
TEST(SolverFigure, GroundGridAndAxesFollowTheView) {
  SolverComparison cmp;
  ASSERT_EQ(startComparison(*findTeachingPreset("ccd-steps"), cmp, 1), "");
  const Rgba red{255, 51, 82, 255}, green{139, 220, 0, 255}, blue{40, 144, 255, 255};
  auto linesOf = [](const Figure& f, Rgba col) {
    std::vector<FigureLine> out;
    for (const FigureLine& l : f.lines)
      if (sameColor(l.color, col)) out.push_back(l);
    return out;
  };
  FigureStyle style;
  EXPECT_TRUE(linesOf(drawSolverStep(cmp, 0, style), red).empty());
  style.showGround = true;
  style.viewDirection = glm::normalize(glm::vec3(0.4f, 0.6f, 1.0f));  // orbited: up and to the side
  const Figure f = drawSolverStep(cmp, 0, style);
  const glm::vec2 base = projectToFigure(cmp.setup.chain.base, style);
  const glm::vec3 axes[3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  const Rgba colors[3] = {red, green, blue};
  for (int k = 0; k < 3; ++k) {
    const std::vector<FigureLine> l = linesOf(f, colors[k]);
    ASSERT_EQ(l.size(), 1u) << "axis " << k;
    // Both ends on the line through the projected base along the projected axis.
    const glm::vec2 dir = glm::normalize(projectToFigure(axes[k], style) - projectToFigure(glm::vec3(0.0f), style));
    for (glm::vec2 end : {l[0].a, l[0].b}) {
      const glm::vec2 d = end - base;
      EXPECT_NEAR(d.x * dir.y - d.y * dir.x, 0.0f, 1e-4f) << "axis " << k;
    }
    EXPECT_GT(glm::length(l[0].b - l[0].a), 0.5f * cmp.setup.chain.reach()) << "axis " << k;
  }
  // The grid: lines of one colour, drawn before the chain (under it), on the ground plane:
  // a grid line's ends and the base are projections of points with y = base.y.
  const Rgba grid = f.lines.front().color;
  int gridLines = 0;
  for (const FigureLine& l : f.lines) gridLines += sameColor(l.color, grid);
  EXPECT_GE(gridLines, 8);
  // Seen from straight above, the ground is not foreshortened: the grid is square.
  FigureStyle top = style;
  top.viewDirection = glm::vec3(0, -1, 0);
  const Figure t = drawSolverStep(cmp, 0, top);
  glm::vec2 lo(1e9f), hi(-1e9f);
  for (const FigureLine& l : t.lines)
    if (sameColor(l.color, grid)) {
      lo = glm::min(lo, glm::min(l.a, l.b));
      hi = glm::max(hi, glm::max(l.a, l.b));
    }
  EXPECT_NEAR(hi.x - lo.x, hi.y - lo.y, 1e-4f);
  EXPECT_GT(hi.x - lo.x, cmp.setup.chain.reach());
}

}  // namespace
}  // namespace kinema
