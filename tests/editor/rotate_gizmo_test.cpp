// The rotate gizmo and R-mode on the hand camera (viewport_test_views.h): eye on +Z looking
// down -Z, so screen right = +X, screen up = +Y and the Z axis points at the viewer. With the
// orthographic view a ring of 80 px has world radius 8 (0.1 units per pixel).
#include "core/default_character.h"
#include "core/forward_kinematics.h"
#include "editor/viewport/rotate_gizmo.h"
#include "render/camera.h"
#include "render/skeleton_view.h"
#include "editor/viewport_test_views.h"
#include "test_support.h"

namespace kinema::test {
namespace KINEMA_UNITY_ID {

constexpr float kPi = 3.14159265358979f;

glm::vec2 onCircle(float radiusPixels, float degreesCcw) {  // around the screen centre (100, 100)
  const float a = glm::radians(degreesCcw);
  return {100 + radiusPixels * std::cos(a), 100 - radiusPixels * std::sin(a)};
}

TEST(RotateGizmo, RingsAreWorldCirclesOfThePixelRadius) {
  const ViewportView v = handView(true);
  RotateGizmo g;
  EXPECT_NEAR(g.ringRadiusWorld(v), 8.0f, 1e-4f);
  for (int i = 0; i < 4; ++i)
    for (const glm::vec3& p : g.ringPoints(v, i, 16)) {
      EXPECT_NEAR(glm::length(p), i < 3 ? 8.0f : 9.6f, 1e-4f);
      if (i < 3) {
        EXPECT_NEAR(p[i], 0.0f, 1e-5f);  // ring i lies in the plane normal to axis i
      }
    }
  // The view ring is an exact 96 px circle on screen, also in perspective.
  const ViewportView persp = handView(false);
  g.pivot = {2, 1, -3};
  for (const glm::vec3& p : g.ringPoints(persp, 3, 12)) {
    glm::vec2 a, c;
    ASSERT_TRUE(persp.project(p, a));
    ASSERT_TRUE(persp.project(g.pivot, c));
    EXPECT_NEAR(glm::length(a - c), 96.0f, 1e-2f);
  }
}

TEST(RotateGizmo, HitTestFindsRingsViewRingTrackballAndNothing) {
  const ViewportView v = handView(true);
  RotateGizmo g;
  // Seen from +Z the Z ring is the 80 px circle; the X and Y rings are edge-on (their front
  // halves are the vertical and horizontal diameters).
  EXPECT_EQ(hitTestRotateGizmo(g, v, onCircle(80, 45)), GizmoPart::AxisZ);
  EXPECT_EQ(hitTestRotateGizmo(g, v, onCircle(84, 45)), GizmoPart::AxisZ);  // within 6 px
  EXPECT_EQ(hitTestRotateGizmo(g, v, {140, 100}), GizmoPart::AxisY);
  EXPECT_EQ(hitTestRotateGizmo(g, v, {100, 60}), GizmoPart::AxisX);
  EXPECT_EQ(hitTestRotateGizmo(g, v, onCircle(96, 45)), GizmoPart::ViewRing);
  EXPECT_EQ(hitTestRotateGizmo(g, v, {130, 130}), GizmoPart::Trackball);  // 30 px from both diameters
  EXPECT_EQ(hitTestRotateGizmo(g, v, onCircle(88, 45)), GizmoPart::None);  // between the rings
  EXPECT_EQ(hitTestRotateGizmo(g, v, {10, 190}), GizmoPart::None);
  // Local axes turned 90 degrees about Y: local X points along world -Z, so ITS ring faces the viewer.
  g.axesRotation = RotateGizmo::axesFor(GizmoOrientation::Local, glm::angleAxis(kPi / 2, glm::vec3(0, 1, 0)));
  EXPECT_VEC3_NEAR(g.axis(0), glm::vec3(0, 0, -1), 1e-6f);
  EXPECT_EQ(hitTestRotateGizmo(g, v, onCircle(80, 45)), GizmoPart::AxisX);
  EXPECT_EQ(RotateGizmo::axesFor(GizmoOrientation::Global, glm::angleAxis(1.0f, glm::vec3(0, 1, 0))),
            glm::quat(1, 0, 0, 0));
}

// Counts the segments of axis ring i that ringSegmentFacesViewer keeps (64 segments).
int frontSegments(const RotateGizmo& g, const ViewportView& v, int i) {
  const std::vector<glm::vec3> ring = g.ringPoints(v, i, 64);
  int n = 0;
  for (size_t k = 0; k < ring.size(); ++k) n += ringSegmentFacesViewer(g, v, ring[k], ring[(k + 1) % ring.size()]);
  return n;
}

TEST(RotateGizmo, RingFacingTheViewAxisIsWholeOffCentreInPerspective) {
  // Pivot (4, -3, 0) in the perspective hand view: 40 px right and 30 px below the centre,
  // pixel (140, 130). The Z ring lies parallel to the image plane, so it projects to a full
  // 80 px circle (depth 10, 0.1 units per pixel) and all of it faces the viewer, although
  // the line from the pivot to the eye, (-4, 3, 10), leans 27 degrees off its axis.
  const ViewportView v = handView(false);
  RotateGizmo g;
  g.pivot = {4, -3, 0};
  EXPECT_EQ(frontSegments(g, v, 2), 64);
  // Grabbable all round, the upper right half (towards the screen centre) included.
  for (float deg : {45.0f, 135.0f, 225.0f, 315.0f}) {
    const float a = glm::radians(deg);
    EXPECT_EQ(hitTestRotateGizmo(g, v, {140 + 80 * std::cos(a), 130 - 80 * std::sin(a)}), GizmoPart::AxisZ) << deg;
  }
  // The edge-on X and Y rings still show their front halves: the segment midpoints lie at
  // z = 8 sin((k + 0.5) 360/64 deg), 32 of them in front of the pivot's plane; the bias
  // (2% of the radius) admits no more, as the nearest behind is 8 sin(2.8 deg) = 0.39 deep.
  for (int i = 0; i < 2; ++i) {
    EXPECT_GE(frontSegments(g, v, i), 32) << i;
    EXPECT_LE(frontSegments(g, v, i), 34) << i;
  }
}

TEST(RotateGizmo, NearlyFaceOnRingIsWholeAndAnObliqueRingShowsItsFrontHalf) {
  const ViewportView v = handView(true);
  RotateGizmo g;
  // Tilted 0.5 degrees: the farthest point lies 8 sin 0.5 = 0.07 behind the pivot's plane,
  // within the 2% bias (0.16): whole. Tilted 30 degrees: points with 8 sin 30 cos(t) >= -0.16,
  // i.e. cos t >= -0.04, about 51% of the ring: 32 to 34 of 64 segments.
  g.axesRotation = glm::angleAxis(glm::radians(0.5f), glm::vec3(0, 1, 0));
  EXPECT_EQ(frontSegments(g, v, 2), 64);
  g.axesRotation = glm::angleAxis(glm::radians(30.0f), glm::vec3(0, 1, 0));
  EXPECT_GE(frontSegments(g, v, 2), 32);
  EXPECT_LE(frontSegments(g, v, 2), 34);
  // Its farthest point, 8 axis(0) = 8 (cos 30, 0, -sin 30), is 4 behind the pivot: not
  // kept; the opposite point, 4 in front, is.
  const glm::vec3 far = g.pivot + 8.0f * g.axis(0);
  EXPECT_LT(far.z, 0.0f);
  EXPECT_FALSE(ringSegmentFacesViewer(g, v, far, far));
  EXPECT_TRUE(ringSegmentFacesViewer(g, v, g.pivot - 8.0f * g.axis(0), g.pivot - 8.0f * g.axis(0)));
}

TEST(RotateGizmo, SweptAngleIsCounterClockwiseAsTheViewerSeesIt) {
  const glm::vec2 c(100, 100);
  EXPECT_NEAR(sweptAngle(c, {150, 100}, {100, 50}), kPi / 2, 1e-6f);   // right -> up: CCW
  EXPECT_NEAR(sweptAngle(c, {150, 100}, {100, 150}), -kPi / 2, 1e-6f); // right -> down: CW
  EXPECT_NEAR(sweptAngle(c, {150, 100}, {300, 100}), 0.0f, 1e-6f);    // radius does not matter
  EXPECT_EQ(sweptAngle(c, c, {0, 0}), 0.0f);
  SweepTracker t;
  t.begin(c, onCircle(80, 0));
  for (float deg : {90.0f, 180.0f, 270.0f, 360.0f, 450.0f}) t.update(onCircle(80, deg));
  EXPECT_NEAR(t.total, 2.5f * kPi, 1e-5f);  // a turn and a quarter, not wrapped
}

// A quarter sweep counter-clockwise on screen around the pivot, from the right (180, 100) to
// the top (100, 20). Hand derivation: seen from +Z, a counter-clockwise quarter turn is +90
// degrees about +Z (right-hand rule: x -> y). The ring point under the start cursor, (8, 0, 0),
// goes to (0, 8, 0), which projects to the end cursor: the joint follows the mouse.
TEST(RotateGizmo, QuarterSweepIsNinetyDegreesAboutTheAxis) {
  for (bool ortho : {true, false}) {
    const ViewportView v = handView(ortho);
    float angle = 0;
    const glm::quat q = ringDragRotation(v, {0, 0, 0}, {0, 0, 1}, {180, 100}, {100, 20}, false, &angle);
    EXPECT_NEAR(angle, kPi / 2, 1e-5f);
    EXPECT_SAME_ROTATION(q, glm::angleAxis(kPi / 2, glm::vec3(0, 0, 1)), 1e-6f);
    EXPECT_VEC3_NEAR(q * glm::vec3(8, 0, 0), glm::vec3(0, 8, 0), 1e-4f);
    // The axis pointing away from the viewer: -90 degrees about -Z, the same turn on screen.
    const glm::quat away = ringDragRotation(v, {0, 0, 0}, {0, 0, -1}, {180, 100}, {100, 20}, false, &angle);
    EXPECT_NEAR(angle, -kPi / 2, 1e-5f);
    EXPECT_VEC3_NEAR(away * glm::vec3(8, 0, 0), glm::vec3(0, 8, 0), 1e-4f);
  }
}

TEST(RotateGizmo, CtrlSnapsToFiveDegrees) {
  const ViewportView v = handView(true);
  float angle = 0;
  ringDragRotation(v, {0, 0, 0}, {0, 0, 1}, onCircle(80, 0), onCircle(80, 47), true, &angle);
  EXPECT_NEAR(angle, glm::radians(45.0f), 1e-6f);
  ringDragRotation(v, {0, 0, 0}, {0, 0, 1}, onCircle(80, 0), onCircle(80, -48), true, &angle);
  EXPECT_NEAR(angle, glm::radians(-50.0f), 1e-6f);
  EXPECT_NEAR(snapAngle(glm::radians(2.4f)), 0.0f, 1e-7f);
  EXPECT_NEAR(snapAngle(glm::radians(12.6f), 5.0f), glm::radians(15.0f), 1e-6f);
}

TEST(RotateGizmo, TrackballTurnsAboutTheViewAxisPerpendicularToTheDrag) {
  const ViewportView v = handView(false);
  // 100 px to the right at 0.01 rad/px: 1 rad about +Y (towardViewer x drag = z x x = y), which
  // carries the ball's front point (0, 0, 1) towards +X, with the cursor.
  const glm::quat right = trackballRotation(v, {100, 100}, {200, 100}, 0.01f);
  EXPECT_SAME_ROTATION(right, glm::angleAxis(1.0f, glm::vec3(0, 1, 0)), 1e-6f);
  EXPECT_GT((right * glm::vec3(0, 0, 1)).x, 0.8f);
  // 50 px up (pixel y decreases): 0.5 rad about z x y = -X; the front point moves up.
  const glm::quat up = trackballRotation(v, {100, 100}, {100, 50}, 0.01f);
  EXPECT_SAME_ROTATION(up, glm::angleAxis(0.5f, glm::vec3(-1, 0, 0)), 1e-6f);
  EXPECT_GT((up * glm::vec3(0, 0, 1)).y, 0.4f);
  EXPECT_SAME_ROTATION(trackballRotation(v, {5, 5}, {5, 5}), glm::quat(1, 0, 0, 0), 1e-7f);
}

TEST(RotateGizmo, GizmoPartsTurnAboutTheirAxes) {
  const ViewportView v = handView(true);
  RotateGizmo g;
  const glm::vec2 from = onCircle(80, 0), to = onCircle(80, 90);
  EXPECT_SAME_ROTATION(gizmoDragRotation(g, v, GizmoPart::AxisZ, from, to, false),
                       glm::angleAxis(kPi / 2, glm::vec3(0, 0, 1)), 1e-5f);
  EXPECT_SAME_ROTATION(gizmoDragRotation(g, v, GizmoPart::ViewRing, from, to, false),
                       glm::angleAxis(kPi / 2, glm::vec3(0, 0, 1)), 1e-5f);
  // The X ring is edge-on here: the sweep still turns about X, by +90 (X lies in the view plane; sign +).
  EXPECT_SAME_ROTATION(gizmoDragRotation(g, v, GizmoPart::AxisX, from, to, false),
                       glm::angleAxis(kPi / 2, glm::vec3(1, 0, 0)), 1e-5f);
  EXPECT_SAME_ROTATION(gizmoDragRotation(g, v, GizmoPart::None, from, to, false), glm::quat(1, 0, 0, 0), 1e-7f);
}

TEST(RotateMode, AxisKeysCycleGlobalLocalFree) {
  RotateMode m;
  EXPECT_EQ(m.axis, -1);
  m.pressAxis(0);
  EXPECT_EQ(m.axis, 0);
  EXPECT_FALSE(m.local);
  m.pressAxis(0);
  EXPECT_EQ(m.axis, 0);
  EXPECT_TRUE(m.local);
  m.pressAxis(0);
  EXPECT_EQ(m.axis, -1);
  m.pressAxis(1);
  m.pressAxis(1);
  m.pressAxis(2);  // another axis starts global
  EXPECT_EQ(m.axis, 2);
  EXPECT_FALSE(m.local);
}

TEST(RotateMode, ConstrainedAndFreeRotations) {
  const ViewportView v = handView(false);
  const glm::quat joint = glm::angleAxis(kPi / 2, glm::vec3(0, 1, 0));  // local X = world -Z
  RotateMode m;
  float angle = 0;
  // Free: about the view axis (+Z here), a CCW quarter = +90 about +Z.
  EXPECT_SAME_ROTATION(m.rotation(v, {0, 0, 0}, joint, {180, 100}, {100, 20}, false, &angle),
                       glm::angleAxis(kPi / 2, glm::vec3(0, 0, 1)), 1e-5f);
  m.pressAxis(0);  // global X
  EXPECT_VEC3_NEAR(m.worldAxis(v, {0, 0, 0}, joint), glm::vec3(1, 0, 0), 1e-6f);
  m.pressAxis(0);  // local X = (0, 0, -1), pointing away: the angle about it is -90
  EXPECT_VEC3_NEAR(m.worldAxis(v, {0, 0, 0}, joint), glm::vec3(0, 0, -1), 1e-6f);
  const glm::quat q = m.rotation(v, {0, 0, 0}, joint, {180, 100}, {100, 20}, false, &angle);
  EXPECT_NEAR(angle, -kPi / 2, 1e-5f);
  EXPECT_VEC3_NEAR(q * glm::vec3(1, 0, 0), glm::vec3(0, 1, 0), 1e-5f);
}

// Parent world rotation P = 90 degrees about Z, start local L = identity, world turn D = 90
// degrees about X. The new world rotation is D P, so the local one is P^-1 D P: a 90 degree turn
// about P^-1 (1, 0, 0) = (0, -1, 0) (rotating x by -90 about z).
TEST(RotateGizmo, WorldTurnBecomesTheLocalRotationUnderTheParent) {
  const glm::quat parent = glm::angleAxis(kPi / 2, glm::vec3(0, 0, 1));
  const glm::quat delta = glm::angleAxis(kPi / 2, glm::vec3(1, 0, 0));
  const glm::quat local = localRotationAfterWorldTurn(parent, glm::quat(1, 0, 0, 0), delta);
  EXPECT_SAME_ROTATION(local, glm::angleAxis(kPi / 2, glm::vec3(0, -1, 0)), 1e-6f);
  EXPECT_SAME_ROTATION(parent * local, delta * parent, 1e-6f);
  // A root (identity parent) with a start rotation: the turn is applied on the world side.
  const glm::quat start = glm::angleAxis(0.3f, glm::vec3(0, 1, 0));
  EXPECT_SAME_ROTATION(localRotationAfterWorldTurn(glm::quat(1, 0, 0, 0), start, delta), delta * start, 1e-6f);
}

}  // namespace
}  // namespace kinema::test

