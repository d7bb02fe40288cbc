// Orbit camera and framing math (no GL context needed).
#include <glm/gtc/matrix_transform.hpp>

#include <cmath>

#include "render/camera.h"
#include "test_support.h"

namespace kinema::test {
namespace KINEMA_UNITY_ID {

TEST(OrbitCamera, AnglesPlaceTheEyeWhereTheConventionSays) {
  OrbitCamera c;
  c.target = {1, 2, 3};
  c.distance = 4;
  c.azimuthDeg = 0;
  c.elevationDeg = 0;
  EXPECT_VEC3_NEAR(c.eye(), glm::vec3(1, 2, 7), 1e-5f);  // in front, on +Z
  c.azimuthDeg = 90;
  EXPECT_VEC3_NEAR(c.eye(), glm::vec3(5, 2, 3), 1e-5f);  // on +X
  c.azimuthDeg = 0;
  c.elevationDeg = 90;
  EXPECT_VEC3_NEAR(c.eye(), glm::vec3(1, 6, 3), 1e-5f);  // straight above
  c.elevationDeg = 30;  // sin 30 = 1/2, cos 30 = sqrt(3)/2
  EXPECT_VEC3_NEAR(c.eye(), glm::vec3(1, 2 + 2, 3 + 4 * std::sqrt(3.0f) / 2), 1e-5f);
}

TEST(OrbitCamera, ViewMapsTargetToTheScreenCentreAndKeepsUpUp) {
  OrbitCamera c;
  c.target = {0.5f, 1, -2};
  c.distance = 3;
  for (float el : {-60.0f, 0.0f, 45.0f, 90.0f, -90.0f}) {
    c.elevationDeg = el;
    const glm::vec4 t = c.view() * glm::vec4(c.target, 1);
    EXPECT_NEAR(t.x, 0, 1e-5f);
    EXPECT_NEAR(t.y, 0, 1e-5f);
    EXPECT_NEAR(t.z, -3, 1e-5f);  // GL looks down -Z
  }
  c.elevationDeg = 20;
  const glm::vec4 above = c.view() * glm::vec4(c.target + glm::vec3(0, 1, 0), 1);
  EXPECT_GT(above.y, 0.5f);  // world up appears up on screen
}

TEST(OrbitCamera, FrameFitsEveryCornerOfTheBoundsInsideTheView) {
  for (float aspect : {0.5f, 1.0f, 16.0f / 9.0f}) {
    for (float az : {0.0f, 37.0f, 200.0f}) {
      Bounds b;
      b.add({-0.4f, 0.0f, -0.1f});
      b.add({0.9f, 1.8f, 0.3f});
      OrbitCamera c;
      c.azimuthDeg = az;
      c.elevationDeg = 15;
      c.frame(b, aspect);
      EXPECT_TRUE(c.validate().empty()) << c.validate();
      EXPECT_VEC3_NEAR(c.target, glm::vec3(0.25f, 0.9f, 0.1f), 1e-6f);
      const glm::mat4 vp = c.projection(aspect) * c.view();
      float widest = 0;
      for (int k = 0; k < 8; ++k) {
        const glm::vec3 p((k & 1) ? b.max.x : b.min.x, (k & 2) ? b.max.y : b.min.y, (k & 4) ? b.max.z : b.min.z);
        const glm::vec4 clip = vp * glm::vec4(p, 1);
        const glm::vec3 ndc = glm::vec3(clip) / clip.w;
        EXPECT_LT(std::abs(ndc.x), 1.0f);
        EXPECT_LT(std::abs(ndc.y), 1.0f);
        EXPECT_GT(ndc.z, -1.0f);  // between the clip planes
        EXPECT_LT(ndc.z, 1.0f);
        widest = std::max({widest, std::abs(ndc.x), std::abs(ndc.y)});
      }
      EXPECT_GT(widest, 0.4f) << "framing should fill the view, not leave the skeleton tiny";
    }
  }
}

TEST(OrbitCamera, FramingDistanceIsTheClosedFormForASphere) {
  // Bounds of a cube of side 2: radius sqrt(3). Square view, fov 35: the sphere must subtend
  // fill * 17.5 degrees, i.e. d = sqrt(3) / sin(0.85 * 17.5 deg).
  Bounds b;
  b.add({-1, -1, -1});
  b.add({1, 1, 1});
  OrbitCamera c;
  c.frame(b, 1.0f, 0.85f);
  const double expected = std::sqrt(3.0) / std::sin(0.85 * 17.5 * 3.14159265358979 / 180.0);
  EXPECT_NEAR(c.distance, expected, 1e-4);
}

TEST(SteadySceneRadius, RoundsUpToAPowerOfOneAndAQuarterAndHoldsThroughSmallMoves) {
  for (float r : {0.01f, 0.3f, 0.95f, 1.0f, 1.7f, 12.0f, 480.0f}) {
    const float s = steadySceneRadius(r);
    EXPECT_GE(s, r * (1.0f - 1e-6f)) << r;
    EXPECT_LT(s, r * 1.25f * (1.0f + 1e-6f)) << r;
    const double k = std::log(double(s)) / std::log(1.25);  // a whole power of 1.25
    EXPECT_NEAR(k, std::round(k), 1e-4) << r;
  }
  // A pose that moves a little keeps the radius (unless it crosses a step).
  EXPECT_EQ(steadySceneRadius(1.10f), steadySceneRadius(1.12f));
  EXPECT_EQ(steadySceneRadius(0.0f), 1e-3f);
  EXPECT_EQ(steadySceneRadius(std::nanf("")), 1e-3f);
}

TEST(GridCellSize, StepsAreOneTwoAndAHalfOrFiveTimesAPowerOfTen) {
  EXPECT_FLOAT_EQ(gridCellSize(1.0f), 0.25f);    // a 2-unit person: quarter-unit cells
  EXPECT_FLOAT_EQ(gridCellSize(100.0f), 25.0f);  // the same in centimetres
  for (float r : {0.01f, 0.3f, 7.0f, 1234.0f}) {
    const float cell = gridCellSize(r);
    const float mantissa = cell / std::pow(10.0f, std::floor(std::log10(cell) + 1e-6f));
    EXPECT_TRUE(std::abs(mantissa - 1) < 1e-4 || std::abs(mantissa - 2.5f) < 1e-4 || std::abs(mantissa - 5) < 1e-4)
        << r << " -> " << cell;
    EXPECT_GT(2 * r / cell, 3.0f);
    EXPECT_LT(2 * r / cell, 20.0f);
  }
  EXPECT_FLOAT_EQ(gridCellSize(std::nanf("")), 1.0f);
}

}  // namespace
}  // namespace kinema::test
