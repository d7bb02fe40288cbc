// Bones are lit once per face (shaders/faceted.*): every pixel of an octahedron's face has
// the colour the studio light gives that face's normal, worked out here on the CPU from the
// shape's corners (shape_meshes.cpp) and the light's formula (shaded.frag).
#include <gtest/gtest.h>

#include <cmath>

#include "render/headless_renderer.h"

namespace kinema {
namespace KINEMA_UNITY_ID {

constexpr int kSize = 200;

// shaded.frag's light for a view-space normal.
float studioLight(const glm::vec3& n) {
  const glm::vec3 key = glm::normalize(glm::vec3(-0.4f, 0.6f, 0.7f));
  const glm::vec3 fill = glm::normalize(glm::vec3(0.6f, -0.2f, 0.5f));
  return 0.35f + 0.6f * std::max(glm::dot(n, key), 0.0f) + 0.2f * std::max(glm::dot(n, fill), 0.0f);
}

// One white bone from the origin up +Y, turned by `roll` about its own axis, seen from +Z.
Image drawBone(float roll) {
  auto opened = HeadlessRenderer::open(HeadlessBackend::Egl, kSize, kSize);
  EXPECT_TRUE(opened.ok()) << (opened.ok() ? "" : opened.error());
  if (!opened.ok()) return Image();
  SkeletonDrawList list;
  list.boneMatrices.push_back(
      boneMatrix(glm::vec3(0.0f), glm::vec3(0.0f, 1.0f, 0.0f), glm::vec3(std::cos(roll), 0.0f, -std::sin(roll))));
  list.boneColors.push_back(glm::vec4(0.8f, 0.8f, 0.8f, 1.0f));
  FrameDescription frame;
  frame.skeleton = &list;
  frame.showGrid = false;
  frame.background = glm::vec4(0.0f, 0.0f, 0.0f, 1.0f);
  frame.camera.azimuthDeg = 0.0f;  // the eye on +Z, looking along -Z: view space = world turned by nothing
  frame.camera.elevationDeg = 0.0f;
  frame.camera.target = glm::vec3(0.0f, 0.5f, 0.0f);
  frame.camera.distance = 3.0f;
  frame.camera.fitClipPlanes(2.0f);
  return opened.value()->render(frame);
}

TEST(FacetedBones, AFaceHasTheLightOfItsNormalAtEveryPixel) {
  // The upper face between the waist corners (-0.1, 0.1, 0.1) and (0.1, 0.1, 0.1) and the tail
  // (0, 1, 0), wound outward, faces the eye; the bone's roll turns it about +Y. At the image's
  // centre column, from a little above the waist to a little below the tail, that face is seen.
  const glm::vec3 a(-0.1f, 0.1f, 0.1f), b(0.1f, 0.1f, 0.1f), tail(0.0f, 1.0f, 0.0f);
  const glm::vec3 faceNormal = glm::normalize(glm::cross(b - a, tail - a));
  for (float roll : {0.0f, 0.3f, -0.35f}) {  // well inside the face's +-45 degrees: no edge at the centre column
    const Image img = drawBone(roll);
    ASSERT_EQ(img.width, kSize);
    // The roll turns x = (1, 0, 0) into (cos, 0, -sin): a turn by `roll` about +Y.
    const glm::vec3 n = glm::vec3(glm::rotate(glm::mat4(1.0f), roll, glm::vec3(0, 1, 0)) * glm::vec4(faceNormal, 0.0f));
    const int expected = static_cast<int>(std::lround(std::min(0.8f * studioLight(n), 1.0f) * 255.0f));
    int checked = 0;
    for (int y = kSize / 2 - 40; y <= kSize / 2 + 40; y += 10) {
      const std::uint8_t* p = img.pixel(kSize / 2, y);
      EXPECT_NEAR(p[0], expected, 2) << "roll " << roll << ", row " << y;
      EXPECT_EQ(p[0], p[1]);
      EXPECT_EQ(p[1], p[2]);
      ++checked;
    }
    EXPECT_EQ(checked, 9);
  }
}

}  // namespace
}  // namespace kinema
