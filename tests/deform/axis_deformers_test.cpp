// Barr's bend, twist and taper against their closed forms: twist turns a point at height h by
// theta*h/H, taper scales by the factor, bend keeps lengths along the axis (an arc of radius
// H/theta), each leaves the region below its range alone.
#include "deform/axis_deformers.h"

#include <gtest/gtest.h>

#include <cmath>

#include "test_support.h"

namespace kinema {
namespace KINEMA_UNITY_ID {

constexpr float kPi = 3.14159265358979f;

AxisDeformer make(AxisDeformerKind kind, DeformAxis axis, float amount) {
  AxisDeformer d;
  d.kind = kind;
  d.axis = axis;
  d.origin = glm::vec3(0.5f, -1.0f, 2.0f);
  d.low = 0.2f;
  d.high = 1.8f;  // H = 1.6
  d.amount = amount;
  return d;
}

TEST(AxisDeformers, TwistTurnsAPointAtHeightHByThetaHOverH) {
  for (DeformAxis axis : {DeformAxis::X, DeformAxis::Y, DeformAxis::Z}) {
    const AxisDeformer d = make(AxisDeformerKind::Twist, axis, 1.3f);
    ASSERT_EQ(d.validate(), "");
    const int ia = static_cast<int>(axis), ib = (ia + 1) % 3, ic = (ia + 2) % 3;
    for (float a : {-0.5f, 0.2f, 0.6f, 1.0f, 1.8f, 2.5f}) {
      glm::vec3 local(0.0f);
      local[ia] = a;
      local[ib] = 0.3f;
      local[ic] = -0.1f;
      const glm::vec3 out = applyAxisDeformer(d, d.origin + local) - d.origin;
      const float h = std::fmin(std::fmax(a - 0.2f, 0.0f), 1.6f);
      const float expected = 1.3f * h / 1.6f;
      // The angle turned about the axis, measured from (b, c) to (b', c').
      const float turned = std::atan2(out[ic], out[ib]) - std::atan2(-0.1f, 0.3f);
      EXPECT_NEAR(turned, expected, 1e-5f) << "axis " << toString(axis) << " a=" << a;
      EXPECT_NEAR(out[ia], a, 1e-6f);
      EXPECT_NEAR(std::hypot(out[ib], out[ic]), std::hypot(0.3f, -0.1f), 1e-6f);
    }
  }
}

TEST(AxisDeformers, TaperScalesByTheFactor) {
  const AxisDeformer d = make(AxisDeformerKind::Taper, DeformAxis::Y, 0.25f);
  for (float a : {-1.0f, 0.2f, 1.0f, 1.8f, 3.0f}) {
    const glm::vec3 p = d.origin + glm::vec3(0.4f, a, -0.6f);  // b = z, c = x for axis Y
    const glm::vec3 out = applyAxisDeformer(d, p) - d.origin;
    const float f = std::fmin(std::fmax(a - 0.2f, 0.0f), 1.6f) / 1.6f;
    const float scale = 1.0f + (0.25f - 1.0f) * f;
    EXPECT_NEAR(out.x, 0.4f * scale, 1e-6f) << a;
    EXPECT_NEAR(out.z, -0.6f * scale, 1e-6f) << a;
    EXPECT_NEAR(out.y, a, 1e-6f);
  }
}

// The centre line of the range becomes an arc of radius H / angle: walking along it in small
// steps covers the same length as before, the end lands where the circle says, and the end
// tangent is turned by the angle.
TEST(AxisDeformers, BendKeepsLengthsAlongTheAxis) {
  for (float angle : {0.3f, kPi / 2, kPi, -2.0f, 1e-6f}) {
    const AxisDeformer d = make(AxisDeformerKind::Bend, DeformAxis::Z, angle);  // turns Z towards X
    const int steps = 2000;
    double length = 0.0;
    glm::vec3 prev = applyAxisDeformer(d, d.origin + glm::vec3(0, 0, d.low));
    for (int i = 1; i <= steps; ++i) {
      const float a = d.low + (d.high - d.low) * i / steps;
      const glm::vec3 cur = applyAxisDeformer(d, d.origin + glm::vec3(0, 0, a));
      length += glm::length(glm::dvec3(cur - prev));
      prev = cur;
    }
    EXPECT_NEAR(length, 1.6, 1e-4) << "angle " << angle;
    // End of the arc: (1 - cos) R along X, sin R along Z from the start, R = H / angle.
    const double r = 1.6 / angle;
    const glm::vec3 end = prev - d.origin;
    EXPECT_NEAR(end.x, (1.0 - std::cos(angle)) * r, 2e-5) << angle;
    EXPECT_NEAR(end.z, d.low + std::sin(angle) * r, 2e-5) << angle;
    // Past the range: rigid continuation along the end tangent (sin, cos) in (X, Z).
    const glm::vec3 beyond = applyAxisDeformer(d, d.origin + glm::vec3(0, 0, d.high + 0.5f)) - d.origin;
    EXPECT_NEAR(beyond.x, end.x + 0.5 * std::sin(angle), 2e-5);
    EXPECT_NEAR(beyond.z, end.z + 0.5 * std::cos(angle), 2e-5);
    // Below the range nothing moves; the Y coordinate never does.
    const glm::vec3 below(0.7f, 0.2f, d.low - 0.3f);
    EXPECT_VEC3_NEAR(applyAxisDeformer(d, d.origin + below) - d.origin, below, 1e-6f);
    EXPECT_NEAR(applyAxisDeformer(d, d.origin + glm::vec3(0.1f, 0.9f, 1.0f)).y - d.origin.y, 0.9f, 1e-6f);
  }
}

// Off the centre line a bend is still a rigid turn of each cross-section: a point at offset b
// lies on a circle of radius R - b, and its distance to the centre line's image stays |b|.
TEST(AxisDeformers, BendTurnsCrossSectionsRigidly) {
  const AxisDeformer d = make(AxisDeformerKind::Bend, DeformAxis::X, 1.1f);  // X turns towards Y
  for (float a : {0.3f, 0.9f, 1.7f})
    for (float b : {-0.2f, 0.15f}) {
      const glm::vec3 onLine = applyAxisDeformer(d, d.origin + glm::vec3(a, 0, 0.05f));
      const glm::vec3 off = applyAxisDeformer(d, d.origin + glm::vec3(a, b, 0.05f));
      EXPECT_NEAR(glm::length(off - onLine), std::abs(b), 1e-5f);
    }
}

TEST(AxisDeformers, NamesAndBadValues) {
  AxisDeformerKind k;
  DeformAxis a;
  EXPECT_TRUE(fromString("taper", k));
  EXPECT_EQ(k, AxisDeformerKind::Taper);
  EXPECT_TRUE(fromString("z", a));
  EXPECT_EQ(a, DeformAxis::Z);
  EXPECT_FALSE(fromString("wobble", k));
  AxisDeformer d = make(AxisDeformerKind::Bend, DeformAxis::Y, 1.0f);
  d.high = d.low;
  EXPECT_NE(d.validate().find("range"), std::string::npos);
  d = make(AxisDeformerKind::Twist, DeformAxis::Y, std::nanf(""));
  EXPECT_NE(d.validate().find("finite"), std::string::npos);
}

}  // namespace
}  // namespace kinema
