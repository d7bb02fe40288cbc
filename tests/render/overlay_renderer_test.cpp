// The overlay renderer: the CPU expansion of lines and handles into clip-space triangles
// (exact pixel widths), and a golden image of a full frame with a gizmo, an IK target handle,
// a limit cone and a box-select rectangle (tests/render/overlay_sample_main.cpp).
#include <algorithm>
#include <sstream>

#include "io/image.h"
#include "render/image_compare.h"
#include "render/overlay_renderer.h"
#include "test_support.h"

namespace kinema::test {
namespace KINEMA_UNITY_ID {

using Layer = OverlayDrawList::Layer;

// Identity view-projection, viewport 200 x 100: one pixel is 0.01 NDC across, 0.02 up.
TEST(OverlayRenderer, LinesBecomeQuadsOfTheirPixelWidth) {
  OverlayDrawList list;
  list.addLine({-0.5f, 0, 0}, {0.5f, 0, 0}, {1, 0, 0, 1}, 4.0f, Layer::OnTop);
  std::vector<OverlayRenderer::Vertex> v;
  OverlayRenderer::appendTriangles(list, Layer::OnTop, glm::mat4(1.0f), {200, 100}, v);
  ASSERT_EQ(v.size(), 6u);
  float minX = 9, maxX = -9, minY = 9, maxY = -9;
  for (const auto& p : v) {
    minX = std::min(minX, p.clip.x / p.clip.w);
    maxX = std::max(maxX, p.clip.x / p.clip.w);
    minY = std::min(minY, p.clip.y / p.clip.w);
    maxY = std::max(maxY, p.clip.y / p.clip.w);
    EXPECT_EQ(p.color, glm::vec4(1, 0, 0, 1));
  }
  // 2 px either side: 0.04 NDC vertically; lengthened by 2 px (0.02 NDC) at both ends.
  EXPECT_NEAR(minY, -0.04f, 1e-6f);
  EXPECT_NEAR(maxY, 0.04f, 1e-6f);
  EXPECT_NEAR(minX, -0.52f, 1e-6f);
  EXPECT_NEAR(maxX, 0.52f, 1e-6f);
  v.clear();
  OverlayRenderer::appendTriangles(list, Layer::Scene, glm::mat4(1.0f), {200, 100}, v);
  EXPECT_TRUE(v.empty());  // the other layer
}

TEST(OverlayRenderer, LinesAreCutAtTheNearPlane) {
  // Identity: the near plane is z = -1. From (-1, 0, -3) to (1, 0, 1) it is crossed half-way, at x = 0.
  OverlayDrawList list;
  list.addLine({-1, 0, -3}, {1, 0, 1}, {1, 1, 1, 1}, 2.0f);
  list.addLine({-1, 0, -3}, {1, 0, -2}, {1, 1, 1, 1}, 2.0f);  // wholly before the near plane: dropped
  std::vector<OverlayRenderer::Vertex> v;
  OverlayRenderer::appendTriangles(list, Layer::OnTop, glm::mat4(1.0f), {200, 100}, v);
  ASSERT_EQ(v.size(), 6u);
  float minX = 9;
  for (const auto& p : v) minX = std::min(minX, p.clip.x / p.clip.w);
  EXPECT_NEAR(minX, -0.01f, 1e-6f);  // 0 minus the 1 px end cap
}

TEST(OverlayRenderer, HandlesAreShapesOfTheirPixelRadius) {
  OverlayDrawList list;
  list.addHandle({0, 0, 0}, 6.0f, {1, 1, 0, 1}, OverlayDrawList::HandleShape::Diamond);
  list.handles.back().outline.a = 0;
  list.addHandle({0, 0, 0}, 10.0f, {1, 1, 1, 0.5f}, OverlayDrawList::HandleShape::Disc);
  list.handles.back().outline.a = 0;
  std::vector<OverlayRenderer::Vertex> v;
  OverlayRenderer::appendTriangles(list, Layer::OnTop, glm::mat4(1.0f), {200, 100}, v);
  ASSERT_EQ(v.size(), 32u * 3 + 6);
  // The translucent disc comes first (a backdrop), then the opaque diamond.
  for (size_t k = 0; k < 96; ++k) {
    const glm::vec2 px(v[k].clip.x * 100, v[k].clip.y * 50);
    const float r = glm::length(px);
    EXPECT_TRUE(r < 1e-4f || std::abs(r - 10.0f) < 1e-3f) << r;
  }
  float maxX = 0, maxY = 0;
  for (size_t k = 96; k < v.size(); ++k) {
    maxX = std::max(maxX, v[k].clip.x * 100);
    maxY = std::max(maxY, v[k].clip.y * 50);
  }
  EXPECT_NEAR(maxX, 6.0f, 1e-4f);
  EXPECT_NEAR(maxY, 6.0f, 1e-4f);
  // An outline adds the same shape 1.5 px larger underneath.
  list.handles.resize(1);
  list.handles[0].outline = {0, 0, 0, 1};
  v.clear();
  OverlayRenderer::appendTriangles(list, Layer::OnTop, glm::mat4(1.0f), {200, 100}, v);
  ASSERT_EQ(v.size(), 12u);
  EXPECT_NEAR(v[1].clip.x * 100, 7.5f, 1e-4f);
  EXPECT_EQ(v[1].color, glm::vec4(0, 0, 0, 1));
}

TEST(OverlayRenderer, ScreenRectanglesMapPixelsToNdc) {
  OverlayDrawList list;
  list.screenRects.push_back({{0, 0}, {200, 100}, {1, 1, 1, 0.1f}});
  list.screenLines.push_back({{50, 50}, {150, 50}, {1, 1, 1, 1}, 2.0f});
  std::vector<OverlayRenderer::Vertex> v;
  OverlayRenderer::appendScreenTriangles(list, {200, 100}, v);
  ASSERT_EQ(v.size(), 12u);
  EXPECT_EQ(glm::vec2(v[0].clip), glm::vec2(-1, 1));  // top left pixel corner
  EXPECT_EQ(glm::vec2(v[2].clip), glm::vec2(1, -1));
  for (size_t k = 6; k < 12; ++k) EXPECT_NEAR(std::abs(v[k].clip.y), 0.02f, 1e-6f);  // 1 px above and below y = 50
}

// Golden: EGL and OSMesa (llvmpipe) each match the committed image and each other. Regenerate
// with tests/render/update_golden.sh, and LOOK at the image before committing it.
const std::string kSoftware =
    "LIBGL_ALWAYS_SOFTWARE=1 MESA_GL_VERSION_OVERRIDE=3.3 ASAN_OPTIONS=${ASAN_OPTIONS:+$ASAN_OPTIONS:}detect_leaks=0 ";

TEST(OverlayRenderer, OverlayFrameMatchesGoldenWithEglAndOsMesa) {
  const Result<Image> reference = loadPng(std::string(KINEMA_SOURCE_DIR) + "/tests/render/golden/overlay_gizmo.png");
  ASSERT_TRUE(reference.ok()) << reference.error();
  const std::string dir = makeTempDir();
  Image images[2];
  const char* backends[2] = {"egl", "osmesa"};
  for (int k = 0; k < 2; ++k) {
    const std::string path = dir + "/" + backends[k] + ".png";
    std::string out, err;
    ASSERT_EQ(runCommand(kSoftware + KINEMA_OVERLAY_SAMPLE + " " + path + " " + backends[k], &out, &err), 0) << err;
    const Result<Image> image = loadPng(path);
    ASSERT_TRUE(image.ok()) << image.error();
    images[k] = image.value();
    const int diff = differingPixels(images[k], reference.value(), 8);
    EXPECT_GE(diff, 0) << "size differs from the reference";
    EXPECT_LE(diff, 320 * 240 / 1000) << backends[k] << ": " << diff << " pixels differ from overlay_gizmo.png";

    // Independent of the golden: the gizmo is drawn where the maths puts it. The Z ring is
    // hovered (pale yellow highlight) and the view ring (light grey) is a 32 px screen circle.
    std::istringstream in(out);
    std::string word;
    glm::vec2 pivot;
    in >> word >> pivot.x >> pivot.y;
    ASSERT_EQ(word, "pivot");
    auto brightNear = [&](glm::vec2 p) {
      for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx) {
          const std::uint8_t* c = images[k].pixel(int(p.x) + dx, int(p.y) + dy);
          if (c[0] > 190 && c[1] > 190 && c[2] > 190) return true;
        }
      return false;
    };
    for (glm::vec2 dir : {glm::vec2(1, 0), glm::vec2(0, -1), glm::vec2(-0.6f, 0.8f)})
      EXPECT_TRUE(brightNear(pivot + dir * 32.0f)) << backends[k] << ": no view ring at 32 px";
  }
  const int diff = differingPixels(images[0], images[1], 8);
  EXPECT_GE(diff, 0);
  EXPECT_LE(diff, 320 * 240 / 1000) << "EGL and OSMesa disagree on " << diff << " pixels";
  std::system(("rm -rf '" + dir + "'").c_str());
}

}  // namespace
}  // namespace kinema::test
