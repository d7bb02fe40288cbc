// ScreenRegion / appendTrianglesInRegion (screen_culling.h): what a partial redraw may leave
// out. Checked against a brute-force rasterisation (every pixel centre inside the limit
// tested against every triangle by edge functions on glm::project's pixels): no triangle
// that covers a pixel of the limit is ever dropped, and triangles far from it are.
#include <gtest/gtest.h>

#include <random>

#include "render/camera.h"
#include "render/screen_culling.h"

namespace kinema {
namespace KINEMA_UNITY_ID {

constexpr int kX = 30, kY = 10, kW = 320, kH = 240;

ScreenRegion regionOf(const PixelRect& limit, glm::mat4* view = nullptr, glm::mat4* projection = nullptr) {
  OrbitCamera camera;
  camera.azimuthDeg = 20.0f;
  camera.elevationDeg = 15.0f;
  camera.target = glm::vec3(0.0f);
  camera.distance = 6.0f;
  camera.fitClipPlanes(3.0f);
  if (view) *view = camera.view();
  if (projection) *projection = camera.projection(float(kW) / kH);
  return ScreenRegion{camera.projection(float(kW) / kH) * camera.view(), PixelRect{kX, kY, kX + kW, kY + kH}, limit};
}

// Whether the triangle covers the centre of some pixel of `limit` (a top-left rule is not
// needed: an edge through a centre counts as covering, which is the conservative side).
bool coversAPixel(const glm::vec2 p[3], const PixelRect& limit) {
  auto edge = [](const glm::vec2& a, const glm::vec2& b, const glm::vec2& c) {
    return (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x);
  };
  for (int y = limit.y0; y < limit.y1; ++y)
    for (int x = limit.x0; x < limit.x1; ++x) {
      const glm::vec2 c(x + 0.5f, y + 0.5f);
      const float e0 = edge(p[0], p[1], c), e1 = edge(p[1], p[2], c), e2 = edge(p[2], p[0], c);
      if ((e0 >= 0 && e1 >= 0 && e2 >= 0) || (e0 <= 0 && e1 <= 0 && e2 <= 0)) return true;
    }
  return false;
}

TEST(ScreenCulling, KeepsEveryTriangleThatCoversALimitPixelAndDropsFarOnes) {
  glm::mat4 view, projection;
  const PixelRect limit{150, 100, 190, 130};
  const ScreenRegion region = regionOf(limit, &view, &projection);
  ASSERT_TRUE(region.culls());
  // Small random triangles over the whole view, as a body's are.
  std::mt19937 rng(7);
  std::uniform_real_distribution<float> centre(-2.0f, 2.0f), offset(-0.15f, 0.15f);
  std::vector<float> positions;  // stride 4: the function reads three of every four floats
  std::vector<uint32_t> indices;
  for (uint32_t t = 0; t < 3000; ++t) {
    const glm::vec3 c(centre(rng), centre(rng), centre(rng));
    for (int k = 0; k < 3; ++k) {
      positions.insert(positions.end(), {c.x + offset(rng), c.y + offset(rng), c.z + offset(rng), 99.0f});
      indices.push_back(3 * t + k);
    }
  }
  std::vector<uint32_t> kept = {7, 7, 7};  // appended to, not replaced
  ScreenCullScratch scratch;
  appendTrianglesInRegion(region, positions.data(), 4, positions.size() / 4, indices, kept, scratch);
  ASSERT_EQ(kept.size() % 3, 0u);
  std::vector<char> isKept(indices.size() / 3, 0);
  for (size_t k = 3; k < kept.size(); k += 3) {
    ASSERT_EQ(kept[k] % 3, 0u);
    ASSERT_EQ(kept[k + 1], kept[k] + 1);
    ASSERT_EQ(kept[k + 2], kept[k] + 2);
    if (k > 3) {
      EXPECT_GT(kept[k], kept[k - 3]) << "the kept triangles stay in their order";
    }
    isKept[kept[k] / 3] = 1;
  }
  int covering = 0, dropped = 0;
  for (size_t t = 0; t < isKept.size(); ++t) {
    glm::vec2 p[3];
    glm::vec2 lo(1e9f), hi(-1e9f);
    for (int k = 0; k < 3; ++k) {
      const float* q = &positions[4 * (3 * t + k)];
      p[k] = glm::vec2(glm::project(glm::vec3(q[0], q[1], q[2]), view, projection, glm::vec4(kX, kY, kW, kH)));
      lo = glm::min(lo, p[k]), hi = glm::max(hi, p[k]);
    }
    if (coversAPixel(p, limit)) {
      ++covering;
      EXPECT_TRUE(isKept[t]) << "triangle " << t << " covers a pixel of the limit";
    }
    // Farther than the margin plus a pixel from the limit on some side: nothing to draw there.
    const float far = float(kScreenCullMargin) + 1.0f;
    if (hi.x < limit.x0 - far || lo.x > limit.x1 + far || hi.y < limit.y0 - far || lo.y > limit.y1 + far) {
      EXPECT_FALSE(isKept[t]) << "triangle " << t << " is far from the limit";
      ++dropped;
    }
  }
  EXPECT_GT(covering, 5) << "the scene must put triangles over the limit for this test to mean anything";
  EXPECT_GT(dropped, 2500) << "most of the view is far from a 40 x 30 limit";
}

TEST(ScreenCulling, KeepsTrianglesBehindTheCameraAndDropsBadIndices) {
  const ScreenRegion region = regionOf(PixelRect{150, 100, 160, 110});
  // The camera sits 6 from the origin towards about +z (azimuth 20 degrees): a triangle
  // 10 to its right, at the origin's depth, is far outside the view; one reaching from
  // z = -30 to z = 30 crosses the camera plane, where only the clipper knows what shows.
  const std::vector<float> positions = {
      9.4f, 0.0f, -3.4f,  // to the right, in front of the camera
      9.5f, 0.0f, -3.4f,  //
      9.4f, 0.1f, -3.4f,  //
      0.0f, 0.0f, -30.0f,
      0.0f, 0.0f, 30.0f,  // behind the camera
  };
  const std::vector<uint32_t> indices = {0, 1, 2, 0, 3, 4, 0, 1, 9};
  std::vector<uint32_t> kept;
  ScreenCullScratch scratch;
  appendTrianglesInRegion(region, positions.data(), 3, 5, indices, kept, scratch);
  EXPECT_EQ(kept, (std::vector<uint32_t>{0, 3, 4}));
  // Without a limit (or one holding the whole viewport) everything in range is kept.
  kept.clear();
  appendTrianglesInRegion(regionOf(PixelRect{}), positions.data(), 3, 5, indices, kept, scratch);
  EXPECT_EQ(kept, (std::vector<uint32_t>{0, 1, 2, 0, 3, 4}));
  EXPECT_FALSE(regionOf(PixelRect{0, 0, 1000, 1000}).culls());
}

TEST(ScreenCulling, BoxesAreTestedByTheirEightCorners) {
  glm::mat4 view, projection;
  const PixelRect limit{150, 100, 160, 110};
  const ScreenRegion region = regionOf(limit, &view, &projection);
  // A unit box moved to where the limit's centre looks at depth 0 (the target's depth).
  const glm::vec3 atLimit = glm::unProject(glm::vec3(155.0f, 105.0f, 0.5f), view, projection, glm::vec4(kX, kY, kW, kH));
  const glm::mat4 small = glm::translate(glm::mat4(1.0f), atLimit) * glm::scale(glm::mat4(1.0f), glm::vec3(0.01f));
  EXPECT_TRUE(region.boxMayCover(small, glm::vec3(-1.0f), glm::vec3(1.0f)));
  const glm::mat4 away = glm::translate(glm::mat4(1.0f), glm::vec3(2.0f, 1.5f, 0.0f)) * glm::scale(glm::mat4(1.0f), glm::vec3(0.01f));
  EXPECT_FALSE(region.boxMayCover(away, glm::vec3(-1.0f), glm::vec3(1.0f)));
  // A box around the camera always may.
  const glm::vec3 eye(glm::inverse(view)[3]);
  EXPECT_TRUE(region.boxMayCover(glm::translate(glm::mat4(1.0f), eye), glm::vec3(-1.0f), glm::vec3(1.0f)));
}

}  // namespace
}  // namespace kinema
