// The "Compare solvers" mode drawn with ImGui: the views and the plot on the background
// draw list (no window, so the mouse reaches the mode's own drag handling), the toolbar,
// the numbers and the chain settings in panels.
#include "editor/panels/compare_panel.h"

#include <imgui.h>

#include <cfloat>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

#include "editor/panels/item_names.h"
#include "editor/panels/command_widgets.h"
#include "editor/panels/panel_layout.h"
#include "render/solver_figure.h"

namespace kinema {

namespace {

ImU32 color(const Rgba& c) { return IM_COL32(c[0], c[1], c[2], c[3]); }
ImVec2 im(glm::vec2 p) { return ImVec2(p.x, p.y); }

FigureStyle editorStyle(const CompareMode& m) {
  FigureStyle s;
  s.slides = false;  // the editor's dark theme
  s.viewDirection = m.viewDirection();
  s.showGround = m.view3d;  // an orbit needs the floor and the axes to read as 3D
  return s;
}

// A polygon filled by the even-odd rule (the figures' regions may have holes: a frame with
// the reach circle cut out), as horizontal spans 2 px high.
void fillEvenOdd(ImDrawList* dl, const FigurePolygon& poly, const FigureViewMap& map, const CompareRect& r) {
  if (poly.points.size() < 3) return;
  std::vector<glm::vec2> px;
  float top = r.y + r.h, bottom = r.y;
  for (const glm::vec2& q : poly.points) {
    px.push_back(map.toPixel(q));
    top = std::min(top, px.back().y);
    bottom = std::max(bottom, px.back().y);
  }
  top = std::max(top, r.y);
  bottom = std::min(bottom, r.y + r.h);
  std::vector<float> xs;
  for (float y = std::floor(top); y < bottom; y += 2.0f) {
    const float yc = y + 1.0f;  // the span's centre row
    xs.clear();
    for (size_t i = 0; i < px.size(); ++i) {
      const glm::vec2 a = px[i], b = px[(i + 1) % px.size()];
      if ((a.y <= yc) != (b.y <= yc)) xs.push_back(a.x + (yc - a.y) / (b.y - a.y) * (b.x - a.x));
    }
    std::sort(xs.begin(), xs.end());
    for (size_t k = 0; k + 1 < xs.size(); k += 2) {
      const float x0 = std::max(xs[k], r.x), x1 = std::min(xs[k + 1], r.x + r.w);
      if (x1 > x0) dl->AddRectFilled(ImVec2(x0, y), ImVec2(x1, y + 2.0f), color(poly.color));
    }
  }
}

// A figure's primitives in the rect through the map, in Figure's order (polygons, circles,
// lines, texts), clipped to the rect.
void drawFigure(ImDrawList* dl, const Figure& f, const FigureViewMap& map, const CompareRect& r) {
  dl->PushClipRect(ImVec2(r.x, r.y), ImVec2(r.x + r.w, r.y + r.h), true);
  for (const FigurePolygon& p : f.polygons) fillEvenOdd(dl, p, map, r);
  for (const FigureCircle& c : f.circles) {
    const float radius = c.pixelRadius > 0 ? c.pixelRadius : c.radius * map.pixelsPerUnit;
    const int segments = std::clamp(int(radius * 0.5f), 12, 96);
    if (c.filled)
      dl->AddCircleFilled(im(map.toPixel(c.center)), radius, color(c.color), segments);
    else
      dl->AddCircle(im(map.toPixel(c.center)), radius, color(c.color), segments, c.width);
  }
  for (const FigureLine& l : f.lines) {
    const glm::vec2 a = map.toPixel(l.a), b = map.toPixel(l.b);
    if (!l.dashed) {
      dl->AddLine(im(a), im(b), color(l.color), l.width);
      continue;
    }
    const float len = glm::length(b - a), dash = 6.0f;
    for (float t = 0; t < len; t += 2 * dash)
      dl->AddLine(im(a + (b - a) * (t / len)), im(a + (b - a) * (std::min(t + dash, len) / len)), color(l.color), l.width);
  }
  // Wrapped at the view's right edge, so a long caption or plot title is never cut; a text
  // that a wrapped one above would overlap (a caption's subtitle at 2x) moves below it.
  std::vector<ImVec4> wrapped;  // x0, y0, x1, y1 of the texts that took several lines
  for (const FigureText& t : f.texts) {
    glm::vec2 at = map.toPixel(t.at);
    const float wrap = std::max(r.x + r.w - at.x - 4.0f, ImGui::GetFontSize() * 4.0f);
    const ImVec2 size = ImGui::GetFont()->CalcTextSizeA(ImGui::GetFontSize(), FLT_MAX, wrap, t.text.c_str());
    for (const ImVec4& w : wrapped)
      if (at.x < w.z && at.x + size.x > w.x && at.y < w.w && at.y + size.y > w.y) at.y = w.w;
    dl->AddText(ImGui::GetFont(), ImGui::GetFontSize(), im(at), color(t.color), t.text.c_str(), nullptr, wrap);
    if (size.y > ImGui::GetFontSize() * 1.5f) wrapped.push_back(ImVec4(at.x, at.y, at.x + size.x, at.y + size.y));
  }
  dl->PopClipRect();
}

// Bounds every view shares: the reach around the base, the target and what the figures draw.
void updateFigureBounds(CompareMode& m, const std::vector<Figure>& figures) {
  const SolverComparison& c = m.comparison;
  const FigureProjection proj = FigureProjection::along(m.viewDirection());
  const glm::vec2 base = proj.project(c.setup.chain.base), target = proj.project(c.setup.target);
  const float reach = c.setup.chain.reach();
  glm::vec2 lo = glm::min(base - glm::vec2(reach), target), hi = glm::max(base + glm::vec2(reach), target);
  for (const Figure& f : figures) {
    lo = glm::min(lo, f.min);
    hi = glm::max(hi, f.max);
  }
  const glm::vec2 pad = (hi - lo) * 0.04f;
  m.figureMin = lo - pad;
  m.figureMax = hi + pad;
}

void drawToolbar(CommandContext& ctx) {
  CompareMode& m = ctx.state.compare;
  const CompareRect r = m.layout.toolbar;
  ImGui::SetNextWindowPos(ImVec2(r.x, r.y), ImGuiCond_Always);
  ImGui::SetNextWindowSize(ImVec2(r.w, r.h), ImGuiCond_Always);
  ImGui::Begin("Compare Solvers##toolbar", nullptr, kPanelFlags | ImGuiWindowFlags_NoTitleBar);
  const TeachingCase* shown = findTeachingPreset(m.preset);
  ImGui::SetNextItemWidth(260);
  const bool presetOpen = ImGui::BeginCombo("##preset", shown ? shown->title.c_str() : "Preset");
  recordItem("Compare/Preset");
  if (presetOpen) {
    for (const TeachingCase& p : teachingPresets()) {
      if (ImGui::Selectable(p.title.c_str(), p.name == m.preset)) openComparePreset(m, p.name);
      recordItem("Compare/Preset/" + p.name);
    }
    ImGui::EndCombo();
  }
  ImGui::SameLine();
  // The mode's commands (compare_commands.cpp), the same as its keys.
  const char* window = "Compare Solvers";
  commandButton(ctx, "compare.step", window, "Step");
  ImGui::SameLine();
  commandButton(ctx, "compare.iteration", window, "Iteration");
  ImGui::SameLine();
  commandButton(ctx, "compare.play", window, m.playing ? "Pause" : "Play");
  ImGui::SameLine();
  commandButton(ctx, "compare.run_to_end", window, "Run to end");
  ImGui::SameLine();
  commandButton(ctx, "compare.reset", window, "Reset");
  ImGui::SameLine();
  commandButton(ctx, "compare.exit", window, "Exit");
  ImGui::SetNextItemWidth(200);
  ImGui::SliderFloat("steps/s", &m.stepsPerSecond, 0.25f, 60.0f, "%.2f", ImGuiSliderFlags_Logarithmic);
  ImGui::SameLine();
  bool planar = !m.view3d;
  if (ImGui::RadioButton("2D", planar)) setCompareView3d(m, false);
  recordItem("Compare/2D");
  ImGui::SameLine();
  if (ImGui::RadioButton("3D", !planar)) setCompareView3d(m, true);
  recordItem("Compare/3D");
  ImGui::SameLine();
  if (!m.error.empty())
    ImGui::TextColored(ImVec4(1.0f, 0.45f, 0.4f, 1.0f), "%s", m.error.c_str());
  else
    ImGui::TextDisabled("Right: step  Shift+Right: iteration  Space: play  End: run  R: reset  drag target/joints");
  ImGui::End();
}

void drawChainPanel(CompareMode& m) {
  const CompareRect r = m.layout.side;
  ImGui::SetNextWindowPos(ImVec2(r.x, r.y), ImGuiCond_Always);
  ImGui::SetNextWindowSize(ImVec2(r.w, r.h), ImGuiCond_Always);
  ImGui::Begin("Chain##compare", nullptr, kPanelFlags);
  if (!m.ready()) {
    ImGui::TextWrapped("Choose a preset.");
    ImGui::End();
    return;
  }
  TeachingCase setup = m.comparison.setup;
  ImGui::TextWrapped("%s", setup.description.c_str());
  ImGui::Separator();
  bool changed = false;
  int bones = static_cast<int>(setup.chain.boneLengths.size());
  ImGui::SetNextItemWidth(120);
  if (ImGui::SliderInt("bones", &bones, 1, 24)) {
    const float last = setup.chain.boneLengths.empty() ? 1.0f : setup.chain.boneLengths.back();
    setup.chain.boneLengths.resize(bones, last);
    setup.chain.startAngles.resize(bones, 0.0f);
    if (!setup.chain.limits.empty()) setup.chain.limits.resize(bones + 1, setup.chain.limits.front());
    changed = true;
  }
  float tolerance = setup.settings.tolerance;
  ImGui::SetNextItemWidth(120);
  if (ImGui::InputFloat("tolerance", &tolerance, 0.0f, 0.0f, "%.5f", ImGuiInputTextFlags_EnterReturnsTrue) &&
      tolerance >= 0.0f) {
    setup.settings.tolerance = tolerance;
    changed = true;
  }
  ImGui::SetNextItemWidth(120);
  changed |= ImGui::SliderInt("max iterations", &setup.settings.maxIterations, 1, 500);
  // Hinge limits about Z, the same range for every joint (the board's chains are planar).
  bool limited = !setup.chain.limits.empty();
  if (ImGui::Checkbox("hinge limits", &limited)) {
    setup.chain.limits.clear();
    if (limited)
      setup.chain.limits.assign(bones + 1, JointLimit::hinge(glm::vec3(0, 0, 1), -glm::radians(60.0f), glm::radians(60.0f)));
    changed = true;
  }
  if (limited && !setup.chain.limits.empty()) {
    float lo = glm::degrees(setup.chain.limits.front().minAngle), hi = glm::degrees(setup.chain.limits.front().maxAngle);
    ImGui::SetNextItemWidth(120);
    bool range = ImGui::DragFloat("min (deg)", &lo, 0.5f, -180.0f, 0.0f, "%.1f");
    ImGui::SetNextItemWidth(120);
    range |= ImGui::DragFloat("max (deg)", &hi, 0.5f, 0.0f, 180.0f, "%.1f");
    if (range) {
      for (JointLimit& l : setup.chain.limits)
        if (l.active()) l = JointLimit::hinge(l.axis, glm::radians(lo), glm::radians(hi));
      changed = true;
    }
  }
  ImGui::Separator();
  ImGui::TextUnformatted("bone lengths");
  ImGui::BeginChild("##lengths", ImVec2(0, 0));
  for (int i = 0; i < bones; ++i) {
    ImGui::PushID(i);
    ImGui::SetNextItemWidth(120);
    changed |= ImGui::DragFloat("##len", &setup.chain.boneLengths[i], 0.01f, 0.05f, 100.0f, "%.3f");
    ImGui::SameLine();
    ImGui::Text("bone %d", i + 1);
    ImGui::PopID();
  }
  ImGui::EndChild();
  ImGui::End();
  if (changed) restartComparison(m, setup);
}

void drawNumbers(const CompareMode& m) {
  const CompareRect r = m.layout.numbers;
  ImGui::SetNextWindowPos(ImVec2(r.x, r.y), ImGuiCond_Always);
  ImGui::SetNextWindowSize(ImVec2(r.w, r.h), ImGuiCond_Always);
  ImGui::Begin("Numbers##compare", nullptr, kPanelFlags);
  for (const SolverRun& run : m.comparison.runs) {
    const Rgba c = solverColor(run.solver);
    ImGui::TextColored(ImVec4(c[0] / 255.0f, c[1] / 255.0f, c[2] / 255.0f, 1.0f), "%s", toString(run.solver));
    ImGui::Text("  step %d / %d, iteration %d (%s)", run.cursor, int(run.trace.entries.size()) - 1,
                run.current().iteration, toString(run.current().step));
    ImGui::Text("  error %.3g  (final %.3g, %s)", run.current().error, run.result.error,
                run.result.converged ? "converged" : "not converged");
    ImGui::Text("  %d iterations, %.4f ms/iter, %.4f ms total", run.result.iterations, run.millisecondsPerIteration,
                run.totalMilliseconds);
  }
  ImGui::End();
}

}  // namespace

void drawComparePanel(CommandContext& ctx) {
  CompareMode& m = ctx.state.compare;
  ImGuiIO& io = ImGui::GetIO();
  if (!m.ready() && m.error.empty()) openComparePreset(m, teachingPresets().front().name);
  advanceComparePlay(m, io.DeltaTime);
  const PanelRect& panels = ctx.state.layout.panelArea;
  const CompareRect area{panels.x, panels.y, panels.w, panels.h};
  // The toolbar holds two rows of widgets and the side column grows with the text (UI scale).
  const ImGuiStyle& style = ImGui::GetStyle();
  const float toolbarHeight = std::max(kCompareToolbarHeight, ImGui::GetFrameHeightWithSpacing() + ImGui::GetFrameHeight() +
                                                                  2.0f * style.WindowPadding.y);
  const float sideWidth = kCompareSideWidth * std::max(1.0f, ImGui::GetFontSize() / 14.0f);
  m.layout = compareLayout(area, m.ready() ? static_cast<int>(m.comparison.runs.size()) : 2, toolbarHeight, sideWidth);

  ImDrawList* dl = ImGui::GetBackgroundDrawList();
  dl->AddRectFilled(ImVec2(area.x, area.y), ImVec2(area.x + area.w, area.y + area.h), IM_COL32(40, 40, 44, 255));
  if (m.ready()) {
    const FigureStyle style = editorStyle(m);
    std::vector<Figure> figures;
    for (int i = 0; i < static_cast<int>(m.comparison.runs.size()); ++i)
      figures.push_back(drawSolverStep(m.comparison, i, style));
    if (m.drag == CompareDrag::None || m.drag == CompareDrag::Orbit) updateFigureBounds(m, figures);
    for (int i = 0; i < static_cast<int>(figures.size()); ++i) {
      const CompareRect v = m.layout.views[i];
      dl->AddRectFilled(ImVec2(v.x + 2, v.y + 2), ImVec2(v.x + v.w - 2, v.y + v.h - 2), IM_COL32(28, 28, 32, 255));
      drawFigure(dl, figures[i], m.viewMap(i), v);
      const Rgba c = solverColor(m.comparison.runs[i].solver);
      dl->AddRect(ImVec2(v.x + 2, v.y + 2), ImVec2(v.x + v.w - 2, v.y + v.h - 2), IM_COL32(c[0], c[1], c[2], 160));
    }
    const CompareRect p = m.layout.plot;
    dl->AddRectFilled(ImVec2(p.x + 2, p.y + 2), ImVec2(p.x + p.w - 2, p.y + p.h - 2), IM_COL32(28, 28, 32, 255));
    const Figure plot = drawConvergencePlot(m.comparison, style);
    drawFigure(dl, plot, FigureViewMap::fit(plot.min, plot.max, p, 6.0f), p);
  }
  drawToolbar(ctx);
  drawChainPanel(m);
  drawNumbers(m);
}

nlohmann::json compareStateJson(const CompareMode& m) {
  nlohmann::json out = compareModeJson(m);
  for (size_t i = 0; i < m.comparison.runs.size() && i < out["solvers"].size(); ++i) {
    const Rgba c = solverColor(m.comparison.runs[i].solver);
    out["solvers"][i]["color"] = {c[0], c[1], c[2]};
  }
  return out;
}

}  // namespace kinema
