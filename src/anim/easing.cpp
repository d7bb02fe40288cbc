#include "anim/easing.h"
#include "core/math.h"

#include <cmath>

namespace kinema {

namespace {


// The "In" form of each function; Out and InOut are built from it by symmetry.
float easeIn(EasingFunction f, float u, float period) {
  switch (f) {
    case EasingFunction::Sine: return 1.0f - std::cos(u * kPi / 2);
    case EasingFunction::Quad: return u * u;
    case EasingFunction::Cubic: return u * u * u;
    case EasingFunction::Quart: return u * u * u * u;
    case EasingFunction::Quint: return u * u * u * u * u;
    // Penner's expo is 2^(10(u-1)), which is 2^-10 at 0; shifted and scaled to hit 0 and 1.
    case EasingFunction::Expo: return (std::exp2(10.0f * (u - 1.0f)) - 0.0009765625f) / (1.0f - 0.0009765625f);
    case EasingFunction::Circ: return 1.0f - std::sqrt(std::max(0.0f, 1.0f - u * u));
    case EasingFunction::Back: {
      const float s = 1.70158f;
      return u * u * ((s + 1) * u - s);
    }
    case EasingFunction::Bounce: break;  // handled by the caller (defined by its Out form)
    case EasingFunction::Elastic: {
      if (u <= 0.0f) return 0.0f;
      if (u >= 1.0f) return 1.0f;
      const float s = period / 4;
      const float v = u - 1.0f;
      return -std::exp2(10.0f * v) * std::sin((v - s) * (2 * kPi) / period);
    }
  }
  return u;
}

float bounceOut(float u) {
  if (u < 1 / 2.75f) return 7.5625f * u * u;
  if (u < 2 / 2.75f) {
    u -= 1.5f / 2.75f;
    return 7.5625f * u * u + 0.75f;
  }
  if (u < 2.5f / 2.75f) {
    u -= 2.25f / 2.75f;
    return 7.5625f * u * u + 0.9375f;
  }
  u -= 2.625f / 2.75f;
  return 7.5625f * u * u + 0.984375f;
}

float in(EasingFunction f, float u, float period) {
  return f == EasingFunction::Bounce ? 1.0f - bounceOut(1.0f - u) : easeIn(f, u, period);
}

}  // namespace

float ease(EasingFunction f, EasingMode mode, float u) {
  u = std::min(1.0f, std::max(0.0f, u));
  switch (mode) {
    case EasingMode::In: return in(f, u, 0.3f);
    case EasingMode::Out: return 1.0f - in(f, 1.0f - u, 0.3f);
    case EasingMode::InOut:
      // Back's overshoot is scaled by 1.525 in Penner's InOut form, as in Blender.
      if (f == EasingFunction::Back) {
        const float s = 1.70158f * 1.525f;
        const float v = 2 * u;
        if (v < 1) return 0.5f * (v * v * ((s + 1) * v - s));
        const float w = v - 2;
        return 0.5f * (w * w * ((s + 1) * w + s) + 2);
      }
      return u < 0.5f ? 0.5f * in(f, 2 * u, 0.45f) : 1.0f - 0.5f * in(f, 2 - 2 * u, 0.45f);
  }
  return u;
}

}  // namespace kinema
