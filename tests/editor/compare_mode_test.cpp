// The "Compare solvers" mode's window-free logic: view layout, figure <-> pixel mapping,
// projection (ik/figure_projection.h), hit-tests, play clock, start-pose drags, keys and target drags on a preset.
#include <gtest/gtest.h>

#include <cmath>

#include "editor/model/compare_mode.h"

namespace kinema {
namespace KINEMA_UNITY_ID {

constexpr float kPi = 3.14159265358979f;

void expectVec2(glm::vec2 a, glm::vec2 e, float tol, const char* what) {
  EXPECT_NEAR(a.x, e.x, tol) << what;
  EXPECT_NEAR(a.y, e.y, tol) << what;
}
void expectVec3(glm::vec3 a, glm::vec3 e, float tol, const char* what) {
  EXPECT_NEAR(a.x, e.x, tol) << what;
  EXPECT_NEAR(a.y, e.y, tol) << what;
  EXPECT_NEAR(a.z, e.z, tol) << what;
}

TEST(CompareMode, FigureMapKeepsAspectAndCentres) {
  // [0,2] x [0,1] into 220 x 120 less 10 px margins: 200 x 100 -> 100 px per unit both ways.
  const FigureViewMap m = FigureViewMap::fit({0, 0}, {2, 1}, {0, 0, 220, 120}, 10);
  EXPECT_FLOAT_EQ(m.pixelsPerUnit, 100.0f);
  expectVec2(m.toPixel({0, 0}), {10, 110}, 1e-4f, "bottom left (Y up -> pixels down)");
  expectVec2(m.toPixel({2, 1}), {210, 10}, 1e-4f, "top right");
  // A square figure in a wide rect: the height decides, the width is centred.
  const FigureViewMap s = FigureViewMap::fit({0, 0}, {1, 1}, {100, 50, 420, 220}, 10);
  EXPECT_FLOAT_EQ(s.pixelsPerUnit, 200.0f);
  expectVec2(s.toPixel({0, 0}), {100 + 210 - 100, 50 + 110 + 100}, 1e-4f, "square, bottom left");
  expectVec2(s.toFigure(s.toPixel({0.3f, 0.7f})), {0.3f, 0.7f}, 1e-5f, "round trip");
}

TEST(CompareMode, ProjectionIsTheBoardForThePlanarViewAndOrthonormalOtherwise) {
  const FigureProjection p = FigureProjection::along({0, 0, 1});
  expectVec2(p.project({1, 2, 3}), {1, 2}, 1e-6f, "planar: x, y");
  expectVec3(orbitViewDirection(0, 0), {0, 0, 1}, 1e-6f, "no orbit looks along +Z");
  expectVec3(orbitViewDirection(kPi / 2, 0), {1, 0, 0}, 1e-6f, "yaw 90");
  for (glm::vec3 d : {glm::vec3(1, 0, 0), glm::vec3(0.3f, 0.5f, -0.8f), glm::vec3(0, 1, 0)}) {
    const FigureProjection q = FigureProjection::along(d);
    const glm::vec3 n = glm::normalize(d);
    EXPECT_NEAR(glm::length(q.right), 1.0f, 1e-5f);
    EXPECT_NEAR(glm::length(q.up), 1.0f, 1e-5f);
    EXPECT_NEAR(glm::dot(q.right, q.up), 0.0f, 1e-5f);
    expectVec2(q.project(n * 5.0f), {0, 0}, 1e-4f, "the view direction collapses to a point");
    expectVec3(glm::cross(q.right, q.up), n, 1e-5f, "right x up = towards the viewer, as X x Y = Z");
  }
}

TEST(CompareMode, HitTestPrefersTheTargetAndNeverTheRoot) {
  const std::vector<glm::vec2> joints{{0, 0}, {100, 0}, {200, 0}};
  EXPECT_EQ(hitCompareHandle(joints, {104, 0}, {102, 0}), kHitTarget);  // both near: the target wins
  EXPECT_EQ(hitCompareHandle(joints, {500, 500}, {103, 4}), 1);
  EXPECT_EQ(hitCompareHandle(joints, {500, 500}, {195, 0}), 2);
  EXPECT_EQ(hitCompareHandle(joints, {500, 500}, {1, 1}), kHitNothing);  // the base stays put
  EXPECT_EQ(hitCompareHandle(joints, {500, 500}, {150, 0}), kHitNothing);
}

TEST(CompareMode, PlayClockTakesStepsPerSecondAcrossFrames) {
  PlayClock c;
  int steps = 0;
  for (int i = 0; i < 60; ++i) steps += c.advance(1.0 / 60.0, 4.0);
  EXPECT_EQ(steps, 4);  // one second at 4 steps/s (the fractions carry over)
  PlayClock d;
  EXPECT_EQ(d.advance(0.1, 25.0), 2);  // 2.5: two now, half carried
  EXPECT_EQ(d.advance(0.1, 25.0), 3);  // 0.5 + 2.5
  EXPECT_EQ(d.advance(0.0, 25.0), 0);
  EXPECT_EQ(d.advance(0.1, 0.0), 0);
}

TEST(CompareMode, StartPoseDragTurnsOneBoneAndCarriesTheRest) {
  TeachingChain c;
  c.boneLengths = {1, 1};
  c.startAngles = {kPi / 2, -kPi / 2};
  std::vector<glm::vec3> p = teachingChainPositions(c);
  ASSERT_EQ(p.size(), 3u);
  expectVec3(p[1], {0, 1, 0}, 1e-5f, "up");
  expectVec3(p[2], {1, 1, 0}, 1e-5f, "then right");

  TeachingChain d;
  d.boneLengths = {1, 1, 1};
  d.startAngles = {0, 0, 0};
  aimTeachingBone(d, 2, {1, 3, 0});  // bone 2 (from (1,0)) turns straight up
  p = teachingChainPositions(d);
  expectVec3(p[1], {1, 0, 0}, 1e-5f, "bone 1 unchanged");
  expectVec3(p[2], {1, 1, 0}, 1e-5f, "bone 2 up, its length kept");
  expectVec3(p[3], {1, 2, 0}, 1e-5f, "bone 3 keeps its relative angle (straight on)");
  EXPECT_NEAR(d.startAngles[1], kPi / 2, 1e-5f);
  aimTeachingBone(d, 1, {-2, 0, 0});  // bone 1 turns to -X: relative angle pi (or -pi)
  EXPECT_NEAR(std::abs(d.startAngles[0]), kPi, 1e-5f);
  EXPECT_NEAR(d.startAngles[1], kPi / 2, 1e-5f);  // children keep their relative angles
}

TEST(CompareMode, LayoutPutsTheViewsSideBySideAboveThePlot) {
  const CompareRect area{0, 19, 1280, 677};
  for (int n : {2, 3}) {
    const CompareLayout l = compareLayout(area, n);
    ASSERT_EQ(static_cast<int>(l.views.size()), n);
    EXPECT_FLOAT_EQ(l.side.w, kCompareSideWidth);
    for (int i = 0; i < n; ++i) {
      EXPECT_GE(l.views[i].x, area.x + kCompareSideWidth);
      EXPECT_LE(l.views[i].x + l.views[i].w, area.x + area.w + 0.5f);
      EXPECT_FLOAT_EQ(l.views[i].y, area.y + kCompareToolbarHeight);
      if (i > 0) {
        EXPECT_FLOAT_EQ(l.views[i].x, l.views[i - 1].x + l.views[i - 1].w);  // side by side
      }
      EXPECT_FLOAT_EQ(l.views[i].w, l.views[0].w);  // comparable: the same size
    }
    EXPECT_FLOAT_EQ(l.plot.y, l.views[0].y + l.views[0].h);
    EXPECT_LE(l.plot.y + l.plot.h, area.y + area.h + 0.5f);
    EXPECT_FLOAT_EQ(l.numbers.x, l.plot.x + l.plot.w);
  }
}

// A preset opened in a 1000 x 600 area with figure bounds [-4, 4]^2.
CompareMode openedPreset(const char* name) {
  CompareMode m;
  m.active = true;
  EXPECT_EQ(openComparePreset(m, name), "");
  m.layout = compareLayout({0, 0, 1000, 600}, static_cast<int>(m.comparison.runs.size()));
  m.figureMin = glm::vec2(-4.0f);
  m.figureMax = glm::vec2(4.0f);
  return m;
}

TEST(CompareMode, StepResetPlayAndRunEverySolver) {
  CompareMode m = openedPreset("ccd-steps");
  ASSERT_TRUE(m.ready());
  ASSERT_GE(m.comparison.runs.size(), 2u);
  EXPECT_TRUE(compareStepSubStep(m));
  for (const SolverRun& r : m.comparison.runs) EXPECT_EQ(r.cursor, 1) << toString(r.solver);
  // Shift+Right from inside iteration 1: to the last entry of iteration 1; again: of
  // iteration 2 (solver_comparison.h).
  for (const SolverRun& r : m.comparison.runs) ASSERT_EQ(r.current().iteration, 1) << toString(r.solver);
  for (int expected = 1; expected <= 2; ++expected) {
    EXPECT_TRUE(compareStepIteration(m));
    for (const SolverRun& r : m.comparison.runs) {
      EXPECT_EQ(r.current().iteration, expected) << toString(r.solver);
      if (!r.finished()) {
        EXPECT_EQ(r.trace.entries[r.cursor + 1].iteration, expected + 1) << toString(r.solver);
      }
    }
  }
  EXPECT_TRUE(compareReset(m));
  for (const SolverRun& r : m.comparison.runs) EXPECT_EQ(r.cursor, 0);
  EXPECT_TRUE(compareRunToEnd(m));
  for (const SolverRun& r : m.comparison.runs) EXPECT_TRUE(r.finished());
  // Space plays: at 4 steps/s one second of frames takes 4 sub-steps in each run.
  compareReset(m);
  EXPECT_TRUE(toggleComparePlay(m));
  EXPECT_TRUE(m.playing);
  m.stepsPerSecond = 4.0f;
  for (int i = 0; i < 60; ++i) advanceComparePlay(m, 1.0 / 60.0);
  for (const SolverRun& r : m.comparison.runs)
    EXPECT_EQ(r.cursor, std::min(4, static_cast<int>(r.trace.entries.size()) - 1)) << toString(r.solver);
  leaveCompareMode(m);
  EXPECT_FALSE(m.active);
}

TEST(CompareMode, DraggingTheTargetRestartsEverySolverOnTheNewTarget) {
  CompareMode m = openedPreset("ccd-steps");
  ASSERT_TRUE(m.ready());
  compareStepSubStep(m);
  const glm::vec3 before = m.comparison.setup.target;
  const glm::vec2 px = compareTargetPixel(m, 1);  // the second view: any view works
  // Independently: view 1 is 375 x 336 at (625, 58); 8 units into 351 x 312 -> 39 px/unit.
  EXPECT_NEAR(px.x, 625 + 187.5f + before.x * 39.0f, 1e-3f);
  EXPECT_NEAR(px.y, 58 + 168 - before.y * 39.0f, 1e-3f);
  ASSERT_TRUE(compareMouseDown(m, px));
  EXPECT_EQ(m.drag, CompareDrag::Target);
  ASSERT_TRUE(compareMouseMove(m, px + glm::vec2(39.0f * 0.25f, -39.0f * 0.5f)));
  EXPECT_TRUE(compareMouseUp(m));
  expectVec3(m.comparison.setup.target, before + glm::vec3(0.25f, 0.5f, 0.0f), 1e-4f, "moved in figure units");
  for (const SolverRun& r : m.comparison.runs) {
    EXPECT_EQ(r.cursor, 0) << toString(r.solver);
    // Solved again for the new target: the last entry's error is the effector's distance to it.
    const glm::vec3 effector = r.trace.entries.back().positions.back();
    EXPECT_NEAR(glm::distance(effector, m.comparison.setup.target), r.trace.entries.back().error, 1e-4f)
        << toString(r.solver);
  }
}

TEST(CompareMode, DraggingAJointSetsTheStartPose) {
  CompareMode m = openedPreset("ccd-steps");
  ASSERT_TRUE(m.ready());
  const TeachingChain before = m.comparison.setup.chain;
  const std::vector<glm::vec2> joints = compareJointPixels(m, 0);
  ASSERT_GE(joints.size(), 3u);
  ASSERT_TRUE(compareMouseDown(m, joints[1]));
  ASSERT_EQ(m.drag, CompareDrag::Joint);
  // Joint 1 dragged to straight above the base: bone 1 points along +Y.
  const glm::vec3 base = before.base;
  const glm::vec2 above = m.viewMap(0).toPixel({base.x, base.y + 1.0f});
  ASSERT_TRUE(compareMouseMove(m, above));
  compareMouseUp(m);
  EXPECT_NEAR(m.comparison.setup.chain.startAngles[0], kPi / 2, 1e-3f);
  for (size_t i = 1; i < before.startAngles.size(); ++i)
    EXPECT_FLOAT_EQ(m.comparison.setup.chain.startAngles[i], before.startAngles[i]);
  // The runs start from that pose.
  const std::vector<glm::vec3> expected = teachingChainPositions(m.comparison.setup.chain);
  for (const SolverRun& r : m.comparison.runs) {
    ASSERT_EQ(r.trace.entries[0].positions.size(), expected.size());
    for (size_t j = 0; j < expected.size(); ++j) expectVec3(r.trace.entries[0].positions[j], expected[j], 1e-4f, "start");
  }
}

TEST(CompareMode, UnknownPresetIsAnErrorAndChangesNothing) {
  CompareMode m;
  EXPECT_NE(openComparePreset(m, "no-such-case").find("no-such-case"), std::string::npos);
  EXPECT_FALSE(m.ready());
}

}  // namespace
}  // namespace kinema
