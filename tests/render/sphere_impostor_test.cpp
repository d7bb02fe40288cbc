// Joint spheres drawn as impostors while the view moves (FrameDescription::frontFacesOnly,
// shaders/sphere_impostor.*): a box per joint whose pixels find the sphere by a ray. Checked
// against the closed forms of the sphere's outline (a circle of radius R = h/2 tan(asin(r/d))
// / tan(fov/2) pixels in perspective, r / (d tan(fov/2)) * h/2 in orthographic) and against
// the tessellated 16 x 10 sphere drawn when still: the same colours inside (its normals are
// interpolated, the impostor's exact), and the same one in front where two spheres overlap
// (the impostor's depth is the sphere's, not its box's).
#include <gtest/gtest.h>

#include <cmath>

#include "render/headless_renderer.h"

namespace kinema {
namespace KINEMA_UNITY_ID {

constexpr int kSize = 200;
const glm::vec4 kBackground(0.2f, 0.2f, 0.2f, 1.0f);

Image draw(HeadlessRenderer& renderer, const SkeletonDrawList& list, bool orthographic, bool frontFacesOnly) {
  FrameDescription frame;
  frame.skeleton = &list;
  frame.showGrid = false;
  frame.background = kBackground;
  frame.camera.azimuthDeg = 0.0f;  // looking along -Z at the origin
  frame.camera.elevationDeg = 0.0f;
  frame.camera.target = glm::vec3(0.0f);
  frame.camera.distance = 4.0f;
  frame.camera.orthographic = orthographic;
  frame.camera.fitClipPlanes(2.0f);
  frame.frontFacesOnly = frontFacesOnly;
  return renderer.render(frame);
}

bool isBackground(const Image& img, int x, int y) {
  const std::uint8_t* p = img.pixel(x, y);
  const int bg = int(0.2f * 255.0f + 0.5f);
  return std::abs(p[0] - bg) <= 2 && std::abs(p[1] - bg) <= 2 && std::abs(p[2] - bg) <= 2;
}

TEST(SphereImpostor, MatchesTheSpheresOutlineAndTheTessellatedSphere) {
  setenv("LIBGL_ALWAYS_SOFTWARE", "1", 0);
  auto opened = HeadlessRenderer::open(HeadlessBackend::Egl, kSize, kSize);
  ASSERT_TRUE(opened.ok()) << (opened.ok() ? "" : opened.error());
  HeadlessRenderer& renderer = *opened.value();
  // A sphere of radius 0.8 at the origin, and a red one of 0.5 in front of its right side
  // (their surfaces cross, so which is nearer changes across the overlap).
  SkeletonDrawList list;
  list.jointMatrices = {glm::scale(glm::mat4(1.0f), glm::vec3(0.8f)),
                        glm::translate(glm::mat4(1.0f), glm::vec3(0.6f, 0.0f, 0.5f)) * glm::scale(glm::mat4(1.0f), glm::vec3(0.5f))};
  list.jointColors = {glm::vec4(0.8f, 0.8f, 0.8f, 1.0f), glm::vec4(0.9f, 0.1f, 0.1f, 1.0f)};
  list.joints = {0, 1};
  const float fov = glm::radians(OrbitCamera().fovYDeg), d = 4.0f;
  for (const bool orthographic : {false, true}) {
    SCOPED_TRACE(orthographic ? "orthographic" : "perspective");
    const Image still = draw(renderer, list, orthographic, false);
    const Image moving = draw(renderer, list, orthographic, true);
    ASSERT_EQ(moving.width, kSize);
    // The big sphere's outline along the row through the centre, on its left (the red one
    // is on the right): its leftmost pixel against the closed form.
    const double radius = orthographic ? 0.8 / (d * std::tan(fov / 2.0)) * kSize / 2.0
                                       : kSize / 2.0 * std::tan(std::asin(0.8 / d)) / std::tan(fov / 2.0);
    int left = kSize / 2;
    while (left > 0 && !isBackground(moving, left - 1, kSize / 2)) --left;
    EXPECT_NEAR(kSize / 2.0 - left, radius, 1.0);
    // Inside both outlines, away from edges: the same colours within the tessellation's
    // shading error.
    int compared = 0, far = 0;
    for (int y = 2; y < kSize - 2; ++y)
      for (int x = 2; x < kSize - 2; ++x) {
        bool inside = true;
        for (int dy = -2; dy <= 2 && inside; ++dy)
          for (int dx = -2; dx <= 2 && inside; ++dx) {
            const std::uint8_t *a = still.pixel(x + dx, y + dy), *b = still.pixel(x, y);
            inside = !isBackground(still, x + dx, y + dy) && !isBackground(moving, x + dx, y + dy) &&
                     std::abs(a[0] - b[0]) + std::abs(a[1] - b[1]) + std::abs(a[2] - b[2]) < 60;  // not across the two spheres' seam
          }
        if (!inside) continue;
        ++compared;
        const std::uint8_t *a = still.pixel(x, y), *b = moving.pixel(x, y);
        far += std::abs(a[0] - b[0]) > 12 || std::abs(a[1] - b[1]) > 12 || std::abs(a[2] - b[2]) > 12;
      }
    EXPECT_GT(compared, 8000);
    EXPECT_EQ(far, 0) << "pixels inside the spheres differ by more than the tessellation's shading error";
  }
}

}  // namespace
}  // namespace kinema
