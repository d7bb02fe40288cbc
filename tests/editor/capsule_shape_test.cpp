// The collision capsule's wireframe (issue 23): every drawn point lies on the capsule's
// surface, at the radius from its segment, and the caps reach past its ends.
#include <gtest/gtest.h>

#include "editor/viewport/capsule_shape.h"

namespace kinema {
namespace KINEMA_UNITY_ID {

float segmentDistance(const glm::vec3& p, const glm::vec3& a, const glm::vec3& b) {
  const glm::vec3 d = b - a;
  const float dd = glm::dot(d, d);
  const float t = dd > 0.0f ? glm::clamp(glm::dot(p - a, d) / dd, 0.0f, 1.0f) : 0.0f;
  return glm::length(p - (a + t * d));
}

TEST(CapsuleShape, EveryPointIsOnTheSurfaceAndTheCapsReachPastTheEnds) {
  const glm::vec3 a(0.3f, -1.0f, 2.0f), b(1.3f, 0.5f, 2.5f);
  const float r = 0.25f;
  const CapsuleWire wire = capsuleWire(a, b, r, 16);
  ASSERT_EQ(wire.polylines.size(), 2u + 4u + 4u);  // two rings, four sides, two caps at each end
  const glm::vec3 axis = glm::normalize(b - a);
  float before = 0.0f, after = 0.0f;
  for (const std::vector<glm::vec3>& line : wire.polylines)
    for (const glm::vec3& p : line) {
      EXPECT_NEAR(segmentDistance(p, a, b), r, 1e-5f);
      before = std::max(before, glm::dot(a - p, axis));
      after = std::max(after, glm::dot(p - b, axis));
    }
  EXPECT_NEAR(before, r, 1e-5f);  // the caps' tips: a radius beyond each end
  EXPECT_NEAR(after, r, 1e-5f);
  EXPECT_EQ(wire.polylines[0].size(), 17u);  // a closed ring repeats its first point
  EXPECT_NEAR(glm::distance(wire.polylines[0].front(), wire.polylines[0].back()), 0.0f, 1e-5f);
}

TEST(CapsuleShape, APointCapsuleIsASphereAndNoRadiusDrawsNothing) {
  const glm::vec3 c(1.0f, 2.0f, 3.0f);
  const CapsuleWire sphere = capsuleWire(c, c, 0.5f);
  ASSERT_EQ(sphere.polylines.size(), 3u);
  for (const std::vector<glm::vec3>& line : sphere.polylines)
    for (const glm::vec3& p : line) EXPECT_NEAR(glm::distance(p, c), 0.5f, 1e-5f);
  EXPECT_TRUE(capsuleWire(c, c + glm::vec3(1.0f), 0.0f).polylines.empty());
}

}  // namespace
}  // namespace kinema
