#include "deform/bernstein.h"

namespace kinema {

void bernsteinBasis(int degree, float t, float* out) {
  // De Casteljau's triangle on the basis itself: each row splits every weight between its
  // two children, so the weights stay non-negative and sum to 1 in float for t in [0, 1]
  // (no binomials or powers that lose digits near the ends).
  const float s = 1.0f - t;
  out[0] = 1.0f;
  for (int n = 1; n <= degree; ++n) {
    float carried = 0.0f;
    for (int i = 0; i < n; ++i) {
      const float w = out[i];
      out[i] = carried + s * w;
      carried = t * w;
    }
    out[n] = carried;
  }
}

}  // namespace kinema
