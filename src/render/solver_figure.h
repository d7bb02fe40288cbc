#pragma once
// Teaching figures as 2D vector drawings (issue 10): the same primitives are drawn by the
// editor's "Compare solvers" view (ImGui draw lists) and rasterised on the CPU for
// `kinema demo` (PNG for slides, white background). No OpenGL.
#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "core/math.h"
#include "ik/figure_projection.h"
#include "ik/solver_comparison.h"
#include "io/image.h"

namespace kinema {

using Rgba = std::array<std::uint8_t, 4>;

struct FigureLine {
  glm::vec2 a{0.0f}, b{0.0f};
  Rgba color{0, 0, 0, 255};
  float width = 2.0f;  // pixels
  bool dashed = false;
};
struct FigureCircle {
  glm::vec2 center{0.0f};
  float radius = 1.0f;      // figure units (a joint dot: pixelRadius instead)
  float pixelRadius = 0.0f; // > 0: a dot of this many pixels whatever the zoom
  Rgba color{0, 0, 0, 255};
  float width = 2.0f;
  bool filled = false;
};
struct FigurePolygon {  // filled (reach regions, unreachable areas)
  std::vector<glm::vec2> points;
  Rgba color{0, 0, 0, 64};
};
struct FigureText {
  glm::vec2 at{0.0f};  // figure units, text's top left
  std::string text;
  Rgba color{0, 0, 0, 255};
  int scale = 2;       // rasterised: pixels per stb_easy_font pixel (titles 2, labels 1)
};

// In figure units (the chain's own, Y up); a view maps [min, max] into its pixels keeping
// the aspect ratio. Drawn in this order: polygons, circles, lines, texts.
struct Figure {
  glm::vec2 min{-1.0f}, max{1.0f};
  std::vector<FigurePolygon> polygons;
  std::vector<FigureCircle> circles;
  std::vector<FigureLine> lines;
  std::vector<FigureText> texts;
};

struct FigureStyle {
  bool slides = true;            // true: clear colours on white; false: the editor's dark theme
  bool showGhost = true;         // the previous sub-step, faded
  bool showReach = true;         // the reach circle (sum of bone lengths)
  glm::vec3 viewDirection{0.0f, 0.0f, 1.0f};  // 3D chains: projected along this onto the figure plane
  // A ground grid (the XZ plane through the base, Y up) and the X / Y / Z axes through the
  // base in red / green / blue (Blender's colours), so an orbited 3D view shows which way is up.
  bool showGround = false;
};

// Run `run` of the comparison at its cursor: the chain, the target, the ghost, and what the
// step did (CCD: joint->effector and joint->target lines with the angle; FABRIK: the
// target-anchored backward chain and the root-anchored forward chain in their colours;
// two-bone: unreachable regions shaded and both elbow solutions), titled with the solver,
// the iteration and the error.
Figure drawSolverStep(const SolverComparison& comparison, int run, const FigureStyle& style);

// Error against iteration, log scale, one series per run, in the solvers' colours, revealed
// up to each run's cursor (SolverRun::convergenceSoFar) with a ring at the cursor's point;
// the axes span the whole runs, so they stay put while the steps are taken.
Figure drawConvergencePlot(const SolverComparison& comparison, const FigureStyle& style);

// A solver's name on figures ("Jacobian DLS"; abbreviated: "J DLS", for narrow labels).
std::string solverDisplayName(IkSolver solver, bool abbreviated = false);

// The colour each solver is drawn in (figures, plot, editor).
Rgba solverColor(IkSolver solver);

// Where figure point p lands in a width x height image (pixel units, y down): [min, max]
// scaled uniformly to fit and centred. rasterizeFigure and tests use the same mapping.
glm::vec2 figureToPixel(const Figure& figure, int width, int height, glm::vec2 p);
// Where a 3D chain position lands on the figure plane (FigureProjection along the style's
// view direction: x, y for the board's view along Z).
glm::vec2 projectToFigure(const glm::vec3& p, const FigureStyle& style);

// Anti-aliased CPU rasterisation into a width x height RGBA image (background white when
// style.slides, else dark).
Image rasterizeFigure(const Figure& figure, int width, int height, bool slides = true);

}  // namespace kinema
