// Properties of the viewport maths over random cameras (both projections): rays pass through
// the points that project to their pixel, a view-plane drag puts the point under the cursor,
// and a ring drag turns the ring point under the cursor round the pivot the way the cursor went.
#include <random>

#include "editor/viewport/rotate_gizmo.h"
#include "editor/viewport/translate_drag.h"
#include "test_support.h"

namespace kinema::test {
namespace KINEMA_UNITY_ID {

OrbitCamera randomCamera(std::mt19937& rng, bool ortho) {
  std::uniform_real_distribution<float> u(-1.0f, 1.0f);
  OrbitCamera c;
  c.azimuthDeg = 180.0f * u(rng);
  c.elevationDeg = 80.0f * u(rng);
  c.distance = 3.0f + 2.0f * u(rng);
  c.target = glm::vec3(u(rng), u(rng) + 1.0f, u(rng));
  c.fovYDeg = 50.0f + 20.0f * u(rng);
  c.fitClipPlanes(2.0f);
  c.orthographic = ortho;
  return c;
}

TEST(ViewportProperties, RaysDragsAndRingTurnsAgreeWithProjection) {
  std::mt19937 rng(20240811);
  std::uniform_real_distribution<float> u(-1.0f, 1.0f);
  const int cases = propertyCases(200);
  for (int n = 0; n < cases; ++n) {
    const bool ortho = n % 2 == 1;
    const OrbitCamera camera = randomCamera(rng, ortho);
    const ViewportView v = ViewportView::of(camera, {640, 480});
    const glm::vec3 point = camera.target + 0.5f * glm::vec3(u(rng), u(rng), u(rng));
    glm::vec2 pixel;
    ASSERT_TRUE(v.project(point, pixel));
    const PickRay ray = v.rayThrough(pixel);
    const glm::vec3 rel = point - ray.origin;
    EXPECT_LT(glm::length(rel - ray.direction * glm::dot(rel, ray.direction)), 1e-4f * camera.distance) << n;

    const glm::vec2 cursor = pixel + glm::vec2(120.0f * u(rng), 120.0f * u(rng));
    glm::vec2 moved;
    ASSERT_TRUE(v.project(dragInViewPlane(v, point, pixel, cursor), moved));
    EXPECT_LT(glm::length(moved - cursor), 0.05f) << n;

    // A 20 degree counter-clockwise sweep about a random axis not too edge-on: the ring point
    // that starts under the cursor turns counter-clockwise round the pivot on screen too.
    const glm::vec3 axis = randomRotation(rng) * glm::vec3(0, 0, 1);
    if (std::abs(glm::dot(axis, v.towardViewer(point))) < 0.3f) continue;
    RotateGizmo g;
    g.pivot = point;
    glm::vec3 side = glm::normalize(glm::cross(axis, glm::vec3(u(rng), u(rng), u(rng))));
    const glm::vec3 ringPoint = point + side * g.ringRadiusWorld(v);
    glm::vec2 start;
    ASSERT_TRUE(v.project(ringPoint, start));
    const float a = glm::radians(20.0f);
    const glm::vec2 d = start - pixel;  // rotate by +a counter-clockwise on screen (y down)
    const glm::vec2 end = pixel + glm::vec2(d.x * std::cos(a) + d.y * std::sin(a), -d.x * std::sin(a) + d.y * std::cos(a));
    float angle = 0;
    const glm::quat q = ringDragRotation(v, point, axis, start, end, false, &angle);
    EXPECT_NEAR(std::abs(angle), a, 1e-4f) << n;
    glm::vec2 turned;
    ASSERT_TRUE(v.project(point + q * (ringPoint - point), turned));
    EXPECT_GT(sweptAngle(pixel, start, turned), 0.0f) << n;
  }
}

}  // namespace
}  // namespace kinema::test
