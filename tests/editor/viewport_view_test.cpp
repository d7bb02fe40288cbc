// Pixels <-> world on the hand camera of viewport_test_views.h, perspective and orthographic.
#include "editor/viewport_test_views.h"
#include "test_support.h"

namespace kinema::test {
namespace KINEMA_UNITY_ID {

TEST(ViewportView, PerspectiveProjectsByDepth) {
  const ViewportView v = handView(false);
  glm::vec2 p;
  ASSERT_TRUE(v.project({1, 2, 0}, p));  // depth 10
  EXPECT_NEAR(p.x, 110.0f, 1e-3f);
  EXPECT_NEAR(p.y, 80.0f, 1e-3f);
  ASSERT_TRUE(v.project({1, 2, 5}, p));  // depth 5: twice as far from the centre
  EXPECT_NEAR(p.x, 120.0f, 1e-3f);
  EXPECT_NEAR(p.y, 60.0f, 1e-3f);
  EXPECT_FALSE(v.project({0, 0, 11}, p));  // behind the eye
  EXPECT_NEAR(v.unitsPerPixelAt({0, 0, 0}), 0.1f, 1e-6f);
  EXPECT_NEAR(v.unitsPerPixelAt({3, 1, 5}), 0.05f, 1e-6f);
  EXPECT_VEC3_NEAR(v.eye(), glm::vec3(0, 0, 10), 1e-5f);
  EXPECT_VEC3_NEAR(v.forward(), glm::vec3(0, 0, -1), 1e-6f);
  EXPECT_VEC3_NEAR(v.right(), glm::vec3(1, 0, 0), 1e-6f);
  EXPECT_VEC3_NEAR(v.up(), glm::vec3(0, 1, 0), 1e-6f);
  EXPECT_VEC3_NEAR(v.towardViewer({0, 0, 7}), glm::vec3(0, 0, 1), 1e-6f);
  EXPECT_VEC3_NEAR(v.towardViewer({10, 0, 0}), glm::normalize(glm::vec3(-10, 0, 10)), 1e-6f);
}

TEST(ViewportView, AViewportBetweenPanelsWorksInWindowPixels) {
  // The same 200 x 200 view placed with its top left corner at window pixel (250, 19), as
  // the editor's 3D view sits between its panels: every pixel shifts by (250, 19), the rays
  // through shifted pixels are the unshifted ones, and picking a joint's fallback circle
  // takes window pixels too.
  const ViewportView base = handView(false);
  const ViewportView v = ViewportView::of(handCamera(false), {200, 200}, {250, 19});
  glm::vec2 p;
  ASSERT_TRUE(v.project({1, 2, 0}, p));
  EXPECT_NEAR(p.x, 250.0f + 110.0f, 1e-3f);
  EXPECT_NEAR(p.y, 19.0f + 80.0f, 1e-3f);
  const PickRay a = v.rayThrough({250 + 130, 19 + 40}), b = base.rayThrough({130, 40});
  EXPECT_VEC3_NEAR(a.origin, b.origin, 1e-5f);
  EXPECT_VEC3_NEAR(a.direction, b.direction, 1e-6f);
  // The centre of the viewport looks straight down -Z.
  EXPECT_VEC3_NEAR(v.rayThrough({350, 119}).direction, glm::vec3(0, 0, -1), 1e-6f);
  EXPECT_NEAR(v.unitsPerPixelAt({0, 0, 0}), 0.1f, 1e-6f);
}

TEST(ViewportView, OrthographicIgnoresDepth) {
  const ViewportView v = handView(true);
  glm::vec2 p;
  for (float z : {0.0f, 5.0f, -20.0f}) {
    ASSERT_TRUE(v.project({1, 2, z}, p));
    EXPECT_NEAR(p.x, 110.0f, 1e-3f);
    EXPECT_NEAR(p.y, 80.0f, 1e-3f);
    EXPECT_NEAR(v.unitsPerPixelAt({0, 0, z}), 0.1f, 1e-6f);
  }
  EXPECT_VEC3_NEAR(v.towardViewer({10, 0, 0}), glm::vec3(0, 0, 1), 1e-6f);
}

TEST(ViewportView, RaysGoThroughThePixel) {
  const PickRay persp = handView(false).rayThrough({110, 80});
  EXPECT_VEC3_NEAR(persp.origin, glm::vec3(0, 0, 10), 1e-4f);
  EXPECT_VEC3_NEAR(persp.direction, glm::normalize(glm::vec3(1, 2, -10)), 1e-5f);
  const PickRay ortho = handView(true).rayThrough({110, 80});
  EXPECT_VEC3_NEAR(ortho.origin, glm::vec3(1, 2, 9.9f), 1e-4f);  // on the near plane, 0.1 from the eye
  EXPECT_VEC3_NEAR(ortho.direction, glm::vec3(0, 0, -1), 1e-6f);
}

TEST(ViewportView, ProjectAndRayAreInversesOnAnObliqueCamera) {
  OrbitCamera c;
  c.azimuthDeg = 37;
  c.elevationDeg = -22;
  c.distance = 3.5f;
  c.target = {0.3f, 1.1f, -0.4f};
  for (bool ortho : {false, true}) {
    c.orthographic = ortho;
    const ViewportView v = ViewportView::of(c, {640, 360});
    const glm::vec3 point(0.7f, 0.2f, 0.1f);
    glm::vec2 pixel;
    ASSERT_TRUE(v.project(point, pixel));
    const PickRay ray = v.rayThrough(pixel);
    // The point lies on the ray: its distance from the ray is ~0.
    const glm::vec3 rel = point - ray.origin;
    EXPECT_NEAR(glm::length(rel - ray.direction * glm::dot(rel, ray.direction)), 0.0f, 1e-4f) << ortho;
  }
}

}  // namespace
}  // namespace kinema::test
