// View-plane and axis drags on the hand camera (viewport_test_views.h): at depth D a pixel
// spans D / 100 world units (perspective, tan 45 = 1, 200 px high), 0.1 units (orthographic).
#include "editor/viewport/translate_drag.h"
#include "editor/viewport_test_views.h"
#include "test_support.h"

namespace kinema::test {
namespace KINEMA_UNITY_ID {

TEST(TranslateDrag, ViewPlaneDragKeepsDepthAndFollowsTheCursor) {
  const ViewportView persp = handView(false);
  // Depth 10: 50 px = 5 units.
  EXPECT_VEC3_NEAR(dragInViewPlane(persp, {0, 0, 0}, {100, 100}, {150, 100}), glm::vec3(5, 0, 0), 1e-4f);
  // Depth 5: 50 px right and 20 px up = (2.5, 1, 0) in the plane z = 5.
  EXPECT_VEC3_NEAR(dragInViewPlane(persp, {0, 0, 5}, {100, 100}, {150, 80}), glm::vec3(2.5f, 1, 5), 1e-4f);
  // Grabbed 10 px left of the point (1, 0, 0), moved 20 px: the offset is kept.
  EXPECT_VEC3_NEAR(dragInViewPlane(persp, {1, 0, 0}, {100, 100}, {120, 100}), glm::vec3(3, 0, 0), 1e-4f);
  const ViewportView ortho = handView(true);
  EXPECT_VEC3_NEAR(dragInViewPlane(ortho, {0, 0, 5}, {100, 100}, {150, 100}), glm::vec3(5, 0, 5), 1e-4f);
  // The point projects to the cursor after the drag (perspective, oblique start).
  const glm::vec3 moved = dragInViewPlane(persp, {1, 2, -3}, {100 + 100.0f / 13, 100 - 200.0f / 13}, {40, 170});
  glm::vec2 p;
  ASSERT_TRUE(persp.project(moved, p));
  EXPECT_NEAR(p.x, 40.0f, 1e-2f);
  EXPECT_NEAR(p.y, 170.0f, 1e-2f);
  EXPECT_NEAR(moved.z, -3.0f, 1e-4f);
}

TEST(TranslateDrag, ClosestPointOnALineToARay) {
  glm::vec3 out;
  ASSERT_TRUE(closestPointOnLineToRay({0, 0, 0}, {1, 0, 0}, {{2, 3, 5}, {0, 0, -1}}, out));
  EXPECT_VEC3_NEAR(out, glm::vec3(2, 0, 0), 1e-6f);
  // Line direction need not be unit.
  ASSERT_TRUE(closestPointOnLineToRay({0, 1, 0}, {0, 0, 4}, {{-5, 1, 2.5f}, {1, 0, 0}}, out));
  EXPECT_VEC3_NEAR(out, glm::vec3(0, 1, 2.5f), 1e-6f);
  out = glm::vec3(7);
  EXPECT_FALSE(closestPointOnLineToRay({0, 0, 0}, {0, 0, 1}, {{1, 1, 1}, {0, 0, -1}}, out));
  EXPECT_VEC3_NEAR(out, glm::vec3(7), 0.0f);
}

// Axis X through the origin, cursor at pixel (150, 130): the ray from (0, 0, 10) through
// (5, -3, 0). Minimising |(s, 0, 0) - (5t, -3t, 10 - 10t)|^2 gives s = 5t and
// 18 t - 20 (10 - 10 t) = 0, t = 100/109, s = 500/109.
TEST(TranslateDrag, AxisDragIsTheClosestPointBetweenRayAndAxis) {
  const ViewportView persp = handView(false);
  EXPECT_VEC3_NEAR(dragAlongAxis(persp, {0, 0, 0}, {1, 0, 0}, {100, 100}, {150, 130}),
                   glm::vec3(500.0f / 109.0f, 0, 0), 1e-4f);
  // Orthographic: only the cursor's x matters for the X axis; 30 px = 3 units.
  const ViewportView ortho = handView(true);
  EXPECT_VEC3_NEAR(dragAlongAxis(ortho, {1, 2, 3}, {1, 0, 0}, {110, 80}, {140, 10}), glm::vec3(4, 2, 3), 1e-4f);
  // The Z axis points at the orthographic viewer: no motion rather than a jump.
  EXPECT_VEC3_NEAR(dragAlongAxis(ortho, {1, 2, 3}, {0, 0, 1}, {110, 80}, {140, 10}), glm::vec3(1, 2, 3), 0.0f);
}

}  // namespace
}  // namespace kinema::test
