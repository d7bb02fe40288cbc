// Numpad views, orthographic toggle and frame selected over OrbitCamera.
#include "editor/viewport/viewport_controller.h"
#include "editor/viewport_test_views.h"
#include "test_support.h"

namespace kinema::test {
namespace KINEMA_UNITY_ID {

TEST(ViewPresets, NumpadViewsLookFromTheirSides) {
  OrbitCamera c;
  c.target = {1, 2, 3};
  c.distance = 4;
  const struct {
    ViewPreset preset;
    glm::vec3 eyeOffset;
  } cases[] = {{ViewPreset::Front, {0, 0, 4}}, {ViewPreset::Back, {0, 0, -4}}, {ViewPreset::Right, {4, 0, 0}},
               {ViewPreset::Left, {-4, 0, 0}}, {ViewPreset::Top, {0, 4, 0}},  {ViewPreset::Bottom, {0, -4, 0}}};
  for (const auto& k : cases) {
    applyViewPreset(c, k.preset);
    EXPECT_VEC3_NEAR(c.eye() - c.target, k.eyeOffset, 1e-5f);
    EXPECT_VEC3_NEAR(c.target, glm::vec3(1, 2, 3), 0.0f);
    EXPECT_EQ(c.distance, 4.0f);
  }
}

// Blender's top view shows the character's front (+Z here, -Y in Blender) at the bottom of the
// screen: screen-up is -Z. Just short of the pole the camera's up is the same (no flip).
TEST(ViewPresets, TopAndBottomViewsKeepScreenUpContinuous) {
  OrbitCamera c = handCamera(false);
  applyViewPreset(c, ViewPreset::Top);
  EXPECT_VEC3_NEAR(ViewportView::of(c, {200, 200}).up(), glm::vec3(0, 0, -1), 1e-5f);
  c.elevationDeg = 89.0f;  // outside the straight-down branch of OrbitCamera::view
  EXPECT_LT(ViewportView::of(c, {200, 200}).up().z, -0.99f);
  applyViewPreset(c, ViewPreset::Bottom);
  EXPECT_VEC3_NEAR(ViewportView::of(c, {200, 200}).up(), glm::vec3(0, 0, 1), 1e-5f);
  c.elevationDeg = -89.0f;
  EXPECT_GT(ViewportView::of(c, {200, 200}).up().z, 0.99f);
  applyViewPreset(c, ViewPreset::Front);
  EXPECT_VEC3_NEAR(ViewportView::of(c, {200, 200}).right(), glm::vec3(1, 0, 0), 1e-6f);
}

// fov 90 at distance 10: the target's plane is 20 units high in both projections, so (5, 0, 0)
// lands half-way to the right edge either way; nearer points differ only in perspective.
TEST(ViewPresets, OrthographicToggleKeepsTheFramingAtTheTarget) {
  OrbitCamera c = handCamera(false);
  toggleOrthographic(c);
  EXPECT_TRUE(c.orthographic);
  for (bool ortho : {false, true}) {
    c.orthographic = ortho;
    const glm::vec4 clip = c.projection(1.0f) * c.view() * glm::vec4(5, 0, 0, 1);
    EXPECT_NEAR(clip.x / clip.w, 0.5f, 1e-5f) << ortho;
    const glm::vec4 near = c.projection(1.0f) * c.view() * glm::vec4(5, 0, 5, 1);
    EXPECT_NEAR(near.x / near.w, ortho ? 0.5f : 1.0f, 1e-5f) << ortho;
  }
  toggleOrthographic(c);
  EXPECT_FALSE(c.orthographic);
  EXPECT_NEAR(c.unitsPerPixelAtTarget(200), 0.1f, 1e-6f);
}

TEST(ViewPresets, FrameSelectedFitsTheSelectionWithAMinimumSize) {
  std::vector<glm::mat4> world(3, glm::mat4(1.0f));
  world[1][3] = glm::vec4(0, 2, 0, 1);
  world[2][3] = glm::vec4(0, 4, 0, 1);
  OrbitCamera c;  // fov 35, aspect 1: the sphere fills 0.85 of the 17.5 degree half-field
  const float s = std::sin(glm::radians(17.5f) * 0.85f);
  frameSelected(c, world, {1}, 1.0f, 0.5f);  // one joint: grown to radius 0.5
  EXPECT_VEC3_NEAR(c.target, glm::vec3(0, 2, 0), 1e-6f);
  EXPECT_NEAR(c.distance, 0.5f / s, 1e-4f);
  frameSelected(c, world, {0, 2}, 1.0f, 0.5f);  // radius 2 around (0, 2, 0)
  EXPECT_VEC3_NEAR(c.target, glm::vec3(0, 2, 0), 1e-6f);
  EXPECT_NEAR(c.distance, 2.0f / s, 1e-4f);
  world[2][3] = glm::vec4(0, 6, 0, 1);
  frameSelected(c, world, {}, 1.0f, 0.5f);  // nothing selected: all joints, radius 3
  EXPECT_VEC3_NEAR(c.target, glm::vec3(0, 3, 0), 1e-6f);
  EXPECT_NEAR(c.distance, 3.0f / s, 1e-4f);
  frameSelected(c, world, {7, -1}, 1.0f, 0.5f);  // stale indices are ignored
  EXPECT_NEAR(c.distance, 3.0f / s, 1e-4f);
}

}  // namespace
}  // namespace kinema::test
