// Particles drawn by the renderer (render/particle_overlay.h): a particle's colour lands on
// the pixel where a pinhole projection computed here by hand puts it, a quad's width follows
// its size and depth, and a frame without particles has none of their colour.
#include <gtest/gtest.h>

#include <cmath>

#include "render/headless_renderer.h"
#include "render/particle_overlay.h"

namespace kinema {
namespace KINEMA_UNITY_ID {

constexpr int kWidth = 200, kHeight = 160;
const glm::vec4 kMagenta(1.0f, 0.0f, 1.0f, 1.0f);

bool magenta(const std::uint8_t* p) { return p[0] > 200 && p[1] < 60 && p[2] > 200; }

int countMagenta(const Image& img) {
  int n = 0;
  for (int y = 0; y < img.height; ++y)
    for (int x = 0; x < img.width; ++x) n += magenta(img.pixel(x, y));
  return n;
}

// Looking along -Z from (0, 0.5, 4) at (0, 0.5, 0).
OrbitCamera frontCamera() {
  OrbitCamera c;
  c.azimuthDeg = 0.0f;
  c.elevationDeg = 0.0f;
  c.target = glm::vec3(0, 0.5f, 0);
  c.distance = 4.0f;
  c.fitClipPlanes(2.0f);
  return c;
}

// The pixel (column, row from the top) of world point p for that camera: a pinhole with a
// 35° vertical field at depth 4 - z.
glm::vec2 byHand(const glm::vec3& p) {
  const float depth = 4.0f - p.z;
  const float halfH = depth * std::tan(glm::radians(17.5f)), halfW = halfH * kWidth / kHeight;
  return {(p.x / halfW + 1.0f) * 0.5f * kWidth, (1.0f - (p.y - 0.5f) / halfH) * 0.5f * kHeight};
}

Image draw(const ParticleSystemSettings& settings, const ParticleState& state) {
  auto opened = HeadlessRenderer::open(HeadlessBackend::Egl, kWidth, kHeight);
  EXPECT_TRUE(opened.ok()) << (opened.ok() ? "" : opened.error());
  if (!opened.ok()) return Image();
  FrameDescription frame;
  frame.showGrid = false;
  frame.camera = frontCamera();
  OverlayDrawList overlay;
  appendParticles(settings, state, frame.camera, static_cast<float>(kHeight), overlay);
  frame.overlay = &overlay;
  return opened.value()->render(frame);
}

ParticleState at(const std::vector<glm::vec3>& points) {
  ParticleState s;
  for (const glm::vec3& p : points) {
    s.positions.push_back(p);
    s.velocities.emplace_back(0.0f);
    s.ages.push_back(0.0f);
    s.lifetimes.push_back(1.0f);
    s.emitterOf.push_back(0);
  }
  return s;
}

TEST(ParticleRender, AQuadLandsWhereThePinholeProjectionPutsIt) {
  ParticleSystemSettings s;
  s.colour = kMagenta;
  s.size = 0.2f;
  const glm::vec3 p(0.7f, 1.1f, 0.0f);
  const Image img = draw(s, at({p}));
  ASSERT_EQ(img.width, kWidth);
  const glm::vec2 px = byHand(p);
  EXPECT_TRUE(magenta(img.pixel(static_cast<int>(px.x), static_cast<int>(px.y)))) << px.x << ", " << px.y;
  // Its side: 0.2 units at depth 4 is 0.2 / (2 * 4 tan 17.5°) of the height, ~12.7 pixels.
  const float side = 0.2f / (2.0f * 4.0f * std::tan(glm::radians(17.5f))) * kHeight;
  const int n = countMagenta(img);
  EXPECT_NEAR(std::sqrt(static_cast<float>(n)), side, 2.0f) << n << " magenta pixels";
  // Nothing of its colour far from it, nor anywhere without particles.
  EXPECT_FALSE(magenta(img.pixel(kWidth - 1 - static_cast<int>(px.x), static_cast<int>(px.y))));
  EXPECT_EQ(countMagenta(draw(s, ParticleState{})), 0);
}

TEST(ParticleRender, PointsAreDotsOfTheirPixelSizeAndFarQuadsAreSmaller) {
  ParticleSystemSettings s;
  s.colour = kMagenta;
  s.style = ParticleDrawStyle::Points;
  s.size = 8.0f;  // pixels across
  const glm::vec3 near(-0.6f, 0.2f, 1.0f), far(0.6f, 0.2f, -6.0f);
  const Image img = draw(s, at({near, far}));
  for (const glm::vec3& p : {near, far}) {
    const glm::vec2 px = byHand(p);
    EXPECT_TRUE(magenta(img.pixel(static_cast<int>(px.x), static_cast<int>(px.y)))) << p.z;
  }
  // Two discs 8 pixels across: about 2 pi 4^2 pixels.
  EXPECT_NEAR(countMagenta(img), 2.0f * 3.14159f * 16.0f, 25.0f);
  // As quads of one size, the far one (depth 10) is 3/10 the width of the near one (depth 3).
  OrbitCamera c = frontCamera();
  EXPECT_NEAR(particleRadiusPixels(c, near, 0.2f, kHeight) / particleRadiusPixels(c, far, 0.2f, kHeight), 10.0f / 3.0f, 1e-3f);
}

}  // namespace
}  // namespace kinema
