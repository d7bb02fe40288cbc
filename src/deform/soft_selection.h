#pragma once
#include <string>

#include "core/math.h"

namespace kinema {

// Proportional-editing falloffs (Blender's set, less Random and Inverse Square). With
// x = 1 - distance / radius in [0, 1] (1 at the centre, 0 at the radius):
//   Smooth 3x^2 - 2x^3, Sphere sqrt(2x - x^2), Root sqrt(x), Sharp x^2, Linear x, Constant 1.
enum class Falloff { Smooth, Sphere, Root, Sharp, Linear, Constant };

const char* toString(Falloff falloff);
bool fromString(const std::string& s, Falloff& out);

// The weight of a point `distance` from the centre (metres): the falloff of 1 - d/r for
// d <= radius, 0 beyond; 1 at the centre. radius > 0.
float falloffWeight(Falloff falloff, float distance, float radius);

// A soft-selection pull (the seed's "seed vertex"): the picked point moves by `offset` and
// its neighbourhood follows by falloffWeight of its straight-line distance to `center`
// (where the picked vertex was when it was picked, in the deformer's space). The offset is
// what gets keyed.
struct SoftPull {
  glm::vec3 center{0.0f};
  glm::vec3 offset{0.0f};
  float radius = 0.1f;  // metres, > 0
  Falloff falloff = Falloff::Smooth;

  std::string validate() const;
};

glm::vec3 applySoftPull(const SoftPull& pull, const glm::vec3& p);

}  // namespace kinema
