#pragma once
#include "core/math.h"

namespace kinema {

// The cubic Hermite basis on u in [0, 1]: p(u) = h00 p0 + h10 m0 + h01 p1 + h11 m1, with
// m0, m1 the tangents per unit u. (Seed 001 swaps h01 and h10; these are the standard ones.)
struct HermiteBasis {
  float h00, h10, h01, h11;
};

inline HermiteBasis hermiteBasis(float u) {
  const float u2 = u * u, u3 = u2 * u;
  return {2 * u3 - 3 * u2 + 1, u3 - 2 * u2 + u, -2 * u3 + 3 * u2, u3 - u2};
}

// One Hermite segment between keys dt seconds apart, tangents in value per second.
inline glm::vec4 hermite(const glm::vec4& p0, const glm::vec4& m0, const glm::vec4& p1, const glm::vec4& m1,
                         float dt, float u) {
  const HermiteBasis b = hermiteBasis(u);
  return b.h00 * p0 + (b.h10 * dt) * m0 + b.h01 * p1 + (b.h11 * dt) * m1;
}

}  // namespace kinema
