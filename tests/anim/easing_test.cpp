// Easing presets: values worked out by hand from Penner's equations (comments).
#include <gtest/gtest.h>

#include <cmath>

#include "anim/easing.h"

namespace kinema {
namespace KINEMA_UNITY_ID {

const EasingFunction kAll[] = {EasingFunction::Sine, EasingFunction::Quad, EasingFunction::Cubic,
                               EasingFunction::Quart, EasingFunction::Quint, EasingFunction::Expo,
                               EasingFunction::Circ, EasingFunction::Back, EasingFunction::Bounce,
                               EasingFunction::Elastic};

TEST(Easing, StartsAtZeroEndsAtOneAndOutMirrorsIn) {
  for (EasingFunction f : kAll)
    for (EasingMode m : {EasingMode::In, EasingMode::Out, EasingMode::InOut}) {
      EXPECT_NEAR(ease(f, m, 0.0f), 0.0f, 1e-6f) << toString(f) << " " << toString(m);
      EXPECT_NEAR(ease(f, m, 1.0f), 1.0f, 1e-6f) << toString(f) << " " << toString(m);
    }
  for (EasingFunction f : kAll) {
    for (float u : {0.1f, 0.33f, 0.6f, 0.9f})
      EXPECT_NEAR(ease(f, EasingMode::Out, u), 1.0f - ease(f, EasingMode::In, 1.0f - u), 1e-6f) << toString(f);
    EXPECT_NEAR(ease(f, EasingMode::InOut, 0.5f), 0.5f, 1e-5f) << toString(f);
  }
}

TEST(Easing, KnownValues) {
  EXPECT_NEAR(ease(EasingFunction::Sine, EasingMode::In, 0.5f), 1 - std::cos(M_PI / 4), 1e-6);   // 0.292893
  EXPECT_NEAR(ease(EasingFunction::Sine, EasingMode::Out, 0.5f), std::sin(M_PI / 4), 1e-6);      // 0.707107
  EXPECT_NEAR(ease(EasingFunction::Sine, EasingMode::InOut, 0.25f), (1 - std::cos(M_PI / 4)) / 2, 1e-6);
  EXPECT_NEAR(ease(EasingFunction::Quad, EasingMode::In, 0.5f), 0.25, 1e-7);
  EXPECT_NEAR(ease(EasingFunction::Quad, EasingMode::Out, 0.5f), 0.75, 1e-7);
  EXPECT_NEAR(ease(EasingFunction::Cubic, EasingMode::InOut, 0.25f), 0.0625, 1e-7);  // 0.5 * 0.5^3
  EXPECT_NEAR(ease(EasingFunction::Quart, EasingMode::In, 0.5f), 0.0625, 1e-7);
  EXPECT_NEAR(ease(EasingFunction::Quint, EasingMode::In, 0.5f), 0.03125, 1e-7);
  EXPECT_NEAR(ease(EasingFunction::Circ, EasingMode::In, 0.5f), 1 - std::sqrt(0.75), 1e-6);  // 0.133975
  // Expo, shifted to hit 0 exactly: (2^-5 - 2^-10) / (1 - 2^-10) = 0.030303.
  EXPECT_NEAR(ease(EasingFunction::Expo, EasingMode::In, 0.5f), (1.0 / 32 - 1.0 / 1024) / (1 - 1.0 / 1024), 1e-6);
  // Back-in: u^2 ((s+1) u - s), s = 1.70158: 0.25 * (1.35079 - 1.70158) = -0.0876975.
  EXPECT_NEAR(ease(EasingFunction::Back, EasingMode::In, 0.5f), -0.0876975, 1e-6);
  // Bounce-out: the first bounce lands at u = 1/2.75; at u = 0.5, 7.5625 (0.5 - 1.5/2.75)^2 + 0.75.
  EXPECT_NEAR(ease(EasingFunction::Bounce, EasingMode::Out, 1 / 2.75f), 1.0, 1e-6);
  EXPECT_NEAR(ease(EasingFunction::Bounce, EasingMode::Out, 0.5f), 7.5625 * std::pow(0.5 - 1.5 / 2.75, 2) + 0.75, 1e-6);
}

TEST(Easing, OvershootingPresetsOvershoot) {
  float backMin = 1, elasticMax = 0;
  for (int i = 0; i <= 100; ++i) {
    backMin = std::min(backMin, ease(EasingFunction::Back, EasingMode::In, i / 100.0f));
    elasticMax = std::max(elasticMax, ease(EasingFunction::Elastic, EasingMode::Out, i / 100.0f));
  }
  EXPECT_LT(backMin, -0.09f);  // about -0.1002 at u = 2s / (3 (s + 1))
  EXPECT_GT(elasticMax, 1.2f);
  for (int i = 0; i <= 100; ++i) {
    const float u = i / 100.0f;
    EXPECT_GE(ease(EasingFunction::Bounce, EasingMode::Out, u), -1e-6f);
    EXPECT_LE(ease(EasingFunction::Bounce, EasingMode::Out, u), 1.0f + 1e-6f);
  }
}

}  // namespace
}  // namespace kinema