namespace kinema::test {
namespace KINEMA_UNITY_ID {

// The default character as the editor first frames it (render/skeleton_view.h), in the
// 3D view of the editor's 1600 x 1000 window (1040 x 917 pixels).
struct DefaultCharacterView {
  Skeleton skeleton = makeDefaultCharacter();
  std::vector<glm::mat4> world = computeWorld(skeleton, Pose::rest(skeleton));
  ViewportView view = ViewportView::of(defaultCamera(jointBounds(world), 1040.0f / 917.0f), {1040, 917});
  glm::vec2 pixel(int joint) const {
    glm::vec2 p(0.0f);
    EXPECT_TRUE(view.project(glm::vec3(world[joint][3]), p));
    return p;
  }
};

TEST(RotateGizmoSize, OnAFootAtTheDefaultZoomItCoversNeitherTheOtherFootNorAnyUnrelatedJoint) {
  const DefaultCharacterView c;
  const int foot = c.skeleton.find("Foot.L"), otherFoot = c.skeleton.find("Foot.R");
  ASSERT_GE(foot, 0);
  ASSERT_GE(otherFoot, 0);
  const float ring = rotateGizmoRingPixels(c.view, c.world, c.skeleton.parents, foot);
  // The feet are 0.18 m apart (x = +-0.09): the view ring (1.2 times wider) and its 6 px
  // grab band end before half-way to the other foot; far under Blender's 80 px.
  const float feetApart = glm::length(c.pixel(otherFoot) - c.pixel(foot));
  EXPECT_LE(kViewRingScale * ring + 6.0f, 0.5f * feetApart + 1e-3f);
  EXPECT_LT(ring, 80.0f);
  EXPECT_GE(ring, kMinGizmoRingPixels);
  // Neither ring nor its grab band reaches half-way to a joint the foot does not carry.
  const int lowerLeg = c.skeleton.find("LowerLeg.L");
  for (int k = 0; k < c.skeleton.size(); ++k) {
    bool carried = false;
    for (int a = k; a >= 0; a = c.skeleton.parents[a]) carried = carried || a == foot;
    if (carried || k == lowerLeg) continue;
    EXPECT_GE(0.5f * glm::length(c.pixel(k) - c.pixel(foot)) + 1e-3f, kViewRingScale * ring + 6.0f) << c.skeleton.names[k];
  }
}

TEST(RotateGizmoSize, BlendersSizeWhenNothingUnrelatedIsNearAndAFloorWhenEverythingIs) {
  const DefaultCharacterView c;
  // The root carries every joint: nothing limits it.
  EXPECT_FLOAT_EQ(rotateGizmoRingPixels(c.view, c.world, c.skeleton.parents, c.skeleton.find("Hips")), 80.0f);
  // Two roots 10 px apart in the hand view (0.1 units per pixel, orthographic): the floor
  // (by the rule (5 - 6) / 1.2 px).
  const ViewportView v = handView(true);
  const std::vector<glm::mat4> two{glm::mat4(1.0f), glm::translate(glm::mat4(1.0f), glm::vec3(1.0f, 0.0f, 0.0f))};
  EXPECT_FLOAT_EQ(rotateGizmoRingPixels(v, two, {-1, -1}, 0), kMinGizmoRingPixels);
  // 300 px apart: (150 - 6) / 1.2 = 120, so Blender's 80.
  const std::vector<glm::mat4> far{glm::mat4(1.0f), glm::translate(glm::mat4(1.0f), glm::vec3(30.0f, 0.0f, 0.0f))};
  EXPECT_FLOAT_EQ(rotateGizmoRingPixels(v, far, {-1, -1}, 0), 80.0f);
  // 100 px apart: (50 - 6) / 1.2 = 36.67 px.
  const std::vector<glm::mat4> mid{glm::mat4(1.0f), glm::translate(glm::mat4(1.0f), glm::vec3(10.0f, 0.0f, 0.0f))};
  EXPECT_NEAR(rotateGizmoRingPixels(v, mid, {-1, -1}, 0), 44.0f / 1.2f, 1e-3f);
}

}  // namespace
}  // namespace kinema::test
