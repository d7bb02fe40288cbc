#include "deform/soft_selection.h"

#include <algorithm>
#include <cmath>

namespace kinema {

const char* toString(Falloff falloff) {
  switch (falloff) {
    case Falloff::Smooth: return "smooth";
    case Falloff::Sphere: return "sphere";
    case Falloff::Root: return "root";
    case Falloff::Sharp: return "sharp";
    case Falloff::Linear: return "linear";
    case Falloff::Constant: return "constant";
  }
  return "smooth";
}

bool fromString(const std::string& s, Falloff& out) {
  for (Falloff f : {Falloff::Smooth, Falloff::Sphere, Falloff::Root, Falloff::Sharp, Falloff::Linear,
                    Falloff::Constant})
    if (s == toString(f)) {
      out = f;
      return true;
    }
  return false;
}

float falloffWeight(Falloff falloff, float distance, float radius) {
  if (!(distance <= radius)) return 0.0f;
  const float x = 1.0f - distance / radius;
  switch (falloff) {
    case Falloff::Smooth: return x * x * (3.0f - 2.0f * x);
    case Falloff::Sphere: return std::sqrt(std::max(0.0f, x * (2.0f - x)));
    case Falloff::Root: return std::sqrt(std::max(0.0f, x));
    case Falloff::Sharp: return x * x;
    case Falloff::Linear: return x;
    case Falloff::Constant: return 1.0f;
  }
  return 0.0f;
}

std::string SoftPull::validate() const {
  if (!isFinite(center) || !isFinite(offset) || !std::isfinite(radius))
    return "soft pull has a value that is not finite";
  if (!(radius > 0.0f)) return "soft pull's radius must be above 0";
  return "";
}

glm::vec3 applySoftPull(const SoftPull& pull, const glm::vec3& p) {
  const float w = falloffWeight(pull.falloff, glm::length(p - pull.center), pull.radius);
  return p + w * pull.offset;
}

}  // namespace kinema
