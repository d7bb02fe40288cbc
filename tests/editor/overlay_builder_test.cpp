// The overlay lists the editor builds: gizmo rings, IK target handles, limit shapes, box rectangle.
#include "editor/viewport/overlay_builder.h"
#include "editor/viewport_test_views.h"
#include "test_support.h"

namespace kinema::test {
namespace KINEMA_UNITY_ID {

int countColor(const OverlayDrawList& list, const glm::vec4& color) {
  int n = 0;
  for (const auto& l : list.lines) n += l.color == color;
  return n;
}

// Orthographic from +Z: ring radius 80 px = 8 units. The Z ring faces the viewer: all 64
// segments drawn, every end 80 px from the pivot's pixel. The X and Y rings are edge-on: only
// their front halves (32 segments each). The view ring: 64 segments, 96 px.
TEST(OverlayBuilder, RotateGizmoRingsHaveThePixelRadiiAndFrontHalves) {
  const ViewportView v = handView(true);
  RotateGizmo g;
  OverlayDrawList list;
  const OverlayStyle style;
  addRotateGizmo(list, g, v, GizmoPart::None, style);
  EXPECT_EQ(countColor(list, style.axisX), 32);
  EXPECT_EQ(countColor(list, style.axisY), 32);
  EXPECT_EQ(countColor(list, style.axisZ), 64);
  EXPECT_EQ(countColor(list, style.viewRing), 64);
  for (const auto& l : list.lines) {
    glm::vec2 a, b;
    ASSERT_TRUE(v.project(l.a, a));
    ASSERT_TRUE(v.project(l.b, b));
    if (l.color == style.axisZ) {
      EXPECT_NEAR(glm::length(a - glm::vec2(100, 100)), 80.0f, 1e-3f);
    }
    if (l.color == style.viewRing) {
      EXPECT_NEAR(glm::length(b - glm::vec2(100, 100)), 96.0f, 1e-3f);
    }
    if (l.color == style.axisX || l.color == style.axisY) {
      EXPECT_GE(l.a.z + l.b.z, 0.0f);
    }
    EXPECT_EQ(l.layer, OverlayDrawList::Layer::OnTop);
    EXPECT_EQ(l.widthPixels, style.ringWidthPixels);
  }
  ASSERT_EQ(list.handles.size(), 1u);  // the trackball backdrop
  EXPECT_EQ(list.handles[0].radiusPixels, 80.0f);
  EXPECT_LT(list.handles[0].color.a, 1.0f);

  OverlayDrawList hot;
  addRotateGizmo(hot, g, v, GizmoPart::AxisZ, style);
  EXPECT_EQ(countColor(hot, style.axisZ), 0);
  EXPECT_EQ(countColor(hot, style.highlight), 64);
  for (const auto& l : hot.lines)
    if (l.color == style.highlight) {
      EXPECT_EQ(l.widthPixels, style.highlightWidthPixels);
    }
}

TEST(OverlayBuilder, IkTargetHandleIsADiamondWithADashedLineToTheEffector) {
  OverlayDrawList list;
  const OverlayStyle style;
  addIkTargetHandle(list, {0, 0, 0}, {0, 3, 0}, false, style);
  ASSERT_EQ(list.handles.size(), 1u);
  EXPECT_EQ(list.handles[0].shape, OverlayDrawList::HandleShape::Diamond);
  EXPECT_EQ(list.handles[0].color, style.ikTarget);
  ASSERT_EQ(list.lines.size(), 8u);  // 8 dashes and 7 gaps of 3 / 15 = 0.2 each
  EXPECT_VEC3_NEAR(list.lines.front().a, glm::vec3(0, 0, 0), 1e-6f);
  EXPECT_VEC3_NEAR(list.lines.front().b, glm::vec3(0, 0.2f, 0), 1e-6f);
  EXPECT_VEC3_NEAR(list.lines[1].a, glm::vec3(0, 0.4f, 0), 1e-6f);
  EXPECT_VEC3_NEAR(list.lines.back().b, glm::vec3(0, 3, 0), 1e-5f);
  OverlayDrawList selected;
  addIkTargetHandle(selected, {0, 0, 0}, {0, 3, 0}, true, style);
  EXPECT_EQ(selected.handles[0].color, style.ikTargetSelected);
}

TEST(OverlayBuilder, LimitShapeIsDepthTested) {
  LimitShapeJob job;
  job.limit = JointLimit::cone({0, 1, 0}, 0.6f, -0.3f, 0.3f);
  LimitShape shape;
  ASSERT_TRUE(job.run(shape));
  OverlayDrawList list;
  addLimitShape(list, shape);
  size_t expected = shape.spokes.size() / 2;
  for (const auto& rim : shape.rims) expected += rim.closed ? rim.points.size() : rim.points.size() - 1;
  EXPECT_EQ(list.lines.size(), expected);
  for (const auto& l : list.lines) EXPECT_EQ(l.layer, OverlayDrawList::Layer::Scene);
}

TEST(OverlayBuilder, BoxSelectRectangleIsNormalisedWithADashedBorder) {
  OverlayDrawList list;
  addBoxSelectRectangle(list, {50, 40}, {10, 20});
  ASSERT_EQ(list.screenRects.size(), 1u);
  EXPECT_EQ(list.screenRects[0].min, glm::vec2(10, 20));
  EXPECT_EQ(list.screenRects[0].max, glm::vec2(50, 40));
  // 40 x 20 px with 4 on / 4 off dashes: 5 + 3 + 5 + 3 dashes.
  EXPECT_EQ(list.screenLines.size(), 16u);
  for (const auto& l : list.screenLines) EXPECT_LE(glm::length(l.b - l.a), 4.0f + 1e-5f);
}

}  // namespace
}  // namespace kinema::test
