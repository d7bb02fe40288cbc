// RectClear (render/rect_clear.h): the rectangles, and nothing else, end with the colour and
// depth 1.0, as a scissored glClear of each would leave them; the state it leaves is the one
// its header states.
#include <gtest/gtest.h>

#include <glad/gl.h>

#include "render/gl_context.h"
#include "render/offscreen_target.h"
#include "render/rect_clear.h"

namespace kinema {
namespace KINEMA_UNITY_ID {

constexpr int kW = 64, kH = 48;

struct Cleared {
  Image color;
  std::vector<float> depth;  // rows from the bottom
  GLint depthFunc = 0;
  GLboolean scissor = GL_TRUE, blend = GL_TRUE, depthTest = GL_FALSE;
};

// Filled with red at depth 0.25 (scissor, blend and a GL_EQUAL depth test left on, as a
// frame might leave them), then `rects` cleared to grey.
Cleared clearInto(const std::vector<PixelRect>& rects) {
  Cleared out;
  auto context = createEglContext();
  EXPECT_TRUE(context.ok()) << (context.ok() ? "" : context.error());
  if (!context.ok()) return out;
  OffscreenTarget target;
  EXPECT_EQ(target.create(kW, kH, 0), "");  // one sample, readable as it is
  target.bind();
  glViewport(0, 0, kW, kH);
  glDisable(GL_SCISSOR_TEST);
  glClearColor(1.0f, 0.0f, 0.0f, 1.0f);
  glClearDepth(0.25);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glEnable(GL_SCISSOR_TEST);
  glScissor(0, 0, 1, 1);
  glEnable(GL_BLEND);
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_EQUAL);  // would keep every pixel as it is
  RectClear clear;
  EXPECT_EQ(clear.init(), "");
  clear.clear(rects, kW, kH, glm::vec4(0.5f, 0.5f, 0.5f, 1.0f));
  glGetIntegerv(GL_DEPTH_FUNC, &out.depthFunc);
  out.scissor = glIsEnabled(GL_SCISSOR_TEST);
  out.blend = glIsEnabled(GL_BLEND);
  out.depthTest = glIsEnabled(GL_DEPTH_TEST);
  GLint drawn = 0;
  glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &drawn);
  glBindFramebuffer(GL_READ_FRAMEBUFFER, static_cast<GLuint>(drawn));
  out.depth.assign(kW * kH, -1.0f);
  glReadPixels(0, 0, kW, kH, GL_DEPTH_COMPONENT, GL_FLOAT, out.depth.data());
  out.color = target.read();
  return out;
}

TEST(RectClear, OnlyTheRectanglesTakeTheColourAndTheFarDepth) {
  const std::vector<PixelRect> rects{{3, 4, 20, 9}, {30, 10, 31, 40}, {50, 0, 64, 48}};
  const Cleared c = clearInto(rects);
  ASSERT_EQ(c.color.width, kW);
  int inside = 0;
  for (int y = 0; y < kH; ++y) {  // y: rows from the bottom
    for (int x = 0; x < kW; ++x) {
      bool in = false;
      for (const PixelRect& r : rects) in = in || (x >= r.x0 && x < r.x1 && y >= r.y0 && y < r.y1);
      inside += in;
      const std::uint8_t* p = c.color.pixel(x, kH - 1 - y);  // Image rows from the top
      const float d = c.depth[static_cast<size_t>(y * kW + x)];
      if (in) {
        ASSERT_NEAR(p[0], 128, 1) << x << ", " << y;
        ASSERT_EQ(p[1], p[0]) << x << ", " << y;
        ASSERT_EQ(d, 1.0f) << x << ", " << y;
      } else {
        ASSERT_EQ(p[0], 255) << x << ", " << y;
        ASSERT_EQ(p[1], 0) << x << ", " << y;
        ASSERT_NEAR(d, 0.25f, 1e-6f) << x << ", " << y;
      }
    }
  }
  EXPECT_EQ(inside, 17 * 5 + 1 * 30 + 14 * 48);
  EXPECT_EQ(c.depthFunc, GL_LESS);
  EXPECT_FALSE(c.scissor);
  EXPECT_FALSE(c.blend);
  EXPECT_TRUE(c.depthTest);
}

TEST(RectClear, NoRectanglesChangeNoPixel) {
  const Cleared c = clearInto({{}, {5, 5, 5, 9}});
  ASSERT_EQ(c.color.width, kW);
  for (int y = 0; y < kH; ++y)
    for (int x = 0; x < kW; ++x) {
      ASSERT_EQ(c.color.pixel(x, y)[0], 255);
      ASSERT_NEAR(c.depth[static_cast<size_t>(y * kW + x)], 0.25f, 1e-6f);
    }
  EXPECT_EQ(c.depthFunc, GL_LESS);
}

}  // namespace
}  // namespace kinema
