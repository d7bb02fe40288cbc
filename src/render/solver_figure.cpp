// Teaching figures (issue 10): what one solver's step looks like, as 2D vector primitives
// that the editor draws with ImGui and `kinema demo` rasterises here on the CPU.
#include "render/solver_figure.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "render/raster_draw.h"

namespace kinema {

namespace {

struct Palette {
  Rgba ink, faint, ghost, target, reach, unreachable, backward, forward, elbowA, elbowB, base;
};

Palette paletteFor(const FigureStyle& style) {
  if (style.slides)
    return {{30, 30, 30, 255},   {120, 120, 120, 255}, {185, 185, 185, 255}, {215, 40, 40, 255},
            {150, 150, 150, 255}, {230, 60, 60, 45},   {200, 50, 150, 255},  {31, 119, 180, 255},
            {44, 160, 44, 255},  {148, 103, 189, 255}, {60, 60, 60, 255}};
  return {{230, 230, 230, 255}, {160, 160, 160, 255}, {100, 100, 105, 255}, {255, 90, 90, 255},
          {120, 120, 125, 255}, {255, 80, 80, 50},    {240, 110, 200, 255}, {90, 170, 240, 255},
          {110, 210, 110, 255}, {190, 150, 240, 255}, {200, 200, 200, 255}};
}

std::string format(const char* fmt, double a) {
  char buf[64];
  std::snprintf(buf, sizeof buf, fmt, a);
  return buf;
}

void addChain(Figure& f, const std::vector<glm::vec2>& pts, Rgba color, float width, bool dashed, float dot) {
  for (size_t i = 1; i < pts.size(); ++i) f.lines.push_back({pts[i - 1], pts[i], color, width, dashed});
  for (const glm::vec2& p : pts) {
    FigureCircle c;
    c.center = p;
    c.pixelRadius = dot;
    c.color = color;
    c.filled = true;
    f.circles.push_back(c);
  }
}

std::vector<glm::vec2> project(const std::vector<glm::vec3>& ps, const FigureStyle& style) {
  std::vector<glm::vec2> out;
  out.reserve(ps.size());
  for (const glm::vec3& p : ps) out.push_back(projectToFigure(p, style));
  return out;
}

std::vector<glm::vec2> circlePoints(glm::vec2 c, float r, int n) {
  std::vector<glm::vec2> out;
  for (int i = 0; i < n; ++i) {
    const float a = glm::two_pi<float>() * static_cast<float>(i) / static_cast<float>(n);
    out.push_back(c + r * glm::vec2(std::cos(a), std::sin(a)));
  }
  return out;
}

// The bounds of everything the comparison will ever show, so every step of every solver
// is drawn at the same scale (steps flip like slides without the view jumping).
void fitBounds(Figure& f, const SolverComparison& c, const FigureStyle& style) {
  const glm::vec2 base = projectToFigure(c.setup.chain.base, style);
  const float reach = c.setup.chain.reach();
  glm::vec2 lo = base - glm::vec2(reach), hi = base + glm::vec2(reach);
  const glm::vec2 t = projectToFigure(c.setup.target, style);
  lo = glm::min(lo, t);
  hi = glm::max(hi, t);
  for (const SolverRun& r : c.runs)
    for (const IkTraceEntry& e : r.trace.entries)
      for (const glm::vec3& p : e.positions) {
        const glm::vec2 q = projectToFigure(p, style);
        lo = glm::min(lo, q);
        hi = glm::max(hi, q);
      }
  const glm::vec2 size = glm::max(hi - lo, glm::vec2(1e-3f));
  f.min = lo - 0.06f * size;
  f.max = hi + 0.06f * size;
  f.max.y += 0.16f * size.y;  // room for the title lines
}

// Both elbow positions of a two-bone chain for the target clamped onto the reachable ring.
void addElbowSolutions(Figure& f, const SolverComparison& c, const FigureStyle& style, const Palette& pal) {
  const float l1 = c.setup.chain.boneLengths[0], l2 = c.setup.chain.boneLengths[1];
  const glm::vec2 base = projectToFigure(c.setup.chain.base, style);
  const glm::vec2 toTarget = projectToFigure(c.setup.target, style) - base;
  const float dist = glm::length(toTarget);
  const float inner = std::abs(l1 - l2), outer = l1 + l2;
  // Unreachable: outside the outer circle (a frame with a circular hole) and inside the
  // inner one. The frame and the hole are one contour joined by a seam (even-odd fill).
  FigurePolygon outside;
  outside.color = pal.unreachable;
  // The frame reaches well past the figure so that any image aspect is shaded to its edges.
  const glm::vec2 extra = 2.0f * (f.max - f.min);
  const glm::vec2 a = f.min - extra, b = f.max + extra;
  outside.points = {{b.x, base.y}, {b.x, b.y}, {a.x, b.y}, {a.x, a.y}, {b.x, a.y}, {b.x, base.y}};
  for (int i = 0; i <= 96; ++i) {
    // The seam must be exactly horizontal at both ends (sin(2 pi) is not 0 in floats), or
    // one row of samples sees a crossing there and leaves a streak.
    const float ang = -glm::two_pi<float>() * static_cast<float>(i % 96) / 96.0f;
    outside.points.push_back(base + outer * glm::vec2(std::cos(ang), std::sin(ang)));
  }
  f.polygons.push_back(outside);
  if (inner > 1e-6f) f.polygons.push_back({circlePoints(base, inner, 64), pal.unreachable});
  FigureCircle ring;
  ring.center = base;
  ring.radius = inner;
  ring.color = pal.reach;
  ring.width = 1.0f;
  if (inner > 1e-6f) f.circles.push_back(ring);
  FigureText label;
  label.color = pal.target;
  label.scale = 1;
  label.text = "no solution";
  label.at = base + glm::vec2(-0.5f * inner, -1.08f * inner);
  if (inner > 1e-6f) f.texts.push_back(label);
  label.at = base + glm::vec2(0.72f * outer, 0.78f * outer);
  f.texts.push_back(label);
  if (!(dist > 1e-6f)) return;
  const float d = std::clamp(dist, inner, outer);
  const glm::vec2 u = toTarget / dist;
  const float cosA = std::clamp((l1 * l1 + d * d - l2 * l2) / (2.0f * l1 * d), -1.0f, 1.0f);
  const float angle = std::acos(cosA);
  const glm::vec2 reached = base + d * u;
  const Rgba colors[2] = {pal.elbowA, pal.elbowB};
  for (int side = 0; side < 2; ++side) {
    const float s = side == 0 ? angle : -angle;
    const glm::vec2 dir(u.x * std::cos(s) - u.y * std::sin(s), u.x * std::sin(s) + u.y * std::cos(s));
    const glm::vec2 elbow = base + l1 * dir;
    f.lines.push_back({base, elbow, colors[side], 2.0f, true});
    f.lines.push_back({elbow, reached, colors[side], 2.0f, true});
    FigureText t;
    t.at = elbow + glm::vec2(0.04f, 0.0f) * outer;
    t.text = side == 0 ? "elbow A" : "elbow B";
    t.color = colors[side];
    t.scale = 1;
    f.texts.push_back(t);
  }
}

// The ground grid through the base (XZ plane), cells of a round length (1, 2 or 5 x 10^n)
// about a fifth of the reach, out to twice the reach; then the axes through the base.
void addGround(Figure& f, const SolverComparison& c, const FigureStyle& style) {
  const glm::vec3 base = c.setup.chain.base;
  const float reach = std::max(c.setup.chain.reach(), 1e-3f);
  const float rough = reach / 5.0f, decade = std::pow(10.0f, std::floor(std::log10(rough)));
  const float cell = rough >= 5.0f * decade ? 5.0f * decade : rough >= 2.0f * decade ? 2.0f * decade : decade;
  const int n = static_cast<int>(std::ceil(2.0f * reach / cell));
  const float extent = static_cast<float>(n) * cell;
  const Rgba grid = style.slides ? Rgba{215, 215, 215, 255} : Rgba{62, 62, 68, 255};
  auto line = [&](glm::vec3 a, glm::vec3 b, Rgba col, float width) {
    f.lines.push_back({projectToFigure(base + a, style), projectToFigure(base + b, style), col, width, false});
  };
  for (int i = -n; i <= n; ++i) {
    if (i == 0) continue;  // the axes go there
    const float v = static_cast<float>(i) * cell;
    line({v, 0, -extent}, {v, 0, extent}, grid, 1.0f);
    line({-extent, 0, v}, {extent, 0, v}, grid, 1.0f);
  }
  const Rgba x{255, 51, 82, 255}, y{139, 220, 0, 255}, z{40, 144, 255, 255};  // Blender's axis colours
  line({-extent, 0, 0}, {extent, 0, 0}, x, 1.5f);
  line({0, 0, -extent}, {0, 0, extent}, z, 1.5f);
  line({0, 0, 0}, {0, reach, 0}, y, 1.5f);
  const char* names[3] = {"X", "Y", "Z"};
  const glm::vec3 ends[3] = {{0.6f * reach, 0, 0}, {0, reach, 0}, {0, 0, 0.6f * reach}};
  const Rgba colors[3] = {x, y, z};
  for (int k = 0; k < 3; ++k) f.texts.push_back({projectToFigure(base + ends[k], style), names[k], colors[k], 1});
}

}  // namespace

std::string solverDisplayName(IkSolver s, bool abbreviated) {
  switch (s) {
    case IkSolver::Ccd: return "CCD";
    case IkSolver::Fabrik: return "FABRIK";
    case IkSolver::TwoBone: return abbreviated ? "two-bone" : "Two-bone (analytic)";
    case IkSolver::JacobianTranspose: return abbreviated ? "J^T" : "Jacobian transpose";
    case IkSolver::JacobianPinv: return abbreviated ? "J pinv" : "Jacobian pseudo-inverse";
    case IkSolver::JacobianDls: return abbreviated ? "J DLS" : "Jacobian DLS";
    case IkSolver::JacobianSdls: return abbreviated ? "J SDLS" : "Jacobian SDLS";
  }
  return toString(s);
}

Rgba solverColor(IkSolver solver) {
  switch (solver) {
    case IkSolver::Ccd: return {214, 96, 22, 255};
    case IkSolver::Fabrik: return {31, 119, 180, 255};
    case IkSolver::JacobianDls: return {44, 160, 44, 255};
    case IkSolver::JacobianTranspose: return {148, 103, 189, 255};
    case IkSolver::JacobianPinv: return {140, 86, 75, 255};
    case IkSolver::JacobianSdls: return {227, 119, 194, 255};
    case IkSolver::TwoBone: return {23, 160, 180, 255};
  }
  return {0, 0, 0, 255};
}

glm::vec2 projectToFigure(const glm::vec3& p, const FigureStyle& style) {
  return FigureProjection::along(style.viewDirection).project(p);
}

Figure drawSolverStep(const SolverComparison& c, int runIndex, const FigureStyle& style) {
  Figure f;
  if (runIndex < 0 || runIndex >= static_cast<int>(c.runs.size())) return f;
  const SolverRun& run = c.runs[runIndex];
  if (run.trace.entries.empty()) return f;
  const Palette pal = paletteFor(style);
  fitBounds(f, c, style);
  const IkTraceEntry& e = run.current();
  const IkTraceEntry* prev = style.showGhost ? run.previous() : nullptr;
  const glm::vec2 base = projectToFigure(c.setup.chain.base, style);
  const glm::vec2 target = projectToFigure(c.setup.target, style);
  const float reach = c.setup.chain.reach();
  const bool twoBone = c.setup.chain.boneLengths.size() == 2;

  if (style.showGround) addGround(f, c, style);
  if (twoBone) addElbowSolutions(f, c, style, pal);
  if (style.showReach) {
    FigureCircle r;
    r.center = base;
    r.radius = reach;
    r.color = pal.reach;
    r.width = 1.5f;
    f.circles.push_back(r);
  }
  // The base: a small grey square the root is pinned to.
  const float s = 0.03f * reach;
  f.polygons.push_back({{base + glm::vec2(-s, -s), base + glm::vec2(s, -s), base + glm::vec2(s, s), base + glm::vec2(-s, s)},
                        pal.base});

  const std::vector<glm::vec2> now = project(e.positions, style);
  std::string what;
  // FABRIK's forward pass shows the backward chain it followed, in its colour, instead of
  // the plain ghost (they are the same entry).
  const bool forwardAfterBackward = e.step == IkStep::FabrikForward && run.previous() &&
                                    run.previous()->step == IkStep::FabrikBackward;
  if (forwardAfterBackward)
    addChain(f, project(run.previous()->positions, style), pal.backward, 2.0f, true, 3.0f);
  else if (prev)
    addChain(f, project(prev->positions, style), pal.ghost, 2.0f, true, 3.0f);
  Rgba chainColor = solverColor(run.solver);
  if (e.step == IkStep::CcdJoint && prev) {
    // The joint just turned, the effector before and after, and the target.
    int slot = -1;
    for (size_t k = 0; k < run.trace.joints.size(); ++k)
      if (run.trace.joints[k] == e.joint) slot = static_cast<int>(k);
    if (slot >= 0 && !now.empty()) {
      const glm::vec2 j = now[slot];
      const glm::vec2 before = projectToFigure(prev->positions.back(), style), after = now.back();
      f.lines.push_back({j, before, pal.faint, 1.5f, false});
      f.lines.push_back({j, target, pal.target, 1.5f, true});
      const glm::vec2 u = before - j, v = after - j;
      float turned = 0.0f;
      if (glm::length(u) > 1e-9f && glm::length(v) > 1e-9f)
        turned = std::atan2(u.x * v.y - u.y * v.x, glm::dot(u, v));
      // The angle as an arc at the joint.
      const float radius = 0.45f * std::min(glm::length(u), glm::length(v));
      const float a0 = std::atan2(u.y, u.x);
      const int n = 24;
      for (int i = 0; i < n; ++i) {
        const float t0 = a0 + turned * static_cast<float>(i) / n, t1 = a0 + turned * static_cast<float>(i + 1) / n;
        f.lines.push_back({j + radius * glm::vec2(std::cos(t0), std::sin(t0)), j + radius * glm::vec2(std::cos(t1), std::sin(t1)),
                           pal.ink, 1.5f, false});
      }
      FigureText t;
      t.at = j + radius * 1.25f * glm::vec2(std::cos(a0 + 0.5f * turned), std::sin(a0 + 0.5f * turned));
      t.text = format("%.1f deg", glm::degrees(static_cast<double>(turned)));
      t.color = pal.ink;
      t.scale = 1;
      f.texts.push_back(t);
      what = "turned joint j" + std::to_string(e.joint) + format(" by %.1f deg", glm::degrees(static_cast<double>(turned)));
    }
  } else if (e.step == IkStep::FabrikBackward) {
    chainColor = pal.backward;
    if (!now.empty()) f.lines.push_back({base, now.front(), pal.backward, 1.5f, true});
    what = "backward pass: effector on the target, root pulled off its base";
  } else if (e.step == IkStep::FabrikForward) {
    chainColor = pal.forward;
    what = "forward pass: root back on its base, bones towards the backward chain";
  } else if (e.step == IkStep::Start) {
    what = "start";
  } else if (e.step == IkStep::Straighten) {
    what = "target out of reach: chain straightened towards it";
  } else if (e.step == IkStep::JacobianStep) {
    what = "one damped least squares step (all joints at once)";
  } else if (e.step == IkStep::TwoBone) {
    what = "law of cosines: solved in one step";
  }
  addChain(f, now, chainColor, 3.5f, false, now.size() > 8 ? 3.0f : 4.5f);  // long chains: smaller dots
  FigureCircle t;
  t.center = target;
  t.pixelRadius = 8.0f;
  t.color = pal.target;
  t.width = 2.5f;
  f.circles.push_back(t);
  const float tick = 0.035f * reach;
  f.lines.push_back({target - glm::vec2(tick, 0), target + glm::vec2(tick, 0), pal.target, 1.5f, false});
  f.lines.push_back({target - glm::vec2(0, tick), target + glm::vec2(0, tick), pal.target, 1.5f, false});

  const glm::vec2 size = f.max - f.min;
  FigureText title;
  title.at = {f.min.x + 0.02f * size.x, f.max.y - 0.015f * size.y};
  title.text = solverDisplayName(run.solver) + "  it " + std::to_string(e.iteration) + "  step " +
               std::to_string(run.cursor) + "/" + std::to_string(run.trace.entries.size() - 1) +
               format("  error %.3g", static_cast<double>(e.error));
  title.color = pal.ink;
  f.texts.push_back(title);
  FigureText sub = title;
  sub.at.y -= 0.06f * size.y;
  sub.text = what;
  sub.color = pal.faint;
  sub.scale = 1;
  f.texts.push_back(sub);
  return f;
}

Figure drawConvergencePlot(const SolverComparison& c, const FigureStyle& style) {
  // A fixed 1.6 x 1 box; the plot area inside maps iterations to x and log10(error) to y.
  Figure f;
  f.min = {0.0f, 0.0f};
  f.max = {1.6f, 1.0f};
  const Palette pal = paletteFor(style);
  const glm::vec2 lo(0.16f, 0.1f), hi(1.2f, 0.86f);
  int iterations = 1;
  float emax = 1e-7f, emin = 1e30f;
  // The axes fit the whole runs (the view does not jump as steps are taken); the curves
  // show only what the cursors have reached.
  std::vector<std::vector<float>> series, shown;
  for (const SolverRun& r : c.runs) {
    series.push_back(r.convergence());
    shown.push_back(r.convergenceSoFar());
    iterations = std::max(iterations, static_cast<int>(series.back().size()) - 1);
    for (float e : series.back()) {
      emax = std::max(emax, e);
      if (e > 0.0f) emin = std::min(emin, e);
    }
  }
  const float floorError = 1e-7f;
  emin = std::max(floorError, std::min(emin, c.setup.settings.tolerance > 0 ? c.setup.settings.tolerance : emin));
  const int d0 = static_cast<int>(std::floor(std::log10(emin))), d1 = static_cast<int>(std::ceil(std::log10(emax)));
  const int d1c = std::max(d1, d0 + 1);
  auto map = [&](float it, float err) {
    const float le = std::log10(std::max(err, floorError));
    return glm::vec2(lo.x + (hi.x - lo.x) * it / static_cast<float>(iterations),
                     lo.y + (hi.y - lo.y) * (le - static_cast<float>(d0)) / static_cast<float>(d1c - d0));
  };
  const Rgba grid = style.slides ? Rgba{225, 225, 225, 255} : Rgba{70, 70, 75, 255};
  for (int d = d0; d <= d1c; ++d) {
    const float y = map(0.0f, std::pow(10.0f, static_cast<float>(d))).y;
    f.lines.push_back({{lo.x, y}, {hi.x, y}, grid, 1.0f, false});
    FigureText t;
    t.at = {0.02f, y + 0.015f};
    t.text = "1e" + std::to_string(d);
    t.color = pal.faint;
    t.scale = 1;
    f.texts.push_back(t);
  }
  const int xticks = std::min(iterations, 10);
  for (int k = 0; k <= xticks; ++k) {
    const int it = static_cast<int>(std::lround(static_cast<double>(iterations) * k / xticks));
    const float x = map(static_cast<float>(it), 1.0f).x;
    f.lines.push_back({{x, lo.y}, {x, hi.y}, grid, 1.0f, false});
    FigureText t;
    t.at = {x - 0.01f, lo.y - 0.015f};
    t.text = std::to_string(it);
    t.color = pal.faint;
    t.scale = 1;
    f.texts.push_back(t);
  }
  f.lines.push_back({lo, {hi.x, lo.y}, pal.ink, 1.5f, false});
  f.lines.push_back({lo, {lo.x, hi.y}, pal.ink, 1.5f, false});
  if (c.setup.settings.tolerance > 0.0f) {
    const float y = map(0.0f, c.setup.settings.tolerance).y;
    f.lines.push_back({{lo.x, y}, {hi.x, y}, pal.target, 1.0f, true});
    f.texts.push_back({{hi.x + 0.01f, y + 0.015f}, "tolerance", pal.target, 1});
  }
  for (size_t r = 0; r < shown.size(); ++r) {
    const Rgba col = solverColor(c.runs[r].solver);
    const std::vector<float>& so = shown[r];
    for (size_t k = 1; k < so.size(); ++k)
      f.lines.push_back({map(static_cast<float>(k - 1), so[k - 1]), map(static_cast<float>(k), so[k]), col, 2.5f, false});
    for (size_t k = 0; k < so.size(); ++k) {
      FigureCircle dot;
      dot.center = map(static_cast<float>(k), so[k]);
      dot.pixelRadius = 3.0f;
      dot.color = col;
      dot.filled = true;
      f.circles.push_back(dot);
    }
    if (!so.empty() && !c.runs[r].finished()) {
      // Where the cursor is: a ring around the newest point (a finished curve simply ends).
      FigureCircle now;
      now.center = map(static_cast<float>(so.size() - 1), so.back());
      now.pixelRadius = 7.0f;
      now.color = col;
      now.width = 2.0f;
      f.circles.push_back(now);
    }
    FigureText legend;
    legend.at = {hi.x + 0.04f, hi.y - 0.08f * static_cast<float>(r)};
    // The iteration count so far; the total once the run is at its end.
    legend.text = solverDisplayName(c.runs[r].solver) +
                  (c.runs[r].finished() ? " (" + std::to_string(c.runs[r].result.iterations) + ")"
                                        : "  it " + std::to_string(std::max(0, c.runs[r].current().iteration)));
    legend.color = col;
    legend.scale = 1;
    f.texts.push_back(legend);
  }
  f.texts.push_back({{lo.x, 0.985f}, "Largest effector error per iteration (log scale): " + c.setup.title, pal.ink, 1});
  f.texts.push_back({{0.5f * (lo.x + hi.x) - 0.05f, 0.045f}, "iteration", pal.faint, 1});
  return f;
}

glm::vec2 figureToPixel(const Figure& f, int width, int height, glm::vec2 p) {
  const glm::vec2 size = glm::max(f.max - f.min, glm::vec2(1e-9f));
  const float scale = std::min(static_cast<float>(width) / size.x, static_cast<float>(height) / size.y);
  const glm::vec2 offset = 0.5f * (glm::vec2(width, height) - scale * size);
  return {offset.x + (p.x - f.min.x) * scale, static_cast<float>(height) - (offset.y + (p.y - f.min.y) * scale)};
}

Image rasterizeFigure(const Figure& f, int width, int height, bool slides) {
  Image img(std::max(1, width), std::max(1, height));
  const std::uint8_t bg = slides ? 255 : 32;
  for (size_t i = 0; i < img.rgba.size(); i += 4) {
    img.rgba[i] = img.rgba[i + 1] = img.rgba[i + 2] = bg;
    img.rgba[i + 3] = 255;
  }
  const glm::vec2 size = glm::max(f.max - f.min, glm::vec2(1e-9f));
  const float scale = std::min(static_cast<float>(img.width) / size.x, static_cast<float>(img.height) / size.y);
  auto px = [&](glm::vec2 p) { return figureToPixel(f, img.width, img.height, p); };
  auto rgb = [](const Rgba& c) { return raster::Rgb{c[0], c[1], c[2]}; };
  auto alpha = [](const Rgba& c) { return static_cast<float>(c[3]) / 255.0f; };
  const glm::ivec4 clip(0, 0, img.width, img.height);
  for (const FigurePolygon& p : f.polygons) {
    std::vector<glm::vec2> pts;
    for (const glm::vec2& q : p.points) pts.push_back(px(q));
    raster::polygon(img, pts, rgb(p.color), alpha(p.color));
  }
  for (const FigureCircle& c : f.circles) {
    const float r = c.pixelRadius > 0.0f ? c.pixelRadius : c.radius * scale;
    if (c.filled)
      raster::dot(img, px(c.center), r, rgb(c.color), alpha(c.color));
    else
      raster::ring(img, px(c.center), r, c.width, rgb(c.color), alpha(c.color));
  }
  for (const FigureLine& l : f.lines) {
    const glm::vec2 a = px(l.a), b = px(l.b);
    if (!l.dashed) {
      raster::line(img, a, b, l.width, rgb(l.color), clip, alpha(l.color));
      continue;
    }
    // Dashes of 8 pixels with 6-pixel gaps.
    const float len = glm::length(b - a);
    if (!(len > 0.0f)) continue;
    const glm::vec2 u = (b - a) / len;
    for (float t = 0.0f; t < len; t += 14.0f)
      raster::line(img, a + t * u, a + std::min(len, t + 8.0f) * u, l.width, rgb(l.color), clip, alpha(l.color));
  }
  for (const FigureText& t : f.texts) {
    const glm::vec2 p = px(t.at);
    int textScale = std::max(1, t.scale);  // titles shrink rather than leave the image
    while (textScale > 1 && p.x + static_cast<float>(raster::textWidth(t.text) * textScale) > static_cast<float>(img.width))
      --textScale;
    raster::text(img, static_cast<int>(std::lround(p.x)), static_cast<int>(std::lround(p.y)), t.text, rgb(t.color), textScale);
  }
  return img;
}

}  // namespace kinema
