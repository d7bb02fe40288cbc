#pragma once

namespace kinema {

// The most control points a free-form-deformation lattice has along one axis (degree 7).
constexpr int kMaxBernsteinDegree = 7;

// The Bernstein polynomials of `degree` (0..kMaxBernsteinDegree) at t:
//   out[i] = C(degree, i) (1 - t)^(degree - i) t^i,  i = 0..degree.
// They sum to 1 and reproduce linear functions (sum_i out[i] * i / degree = t), which is why
// an undisturbed lattice leaves every point where it is. t is normally in [0, 1].
void bernsteinBasis(int degree, float t, float* out);

}  // namespace kinema
