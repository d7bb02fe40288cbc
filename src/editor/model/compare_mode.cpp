#include "editor/model/compare_mode.h"

#include <algorithm>
#include <cmath>

namespace kinema {

CompareLayout compareLayout(const CompareRect& area, int solverCount, float toolbarHeight, float sideWidth) {
  CompareLayout l;
  const int n = std::max(solverCount, 1);
  const float sideW = std::min(sideWidth, area.w * 0.4f);
  l.side = {area.x, area.y, sideW, area.h};
  const float mx = area.x + sideW, mw = std::max(area.w - sideW, 1.0f);
  l.toolbar = {mx, area.y, mw, toolbarHeight};
  const float top = area.y + toolbarHeight, rest = std::max(area.h - toolbarHeight, 2.0f);
  const float viewH = std::floor(rest * 0.62f), viewW = std::floor(mw / n);
  for (int i = 0; i < n; ++i) l.views.push_back({mx + i * viewW, top, viewW, viewH});
  const float bottom = top + viewH, bottomH = std::max(rest - viewH, 1.0f);
  const float plotW = std::floor(mw * 0.6f);
  l.plot = {mx, bottom, plotW, bottomH};
  l.numbers = {mx + plotW, bottom, std::max(mw - plotW, 1.0f), bottomH};
  return l;
}

FigureViewMap FigureViewMap::fit(glm::vec2 min, glm::vec2 max, const CompareRect& rect, float marginPixels) {
  FigureViewMap m;
  const glm::vec2 size = glm::max(max - min, glm::vec2(1e-6f));
  const float w = std::max(rect.w - 2 * marginPixels, 1.0f), h = std::max(rect.h - 2 * marginPixels, 1.0f);
  m.pixelsPerUnit = std::min(w / size.x, h / size.y);
  m.center = (min + max) * 0.5f;
  m.pixelCenter = {rect.x + rect.w * 0.5f, rect.y + rect.h * 0.5f};
  return m;
}
glm::vec2 FigureViewMap::toPixel(glm::vec2 f) const {
  return {pixelCenter.x + (f.x - center.x) * pixelsPerUnit, pixelCenter.y - (f.y - center.y) * pixelsPerUnit};
}
glm::vec2 FigureViewMap::toFigure(glm::vec2 p) const {
  return {center.x + (p.x - pixelCenter.x) / pixelsPerUnit, center.y - (p.y - pixelCenter.y) / pixelsPerUnit};
}

glm::vec3 orbitViewDirection(float yaw, float pitch) {
  return {std::cos(pitch) * std::sin(yaw), std::sin(pitch), std::cos(pitch) * std::cos(yaw)};
}

int hitCompareHandle(const std::vector<glm::vec2>& joints, glm::vec2 target, glm::vec2 mouse, float radius) {
  if (glm::length(mouse - target) <= radius) return kHitTarget;
  int best = kHitNothing;
  float bestD = radius;
  // The root stays where it is (the chain's base): only joints 1..N can be dragged.
  for (int i = 1; i < static_cast<int>(joints.size()); ++i) {
    const float d = glm::length(mouse - joints[i]);
    if (d <= bestD) {
      bestD = d;
      best = i;
    }
  }
  return best;
}

int PlayClock::advance(double dt, double stepsPerSecond) {
  if (!(dt > 0.0) || !(stepsPerSecond > 0.0)) return 0;
  carry += dt * stepsPerSecond;
  const double whole = std::floor(carry + 1e-9);  // 60 x (4/60) is 4 steps, not 3.999...
  carry -= whole;
  return static_cast<int>(std::min(whole, 1000.0));
}

std::vector<glm::vec3> teachingChainPositions(const TeachingChain& chain) {
  std::vector<glm::vec3> out{chain.base};
  float angle = 0.0f;
  for (size_t i = 0; i < chain.boneLengths.size(); ++i) {
    angle += i < chain.startAngles.size() ? chain.startAngles[i] : 0.0f;
    out.push_back(out.back() + chain.boneLengths[i] * glm::vec3(std::cos(angle), std::sin(angle), 0.0f));
  }
  return out;
}

void aimTeachingBone(TeachingChain& chain, int joint, glm::vec3 point) {
  const int bones = static_cast<int>(chain.boneLengths.size());
  if (joint < 1 || joint > bones) return;
  chain.startAngles.resize(chain.boneLengths.size(), 0.0f);
  const std::vector<glm::vec3> p = teachingChainPositions(chain);
  const glm::vec3 from = p[joint - 1];
  const glm::vec2 d(point.x - from.x, point.y - from.y);
  if (!(glm::length(d) > 1e-6f)) return;
  float parentAngle = 0.0f;
  for (int i = 0; i < joint - 1; ++i) parentAngle += chain.startAngles[i];
  float a = std::atan2(d.y, d.x) - parentAngle;
  a = std::remainder(a, 2.0f * glm::pi<float>());  // the same direction, in [-pi, pi]
  chain.startAngles[joint - 1] = a;
}

FigureViewMap CompareMode::viewMap(int view) const {
  const CompareRect r = view >= 0 && view < static_cast<int>(layout.views.size()) ? layout.views[view] : CompareRect{};
  return FigureViewMap::fit(figureMin, figureMax, r);
}

std::string openComparePreset(CompareMode& m, const std::string& name) {
  const TeachingCase* preset = findTeachingPreset(name);
  if (!preset) return m.error = "no preset named '" + name + "' (kinema demo list names them)";
  TeachingCase setup = *preset;
  if (m.view3d) setup.chain.planar = false;
  const std::string err = restartComparison(m, setup);
  if (err.empty()) m.preset = name;
  return err;
}

std::string restartComparison(CompareMode& m, const TeachingCase& setup) {
  SolverComparison next;
  const std::string err = startComparison(setup, next);
  m.error = err;
  if (!err.empty()) return err;
  m.comparison = std::move(next);
  m.playing = false;
  m.clock = PlayClock{};
  return {};
}

std::string setCompareView3d(CompareMode& m, bool view3d) {
  m.view3d = view3d;
  if (!m.ready()) return {};
  TeachingCase setup = m.comparison.setup;
  setup.chain.planar = !view3d;
  if (!view3d) setup.target.z = setup.chain.base.z;  // back on the board
  return restartComparison(m, setup);
}

int advanceComparePlay(CompareMode& m, double dt) {
  if (!m.playing || !m.ready()) return 0;
  int steps = m.clock.advance(dt, m.stepsPerSecond), taken = 0;
  for (; steps > 0; --steps) {
    bool all = true;
    for (const SolverRun& r : m.comparison.runs) all = all && r.finished();
    if (all) {
      m.playing = false;
      break;
    }
    stepSubStep(m.comparison);
    ++taken;
  }
  return taken;
}

std::vector<glm::vec2> compareJointPixels(const CompareMode& m, int view) {
  std::vector<glm::vec2> out;
  if (view < 0 || view >= static_cast<int>(m.comparison.runs.size())) return out;
  const FigureProjection proj = FigureProjection::along(m.viewDirection());
  const FigureViewMap map = m.viewMap(view);
  for (const glm::vec3& p : m.comparison.runs[view].current().positions) out.push_back(map.toPixel(proj.project(p)));
  return out;
}

glm::vec2 compareTargetPixel(const CompareMode& m, int view) {
  const FigureProjection proj = FigureProjection::along(m.viewDirection());
  return m.viewMap(view).toPixel(proj.project(m.comparison.setup.target));
}

bool compareMouseDown(CompareMode& m, glm::vec2 mouse) {
  if (!m.ready()) return false;
  for (int v = 0; v < static_cast<int>(m.layout.views.size()) && v < static_cast<int>(m.comparison.runs.size()); ++v) {
    if (!m.layout.views[v].contains(mouse)) continue;
    const int hit = hitCompareHandle(compareJointPixels(m, v), compareTargetPixel(m, v), mouse);
    m.dragView = v;
    m.lastMouse = mouse;
    m.playing = false;
    if (hit == kHitTarget) {
      m.drag = CompareDrag::Target;
    } else if (hit >= 0) {
      m.drag = CompareDrag::Joint;
      m.dragJoint = hit;
    } else if (m.view3d) {
      m.drag = CompareDrag::Orbit;
    } else {
      m.dragView = -1;
      return false;
    }
    return true;
  }
  return false;
}

bool compareMouseMove(CompareMode& m, glm::vec2 mouse) {
  if (m.drag == CompareDrag::None || !m.ready()) return false;
  const glm::vec2 delta = mouse - m.lastMouse;
  m.lastMouse = mouse;
  if (delta == glm::vec2(0.0f)) return true;
  if (m.drag == CompareDrag::Orbit) {
    m.yaw -= delta.x * 0.01f;
    m.pitch = glm::clamp(m.pitch + delta.y * 0.01f, -1.5f, 1.5f);
    return true;
  }
  const FigureViewMap map = m.viewMap(m.dragView);
  const FigureProjection proj = FigureProjection::along(m.viewDirection());
  if (m.drag == CompareDrag::Target) {
    // The target moves in the plane through it facing the view.
    const glm::vec3 old = m.comparison.setup.target;
    const glm::vec2 now = map.toFigure(mouse), was = proj.project(old);
    const glm::vec3 moved = old + proj.right * (now.x - was.x) + proj.up * (now.y - was.y);
    m.error = setTarget(m.comparison, moved);
    return true;
  }
  // A joint: the start pose's bone before it turns towards the mouse (in the chain's plane).
  TeachingChain chain = m.comparison.setup.chain;
  const glm::vec2 f = map.toFigure(mouse);
  const glm::vec3 onPlane = chain.base + proj.right * (f.x - proj.project(chain.base).x) +
                            proj.up * (f.y - proj.project(chain.base).y);
  aimTeachingBone(chain, m.dragJoint, onPlane);
  m.error = setChain(m.comparison, chain);
  return true;
}

bool compareMouseUp(CompareMode& m) {
  const bool was = m.drag != CompareDrag::None;
  m.drag = CompareDrag::None;
  m.dragView = m.dragJoint = -1;
  return was;
}

void leaveCompareMode(CompareMode& m) {
  m.active = false;
  m.playing = false;
}

bool compareStepSubStep(CompareMode& m) {
  if (!m.ready()) return false;
  m.playing = false;
  stepSubStep(m.comparison);
  return true;
}

bool compareStepIteration(CompareMode& m) {
  if (!m.ready()) return false;
  m.playing = false;
  stepIteration(m.comparison);
  return true;
}

bool toggleComparePlay(CompareMode& m) {
  if (!m.ready()) return false;
  m.playing = !m.playing;
  m.clock = PlayClock{};
  return true;
}

bool compareRunToEnd(CompareMode& m) {
  if (!m.ready()) return false;
  m.playing = false;
  runToEnd(m.comparison);
  return true;
}

bool compareReset(CompareMode& m) {
  if (!m.ready()) return false;
  m.playing = false;
  resetCursors(m.comparison);
  return true;
}

bool handleCompareEvent(CompareMode& m, const InputEvent& e, bool mouseCaptured) {
  switch (e.type) {
    case InputEventType::ButtonDown: return !mouseCaptured && e.button == 0 && compareMouseDown(m, m.mouse);
    case InputEventType::MouseMove:
      m.mouse = {e.x, e.y};
      return compareMouseMove(m, m.mouse);
    case InputEventType::ButtonUp: return e.button == 0 && compareMouseUp(m);
    default: return false;
  }
}

namespace {
nlohmann::json vec3Json(const glm::vec3& v) { return nlohmann::json::array({v.x, v.y, v.z}); }
nlohmann::json rectJson(const CompareRect& r) { return {{"x", r.x}, {"y", r.y}, {"width", r.w}, {"height", r.h}}; }
}  // namespace

nlohmann::json compareModeJson(const CompareMode& m) {
  using json = nlohmann::json;
  json out;
  out["active"] = m.active;
  out["preset"] = m.preset;
  out["view"] = m.view3d ? "3d" : "2d";
  out["view_direction"] = vec3Json(m.viewDirection());
  out["playing"] = m.playing;
  out["steps_per_second"] = m.stepsPerSecond;
  out["error"] = m.error;
  out["figure"] = {{"min", {m.figureMin.x, m.figureMin.y}}, {"max", {m.figureMax.x, m.figureMax.y}}};
  json views = json::array();
  for (const CompareRect& r : m.layout.views) views.push_back(rectJson(r));
  out["views"] = views;
  out["plot"] = rectJson(m.layout.plot);
  json solvers = json::array();
  if (m.ready()) {
    const TeachingCase& c = m.comparison.setup;
    out["target"] = vec3Json(c.target);
    out["base"] = vec3Json(c.chain.base);
    out["bone_lengths"] = c.chain.boneLengths;
    out["start_angles"] = c.chain.startAngles;
    out["planar"] = c.chain.planar;
    out["tolerance"] = c.settings.tolerance;
    out["max_iterations"] = c.settings.maxIterations;
    for (const SolverRun& r : m.comparison.runs) {
      const IkTraceEntry& e = r.current();
      json s;
      s["solver"] = toString(r.solver);
      s["cursor"] = r.cursor;
      s["entries"] = static_cast<int>(r.trace.entries.size());
      s["iteration"] = e.iteration;
      s["step"] = toString(e.step);
      s["joint"] = e.joint;
      s["error"] = e.error;
      json ps = json::array();
      for (const glm::vec3& p : e.positions) ps.push_back(vec3Json(p));
      s["positions"] = ps;
      s["iterations"] = r.result.iterations;
      s["converged"] = r.result.converged;
      s["final_error"] = r.result.error;
      s["ms_total"] = r.totalMilliseconds;
      s["ms_per_iteration"] = r.millisecondsPerIteration;
      s["finished"] = r.finished();
      s["plot_points"] = static_cast<int>(r.convergenceSoFar().size());  // the plot reveals up to the cursor
      solvers.push_back(s);
    }
  }
  out["solvers"] = solvers;
  return out;
}

}  // namespace kinema
