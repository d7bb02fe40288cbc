// Onion-skin ghosts in the renderer (FrameDescription::ghosts): blended by their alpha over
// what is behind them, and hidden behind the opaque skeleton in front of them.
#include <gtest/gtest.h>

#include "render/headless_renderer.h"

namespace kinema {
namespace {

constexpr int kSize = 160;
const glm::vec4 kBackground(0.2f, 0.2f, 0.2f, 1.0f);

// One bone from (0, 0, z) to (0, 1, z) in `color` (joints too).
SkeletonDrawList bone(float z, const glm::vec4& color) {
  static const std::vector<int> parents{-1, 0};
  const std::vector<glm::mat4> world{glm::translate(glm::mat4(1.0f), glm::vec3(0, 0, z)),
                                     glm::translate(glm::mat4(1.0f), glm::vec3(0, 1, z))};
  SkeletonDrawJob job;
  job.parents = &parents;
  job.world = &world;
  job.style.bone = job.style.joint = color;
  SkeletonDrawList list;
  EXPECT_TRUE(job.run(list));
  return list;
}

glm::ivec3 centre(const Image& img) {
  const std::uint8_t* p = img.pixel(kSize / 2, kSize / 2);
  return {p[0], p[1], p[2]};
}

Image draw(const SkeletonDrawList* skeleton, const std::vector<SkeletonDrawList>* ghosts) {
  auto opened = HeadlessRenderer::open(HeadlessBackend::Egl, kSize, kSize);
  EXPECT_TRUE(opened.ok()) << (opened.ok() ? "" : opened.error());
  if (!opened.ok()) return Image();
  FrameDescription frame;
  frame.skeleton = skeleton;
  frame.ghosts = ghosts;
  frame.showGrid = false;
  frame.background = kBackground;
  frame.camera.azimuthDeg = 0.0f;  // looking along -Z at the bone's middle
  frame.camera.elevationDeg = 0.0f;
  frame.camera.target = glm::vec3(0, 0.5f, 0);
  frame.camera.distance = 4.0f;
  frame.camera.fitClipPlanes(2.0f);
  return opened.value()->render(frame);
}

TEST(GhostRender, AGhostIsBlendedByItsAlphaOverTheBackground) {
  // Pure blue at alpha 0.5: red and green are half the background's whatever the lighting,
  // blue is above it.
  const std::vector<SkeletonDrawList> ghosts{bone(0.0f, glm::vec4(0, 0, 1, 0.5f))};
  const Image img = draw(nullptr, &ghosts);
  ASSERT_EQ(img.width, kSize);
  const glm::ivec3 c = centre(img);
  const int half = int(0.5f * 0.2f * 255.0f + 0.5f);  // 26
  EXPECT_NEAR(c.r, half, 2);
  EXPECT_NEAR(c.g, half, 2);
  EXPECT_GT(c.b, 51 + 10);
  // Without ghosts the same pixel is the background.
  const glm::ivec3 none = centre(draw(nullptr, nullptr));
  EXPECT_NEAR(none.r, 51, 1);
  EXPECT_NEAR(none.b, 51, 1);
}

TEST(GhostRender, TheOpaqueSkeletonInFrontHidesAGhost) {
  const SkeletonDrawList front = bone(0.5f, glm::vec4(1, 0, 0, 1));  // nearer the camera (+Z)
  const std::vector<SkeletonDrawList> behind{bone(-0.5f, glm::vec4(0, 0, 1, 0.5f))};
  const glm::ivec3 c = centre(draw(&front, &behind));
  EXPECT_GT(c.r, 60);
  EXPECT_EQ(c.g, 0);
  EXPECT_EQ(c.b, 0) << "no blue from the ghost behind the bone";
  // The ghost in front of the bone tints it: red halved, blue added.
  const std::vector<SkeletonDrawList> ahead{bone(1.0f, glm::vec4(0, 0, 1, 0.5f))};
  const glm::ivec3 d = centre(draw(&front, &ahead));
  EXPECT_GT(d.b, 10);
  EXPECT_LT(d.r, c.r);
}

}  // namespace
}  // namespace kinema
