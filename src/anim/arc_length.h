#pragma once
#include <vector>

#include "anim/clip.h"

namespace kinema {

// Motion control along a position path (seed 003, 16.2.1): p(t) = P(u(s(t))).
// P(u) is a Translation channel evaluated at key time u; s(u) is its arc length from the
// first key, tabulated, and u(s) inverts the table (binary search, then Newton-Raphson on
// s(u) - S = 0 with |P'(u)| as the derivative).
struct ArcLengthTable {
  const Channel* path = nullptr;
  std::vector<float> u;       // parameter samples, from the first to the last key time
  std::vector<double> s;      // arc length at each sample (s[0] = 0)

  double length() const { return s.empty() ? 0.0 : s.back(); }
  // Empty when the table was built from a path with at least two keys.
  std::string validate() const;
};

// Tabulates s(u) with `samples` intervals; each interval's length is integrated with
// 5-point Gauss-Legendre quadrature of |P'(u)|.
ArcLengthTable buildArcLengthTable(const Channel& path, int samples = 512);

// The parameter u with s(u) = distance (clamped to [0, length]).
float parameterAtDistance(const ArcLengthTable& table, double distance);

// A distance-time function s(t) over [0, duration] covering `distance` in total.
struct DistanceProfile {
  enum class Kind { ConstantSpeed, SineEase, ParabolicEase, VelocityCurve };
  Kind kind = Kind::ConstantSpeed;
  double duration = 1.0;
  double distance = 1.0;
  // ParabolicEase: constant acceleration over [0, accelEnd], constant speed, constant
  // deceleration over [decelStart, duration] (fractions of the duration, 0 <= a <= d <= 1).
  double accelEnd = 0.25, decelStart = 0.75;
  // VelocityCurve: v(t) from this scalar channel (values.x, distance per second),
  // integrated to s(t); `distance` is then ignored and s is clamped to the path.
  const Channel* velocity = nullptr;
  std::vector<double> integral;  // filled by prepareDistanceProfile for VelocityCurve

  std::string validate() const;
};

// Precomputes what a profile needs (the integral table of a velocity curve).
void prepareDistanceProfile(DistanceProfile& profile, int samples = 1024);
// s(t), with t clamped to [0, duration].
double distanceAt(const DistanceProfile& profile, double t);

// p(t) = P(u(s(t))).
glm::vec3 positionAtTime(const ArcLengthTable& table, const DistanceProfile& profile, double t);

}  // namespace kinema
