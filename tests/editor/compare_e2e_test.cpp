// End-to-end tests of Teach > Compare Solvers: the real `kinema edit --compare PRESET` runs
// under xvfb-run on --script replay. Each solver's state in --dump-state is checked against
// `kinema ik CASE --json --trace` run on the same case (the case's chain saved as .kinema
// here, the CLI arguments from ikCommandArguments), after sub-steps, an iteration and a
// target drag; the plot is checked in the screenshot's pixels (each solver's colour).
#include <algorithm>
#include <cmath>

#include "editor/e2e_harness.h"
#include "io/image.h"
#include "io/kinema_file.h"
#include "ik/solver_comparison.h"

namespace kinema::test {
namespace KINEMA_UNITY_ID {

using namespace e2e;

// The editor on --compare `preset` (the harness's runEditor with the extra flag).
json runCompare(const std::string& dir, const std::string& shotDir, const Script& script, const std::string& name,
                const std::string& preset) {
  return runEditor(dir, shotDir, script, name, "", "--compare " + preset);
}

// `kinema ik` on the case (its chain written as .kinema) with `solver`: the JSON with "trace".
json cliTrace(const std::string& dir, TeachingCase setup, IkSolver solver) {
  const TeachingSkeleton chain = makeTeachingSkeleton(setup.chain);
  Scene scene;
  scene.skeleton = chain.skeleton;
  scene.ik = chain.rig;
  const std::string file = dir + "/case.kinema";
  EXPECT_EQ(saveKinemaFile(file, scene), "");
  std::string command = std::string(KINEMA_BINARY) + " ik '" + file + "'";
  for (const std::string& a : ikCommandArguments(setup, solver)) command += " '" + a + "'";
  command += " --json --trace";
  std::string out, err;
  EXPECT_EQ(runCommand(command, &out, &err), 0) << command << "\n" << err;
  json j = json::parse(out, nullptr, false);
  EXPECT_FALSE(j.is_discarded()) << out.substr(0, 200);
  return j.is_discarded() ? json() : j;
}

const json* solverIn(const json& dump, const char* solver) {
  for (const json& s : dump["compare"]["solvers"])
    if (s["solver"] == solver) return &s;
  ADD_FAILURE() << "no solver " << solver << " in the dump";
  return nullptr;
}

// The dumped solver state equals trace entry `index` of the CLI's run.
void expectTraceEntry(const json& solver, const json& cli, int index, const std::string& what) {
  const json& trace = cli["trace"];
  ASSERT_LT(index, static_cast<int>(trace.size())) << what;
  const json& e = trace[index];
  EXPECT_EQ(solver["cursor"], index) << what;
  EXPECT_EQ(solver["entries"], trace.size()) << what << ": the same number of sub-steps";
  EXPECT_EQ(solver["iteration"], e["iteration"]) << what;
  EXPECT_EQ(solver["step"], e["step"]) << what;
  EXPECT_NEAR(double(solver["error"]), double(e["error"]), 1e-5) << what;
  ASSERT_EQ(solver["positions"].size(), e["positions"].size()) << what;
  for (size_t k = 0; k < e["positions"].size(); ++k)
    expectNear(vec3(solver["positions"][k]), vec3(e["positions"][k]), 1e-5, what + ": joint " + std::to_string(k));
}

TeachingCase presetWithTarget(const char* name, const json& target) {
  const TeachingCase* p = findTeachingPreset(name);
  EXPECT_NE(p, nullptr) << name;
  TeachingCase c = p ? *p : TeachingCase{};
  if (target.is_array()) c.target = glm::vec3(vec3(target));
  return c;
}

// Window pixel of a figure point in view `v`, from the dumped view rect and figure bounds:
// the bounds fitted into the rect less 12 px margins, aspect kept, centred, Y up.
glm::dvec2 figurePixel(const json& compare, int v, glm::dvec2 p) {
  const json& r = compare["views"][v];
  const glm::dvec2 lo(compare["figure"]["min"][0], compare["figure"]["min"][1]);
  const glm::dvec2 hi(compare["figure"]["max"][0], compare["figure"]["max"][1]);
  const double w = double(r["width"]) - 24, h = double(r["height"]) - 24;
  const double ppu = std::min(w / (hi.x - lo.x), h / (hi.y - lo.y));
  const glm::dvec2 c = (lo + hi) / 2.0;
  return {double(r["x"]) + double(r["width"]) / 2 + (p.x - c.x) * ppu,
          double(r["y"]) + double(r["height"]) / 2 - (p.y - c.y) * ppu};
}

class CompareE2e : public ::testing::Test {
 protected:
  void SetUp() override {
    if (runCommand("command -v xvfb-run") != 0) GTEST_SKIP() << "SKIPPED: xvfb-run is not installed";
    dir_ = makeTempDir();
  }
  void TearDown() override {
    if (!dir_.empty()) runCommand("rm -rf '" + dir_ + "'");
  }
  static std::string shotDir() {
    const std::string dir = std::string(KINEMA_BUILD_DIR) + "/compare_e2e";
    runCommand("mkdir -p '" + dir + "'");
    return dir;
  }
  json run(const Script& s, const std::string& name, const std::string& preset) {
    return runCompare(dir_, shotDir(), s, name, preset);
  }
  // The mode on ccd-steps, idle, run once when a test first asks: where its views and the
  // 3D view (behind the mode) are at this window size.
  static const json& probe() {
    static const json d = [] {
      const std::string dir = makeTempDir();
      Script idle;
      idle.wait(2);
      const json out = runCompare(dir, shotDir(), idle, "probe", "ccd-steps");
      runCommand("rm -rf '" + dir + "'");
      return out;
    }();
    return d;
  }
  std::string dir_;
};

TEST_F(CompareE2e, SubStepsFollowTheTraceOfEverySolver) {
  // Right twice: two sub-steps (CCD: two joint rotations; FABRIK: a backward and a forward pass).
  Script s;
  s.wait(4).key("RIGHT").wait(2).key("RIGHT").wait(2);
  const json d = run(s, "ccd_two_substeps", "ccd-steps");
  ASSERT_TRUE(d.is_object());
  EXPECT_EQ(d["compare"]["active"], true);
  EXPECT_EQ(d["compare"]["preset"], "ccd-steps");
  const TeachingCase setup = presetWithTarget("ccd-steps", d["compare"]["target"]);
  ASSERT_EQ(d["compare"]["solvers"].size(), setup.solvers.size());
  for (IkSolver solver : setup.solvers) {
    const json* state = solverIn(d, toString(solver));
    ASSERT_NE(state, nullptr);
    expectTraceEntry(*state, cliTrace(dir_, setup, solver), 2, std::string("ccd-steps, ") + toString(solver));
  }
}

TEST_F(CompareE2e, AnIterationFinishesTheCurrentIterationInTheTrace) {
  // One sub-step, then Shift+Right: the rest of that iteration (FABRIK: the forward pass).
  Script s;
  s.wait(4).key("RIGHT").wait(2).keyDown("LEFT_SHIFT").key("RIGHT").keyUp("LEFT_SHIFT").wait(2);
  const json d = run(s, "fabrik_iteration", "fabrik-steps");
  ASSERT_TRUE(d.is_object());
  const TeachingCase setup = presetWithTarget("fabrik-steps", d["compare"]["target"]);
  for (IkSolver solver : setup.solvers) {
    const json cli = cliTrace(dir_, setup, solver);
    const json& trace = cli["trace"];
    ASSERT_GE(trace.size(), 2u);
    // From entry 1 (iteration i): the last entry of iteration i when entry 2 is still in
    // it (the iteration is finished), else the last entry of iteration i + 1.
    const int i = int(trace[1]["iteration"]);
    const int next = trace.size() > 2u && int(trace[2]["iteration"]) == i ? i : i + 1;
    int expected = 1;
    while (expected + 1 < int(trace.size()) && int(trace[expected + 1]["iteration"]) <= next) ++expected;
    const json* state = solverIn(d, toString(solver));
    ASSERT_NE(state, nullptr);
    expectTraceEntry(*state, cli, expected, std::string("fabrik-steps, ") + toString(solver));
  }
}

TEST_F(CompareE2e, DraggingTheTargetRestartsEverySolverOnTheNewTarget) {
  // Where the target is drawn, from a run that only steps.
  Script steps;
  steps.wait(4).key("RIGHT").key("RIGHT").key("RIGHT").wait(2);
  const json before = run(steps, "drag_before", "ccd-steps");
  ASSERT_TRUE(before.is_object());
  const json& c = before["compare"];
  for (const json& s : c["solvers"]) EXPECT_EQ(s["cursor"], 3);
  const glm::dvec3 target = vec3(c["target"]);
  const glm::dvec2 from = figurePixel(c, 1, {target.x, target.y}), to = from + glm::dvec2(-40, 30);

  // The same steps, then a left drag of the target in the second view.
  Script s = steps;
  s.move(from).wait(1).down().path(from, to).wait(1).up().wait(2);
  const json d = run(s, "drag_target", "ccd-steps");
  ASSERT_TRUE(d.is_object());
  const glm::dvec3 moved = vec3(d["compare"]["target"]);
  // Where the mouse let go, in figure units of the bounds the drag started with.
  const json& r = c["views"][1];
  const glm::dvec2 lo(c["figure"]["min"][0], c["figure"]["min"][1]), hi(c["figure"]["max"][0], c["figure"]["max"][1]);
  const double ppu = std::min((double(r["width"]) - 24) / (hi.x - lo.x), (double(r["height"]) - 24) / (hi.y - lo.y));
  expectNear(moved, target + glm::dvec3(-40 / ppu, -30 / ppu, 0), 2e-3, "the target follows the mouse");
  const TeachingCase setup = presetWithTarget("ccd-steps", d["compare"]["target"]);
  for (IkSolver solver : setup.solvers) {
    const json* state = solverIn(d, toString(solver));
    ASSERT_NE(state, nullptr);
    const json cli = cliTrace(dir_, setup, solver);
    const std::string what = std::string("after the drag, ") + toString(solver);
    expectTraceEntry(*state, cli, 0, what);  // back at the start, solved again for the new target
    EXPECT_EQ((*state)["iterations"], cli["iterations"]) << what;
    EXPECT_NEAR(double((*state)["final_error"]), double(cli["error"]), 1e-5) << what;
  }
}

TEST_F(CompareE2e, ThePlotShowsOneSeriesPerSolver) {
  // Run to convergence (End) so every series is complete, then count each solver's colour
  // inside the plot rectangle of the screenshot.
  Script s;
  s.wait(4).key("END").wait(3);
  const json d = run(s, "plot_series", "near-root");
  ASSERT_TRUE(d.is_object());
  const auto shot = loadPng(shotDir() + "/plot_series.png");
  ASSERT_TRUE(shot.ok()) << shot.error();
  const Image& img = shot.value();
  const json& p = d["compare"]["plot"];
  const int x0 = int(p["x"]), y0 = int(p["y"]), x1 = x0 + int(p["width"]), y1 = y0 + int(p["height"]);
  ASSERT_GE(d["compare"]["solvers"].size(), 2u);
  for (const json& solver : d["compare"]["solvers"]) {
    const json& col = solver["color"];
    int inside = 0, outsideViews = 0;
    for (int y = 0; y < img.height; ++y)
      for (int x = 0; x < img.width; ++x) {
        const std::uint8_t* px = &img.rgba[(size_t(y) * img.width + x) * 4];
        const bool match = std::abs(px[0] - int(col[0])) <= 24 && std::abs(px[1] - int(col[1])) <= 24 &&
                           std::abs(px[2] - int(col[2])) <= 24;
        if (!match) continue;
        if (x >= x0 && x < x1 && y >= y0 && y < y1) ++inside;
        else if (y >= y1) ++outsideViews;
      }
    EXPECT_GE(inside, 30) << solver["solver"] << ": its series in the plot";
    EXPECT_EQ(outsideViews, 0) << solver["solver"] << ": nothing below the plot has its colour";
  }
}

// Pixels of `color` (each channel within `tol`) inside rect r of the screenshot.
int colorCount(const Image& img, const Rect& r, const json& color, int tol) {
  int n = 0;
  for (int y = std::max(0, int(r.y)); y < std::min(img.height, int(r.bottom())); ++y)
    for (int x = std::max(0, int(r.x)); x < std::min(img.width, int(r.right())); ++x) {
      const std::uint8_t* px = img.pixel(x, y);
      n += std::abs(px[0] - int(color[0])) <= tol && std::abs(px[1] - int(color[1])) <= tol &&
           std::abs(px[2] - int(color[2])) <= tol;
    }
  return n;
}

// Window pixel x of plot figure x (drawConvergencePlot's 1.6 x 1 box fitted into the dumped
// plot rect less 6 px margins, centred) and of iteration `it` of `iterations` (its axis runs
// from 0.16 to 1.2).
double plotPixelX(const Rect& p, double fx) {
  const double ppu = std::min((p.width - 12) / 1.6, (p.height - 12) / 1.0);
  return p.x + p.width / 2 + (fx - 0.8) * ppu;
}
double iterationX(const Rect& p, double it, double iterations) { return plotPixelX(p, 0.16 + 1.04 * it / iterations); }

// The plot reveals the curves step by step: after one sub-step each solver's curve ends at
// iteration 1 (plot_points: the cursor's iteration + 1), with nothing of its colour to the
// right of it in the plot, where the finished run's curve is. The 3D view, orbited, shows the
// ground grid and Blender's red X, green Y and blue Z axes; the 2D board shows none of them.
TEST_F(CompareE2e, ThePlotRevealsStepByStepAndThe3dViewHasGridAndAxes) {
  ASSERT_TRUE(probe().is_object());
  const glm::dvec2 a = rectOf(probe()["compare"]["views"][0]).at(0.1, 0.9), b = a + glm::dvec2(60, -40);
  Script orbit;
  orbit.wait(2).clickItem("Compare/3D").wait(2).move(a).wait(1).down().path(a, b).wait(1).up().wait(2);
  Script one = orbit, all = orbit;
  one.key("RIGHT").wait(3);
  all.key("END").wait(3);
  const json first = run(one, "reveal_step_one_3d", "ccd-steps");
  const json last = run(all, "reveal_end_3d", "ccd-steps");
  ASSERT_TRUE(first.is_object() && last.is_object());
  const auto shotFirst = loadPng(shotDir() + "/reveal_step_one_3d.png"), shotLast = loadPng(shotDir() + "/reveal_end_3d.png");
  const auto shotBoard = loadPng(shotDir() + "/probe.png");
  ASSERT_TRUE(shotFirst.ok() && shotLast.ok() && shotBoard.ok());
  ASSERT_EQ(first["compare"]["view"], "3d");
  const Rect plot = rectOf(first["compare"]["plot"]);
  int iterations = 1;
  for (const json& s : last["compare"]["solvers"]) iterations = std::max(iterations, int(s["iterations"]));
  ASSERT_GE(iterations, 3) << "a case with curves long enough to tell apart";
  // Right of iteration 1 (and its ring) up to the last iteration: the plot's data area only.
  const Rect later{iterationX(plot, 1, iterations) + 10, plot.y, iterationX(plot, iterations, iterations) + 4 -
                                                                      (iterationX(plot, 1, iterations) + 10),
                   plot.height};
  for (size_t i = 0; i < first["compare"]["solvers"].size(); ++i) {
    const json& s1 = first["compare"]["solvers"][i];
    const json& sn = last["compare"]["solvers"][i];
    EXPECT_EQ(s1["cursor"], 1);
    EXPECT_EQ(s1["iteration"], 1);
    EXPECT_EQ(s1["plot_points"], 2) << s1["solver"];
    EXPECT_EQ(sn["plot_points"], int(sn["iterations"]) + 1) << sn["solver"] << ": the whole curve at the end";
    EXPECT_EQ(colorCount(shotFirst.value(), later, s1["color"], 24), 0) << s1["solver"] << ": nothing past iteration 1";
    EXPECT_GT(colorCount(shotLast.value(), later, sn["color"], 24), 20) << sn["solver"] << ": the rest of the curve at the end";
  }
  // The axes in their colours in every 3D view; none on the 2D board.
  const json axes[3] = {json::array({255, 51, 82}), json::array({139, 220, 0}), json::array({40, 144, 255})};
  for (size_t v = 0; v < first["compare"]["views"].size(); ++v)
    for (int k = 0; k < 3; ++k) {
      EXPECT_GE(colorCount(shotFirst.value(), rectOf(first["compare"]["views"][v]), axes[k], 24), 8)
          << "view " << v << " axis " << k;
      EXPECT_EQ(colorCount(shotBoard.value(), rectOf(probe()["compare"]["views"][v]), axes[k], 24), 0)
          << "view " << v << " axis " << k << " on the 2D board";
    }
}

TEST_F(CompareE2e, DraggingAJointSetsTheStartPoseOfEverySolver) {
  Script idle;
  idle.wait(2);
  const json before = run(idle, "joint_before", "ccd-steps");
  ASSERT_TRUE(before.is_object());
  const json& c = before["compare"];
  const glm::dvec3 base = vec3(c["base"]), joint1 = vec3(c["solvers"][0]["positions"][1]);
  // Joint 1 dragged to one unit straight above the base: bone 1 turns to +Y (pi/2 from +X).
  const glm::dvec2 from = figurePixel(c, 0, {joint1.x, joint1.y}), to = figurePixel(c, 0, {base.x, base.y + 1.0});
  Script s;
  s.wait(2).move(from).wait(1).down().path(from, to).wait(1).up().wait(2);
  const json d = run(s, "joint_drag", "ccd-steps");
  ASSERT_TRUE(d.is_object());
  const json& angles = d["compare"]["start_angles"];
  ASSERT_EQ(angles.size(), c["start_angles"].size());
  EXPECT_NEAR(double(angles[0]), M_PI / 2, 1e-3);
  for (size_t i = 1; i < angles.size(); ++i) EXPECT_EQ(angles[i], c["start_angles"][i]) << "bone " << i;
  TeachingCase setup = presetWithTarget("ccd-steps", d["compare"]["target"]);
  for (size_t i = 0; i < angles.size(); ++i) setup.chain.startAngles[i] = angles[i].get<float>();
  for (IkSolver solver : setup.solvers) {
    const json* state = solverIn(d, toString(solver));
    ASSERT_NE(state, nullptr);
    const json cli = cliTrace(dir_, setup, solver);
    expectTraceEntry(*state, cli, 0, std::string("after the joint drag, ") + toString(solver));
    EXPECT_EQ((*state)["iterations"], cli["iterations"]);
    expectNear(vec3((*state)["positions"][1]), base + glm::dvec3(0, setup.chain.boneLengths[0], 0), 2e-3,
               "joint 1 straight above the base");
  }
}

// Teach > Compare Solvers, then the toolbar's preset combo and its row "A target near the
// root" (near-root), by name.
TEST_F(CompareE2e, TheTeachMenuOpensTheModeAndTheComboChoosesAPreset) {
  Script s;
  s.menu("Teach", "Compare Solvers").clickItem("Compare/Preset").wait(2).clickItem("Compare/Preset/near-root").wait(2);
  s.key("RIGHT").wait(2);
  const json d = runEditor(dir_, shotDir(), s, "menu_near_root");
  ASSERT_TRUE(d.is_object());
  EXPECT_EQ(d["compare"]["active"], true);
  EXPECT_EQ(d["compare"]["preset"], "near-root");
  const TeachingCase setup = presetWithTarget("near-root", d["compare"]["target"]);
  expectNear(vec3(d["compare"]["target"]), glm::dvec3(glm::vec3(findTeachingPreset("near-root")->target)), 1e-6,
             "the preset's own target");
  for (IkSolver solver : setup.solvers) {
    const json* state = solverIn(d, toString(solver));
    ASSERT_NE(state, nullptr);
    expectTraceEntry(*state, cliTrace(dir_, setup, solver), 1, std::string("near-root, ") + toString(solver));
  }
}

TEST_F(CompareE2e, The3dSwitchSolvesBallJointsAndADragOrbitsTheViews) {
  // 3D, then a left drag on empty space in the first view (its lower left, away from the
  // figure): 60 px right, 20 px up.
  ASSERT_TRUE(probe().is_object());
  const glm::dvec2 a = rectOf(probe()["compare"]["views"][0]).at(0.1, 0.9), b = a + glm::dvec2(60, -20);
  Script s;
  s.wait(2).clickItem("Compare/3D").wait(2).move(a).wait(1).down().path(a, b).wait(1).up().wait(2);
  const json d = run(s, "orbit_3d", "ccd-steps");
  ASSERT_TRUE(d.is_object());
  EXPECT_EQ(d["compare"]["view"], "3d");
  EXPECT_EQ(d["compare"]["planar"], false);
  // Orbit: yaw -0.01 rad per px right, pitch +0.01 per px down -> yaw -0.6, pitch -0.2.
  const double yaw = -0.6, pitch = -0.2;
  expectNear(vec3(d["compare"]["view_direction"]),
             {std::cos(pitch) * std::sin(yaw), std::sin(pitch), std::cos(pitch) * std::cos(yaw)}, 1e-4,
             "the view direction after the orbit");
  TeachingCase setup = presetWithTarget("ccd-steps", d["compare"]["target"]);
  setup.chain.planar = false;
  for (IkSolver solver : setup.solvers) {
    const json* state = solverIn(d, toString(solver));
    ASSERT_NE(state, nullptr);
    const json cli = cliTrace(dir_, setup, solver);
    expectTraceEntry(*state, cli, 0, std::string("3D, ") + toString(solver));
    EXPECT_EQ((*state)["iterations"], cli["iterations"]);
  }
}

TEST_F(CompareE2e, CtrlZInTheModeLeavesTheHiddenDocumentAlone) {
  // Leave the mode, key every joint (one undo step), come back: Ctrl+Z there must not undo
  // the keys nobody can see; after Esc it does. The mouse waits in the 3D view (behind the
  // mode's views while they show).
  ASSERT_TRUE(probe().is_object());
  const glm::dvec2 inView = viewportRect(probe()).at(0.5, 0.45);
  Script s;
  s.wait(4).key("ESCAPE").wait(2).move(inView).wait(1).key("A").wait(2).key("I").wait(3);
  s.menu("Teach", "Compare Solvers").wait(2).move(inView).wait(1);
  s.keyDown("LEFT_CONTROL").key("Z").keyUp("LEFT_CONTROL").wait(3);
  const json inside = run(s, "ctrl_z_inside", "ccd-steps");
  ASSERT_TRUE(inside.is_object());
  EXPECT_EQ(inside["compare"]["active"], true);
  EXPECT_EQ(inside["undo_depth"], 1) << "the keys were inserted once and not undone";
  s.key("ESCAPE").wait(2).move(inView).wait(1).keyDown("LEFT_CONTROL").key("Z").keyUp("LEFT_CONTROL").wait(3);
  const json outside = run(s, "ctrl_z_outside", "ccd-steps");
  ASSERT_TRUE(outside.is_object());
  EXPECT_EQ(outside["compare"]["active"], false);
  EXPECT_EQ(outside["undo_depth"], 0);
}

TEST_F(CompareE2e, AnUnknownPresetIsABadUsage) {
  std::string out, err;
  const int rc = runCommand(editorEnvironment(dir_) + KINEMA_BINARY + " edit --compare no-such-case --frame-count 1", &out, &err);
  EXPECT_EQ(rc, 2) << err;
  EXPECT_NE(err.find("no-such-case"), std::string::npos) << err;
}

}  // namespace
}  // namespace kinema::test
