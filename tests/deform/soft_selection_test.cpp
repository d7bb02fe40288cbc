// Soft-selection pulls: the picked point moves by the whole offset, a point at the radius by
// the falloff's value there, points beyond not at all; each falloff against its formula.
#include "deform/soft_selection.h"

#include <gtest/gtest.h>

#include <cmath>

#include "test_support.h"

namespace kinema {
namespace KINEMA_UNITY_ID {

TEST(SoftSelection, FalloffsAtTheCentreHalfwayAndTheRadius) {
  struct Case {
    Falloff f;
    float half;   // value at x = 1 - d/r = 0.5
    float edge;   // value at the radius (x = 0)
  };
  const Case cases[] = {{Falloff::Smooth, 0.5f, 0.0f},           {Falloff::Sphere, std::sqrt(0.75f), 0.0f},
                        {Falloff::Root, std::sqrt(0.5f), 0.0f},  {Falloff::Sharp, 0.25f, 0.0f},
                        {Falloff::Linear, 0.5f, 0.0f},           {Falloff::Constant, 1.0f, 1.0f}};
  for (const Case& c : cases) {
    EXPECT_FLOAT_EQ(falloffWeight(c.f, 0.0f, 2.0f), 1.0f) << toString(c.f);
    EXPECT_NEAR(falloffWeight(c.f, 1.0f, 2.0f), c.half, 1e-6f) << toString(c.f);
    EXPECT_NEAR(falloffWeight(c.f, 2.0f, 2.0f), c.edge, 1e-6f) << toString(c.f);
    EXPECT_EQ(falloffWeight(c.f, 2.001f, 2.0f), 0.0f) << toString(c.f);
    Falloff back;
    ASSERT_TRUE(fromString(toString(c.f), back));
    EXPECT_EQ(back, c.f);
  }
  // Smooth is 3x^2 - 2x^3 of x = 1 - d/r everywhere, and never increases with distance.
  float previous = 1.0f;
  for (int i = 0; i <= 100; ++i) {
    const float d = 0.03f * i, x = 1.0f - d / 3.0f;
    const float w = falloffWeight(Falloff::Smooth, d, 3.0f);
    EXPECT_NEAR(w, 3 * x * x - 2 * x * x * x, 1e-6f);
    EXPECT_LE(w, previous + 1e-7f);
    previous = w;
  }
}

TEST(SoftSelection, ThePickedPointMovesByTheOffsetItsNeighboursByTheFalloff) {
  SoftPull pull;
  pull.center = glm::vec3(1, 2, 3);
  pull.offset = glm::vec3(0.2f, -0.1f, 0.4f);
  pull.radius = 0.5f;
  pull.falloff = Falloff::Sharp;
  ASSERT_EQ(pull.validate(), "");
  EXPECT_VEC3_NEAR(applySoftPull(pull, pull.center), pull.center + pull.offset, 1e-6f);
  const glm::vec3 atRadius = pull.center + glm::vec3(0, 0.5f, 0);
  EXPECT_VEC3_NEAR(applySoftPull(pull, atRadius), atRadius, 1e-6f);  // sharp: 0 at the radius
  const glm::vec3 quarter = pull.center + glm::normalize(glm::vec3(1, 1, 0)) * 0.125f;  // x = 0.75
  EXPECT_VEC3_NEAR(applySoftPull(pull, quarter), quarter + 0.5625f * pull.offset, 1e-6f);
  pull.falloff = Falloff::Constant;
  EXPECT_VEC3_NEAR(applySoftPull(pull, atRadius), atRadius + pull.offset, 1e-6f);
  pull.radius = 0.0f;
  EXPECT_NE(pull.validate().find("radius"), std::string::npos);
}

}  // namespace
}  // namespace kinema
