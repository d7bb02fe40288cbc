#pragma once
#include <cmath>
#include <vector>

#include "anim/clip.h"
#include "anim/sampling.h"

namespace kinema::test {

// A scalar-valued channel (values.x) keyed with one interpolation on every key.
inline Channel scalarChannel(const std::vector<float>& times, const std::vector<float>& values,
                             Interpolation interpolation) {
  Channel c;
  c.joint = -1;
  c.target = ChannelTarget::Scalar;
  c.interpolation = interpolation;
  c.times = times;
  for (float v : values) c.values.emplace_back(v, 0.0f, 0.0f, 0.0f);
  KeySettings s;
  s.interpolation = interpolation;
  c.keys.assign(times.size(), s);
  return c;
}

inline double valueAt(const Channel& c, double t) { return sampleChannel(c, static_cast<float>(t)).x; }

// One-sided derivatives by second-order differences over h (samples are floats, so h is
// not tiny: the truncation error is O(h^2), the rounding error O(1e-7 / h)).
inline double leftSlope(const Channel& c, double t, double h = 2e-3) {
  return (3 * valueAt(c, t) - 4 * valueAt(c, t - h) + valueAt(c, t - 2 * h)) / (2 * h);
}
inline double rightSlope(const Channel& c, double t, double h = 2e-3) {
  return (-3 * valueAt(c, t) + 4 * valueAt(c, t + h) - valueAt(c, t + 2 * h)) / (2 * h);
}

}  // namespace kinema::test
