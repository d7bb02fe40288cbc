#include "anim/arc_length.h"

#include <algorithm>
#include <cmath>
#include <glm/gtc/constants.hpp>

#include "anim/sampling.h"

namespace kinema {

namespace {


glm::dvec3 P(const Channel& path, double u) { return glm::dvec3(glm::vec3(sampleChannel(path, static_cast<float>(u)))); }

// |P'(u)| by a central difference, one-sided at the ends of the path.
double speed(const Channel& path, double u) {
  const double a = path.startTime(), b = path.endTime();
  const double h = 1e-3 * (b - a);
  const double lo = std::max(a, u - h), hi = std::min(b, u + h);
  return glm::length(P(path, hi) - P(path, lo)) / (hi - lo);
}

double gaussLength(const Channel& path, double a, double b) {
  static const double x[5] = {0.0, -0.5384693101056831, 0.5384693101056831, -0.9061798459386640, 0.9061798459386640};
  static const double w[5] = {0.5688888888888889, 0.4786286704993665, 0.4786286704993665, 0.2369268850561891,
                              0.2369268850561891};
  const double m = 0.5 * (a + b), r = 0.5 * (b - a);
  double sum = 0.0;
  for (int i = 0; i < 5; ++i) sum += w[i] * speed(path, m + r * x[i]);
  return sum * r;
}

}  // namespace

std::string ArcLengthTable::validate() const {
  if (!path) return "no path";
  if (path->keyCount() < 2) return "the path needs at least two keys";
  if (u.size() < 2 || u.size() != s.size()) return "the table is empty";
  return {};
}

ArcLengthTable buildArcLengthTable(const Channel& path, int samples) {
  ArcLengthTable t;
  t.path = &path;
  if (path.keyCount() < 2 || samples < 1) return t;
  const double a = path.startTime(), b = path.endTime();
  t.u.resize(samples + 1);
  t.s.resize(samples + 1);
  t.u[0] = static_cast<float>(a);
  t.s[0] = 0.0;
  for (int i = 1; i <= samples; ++i) {
    const double u0 = a + (b - a) * (i - 1) / samples, u1 = a + (b - a) * i / samples;
    t.u[i] = static_cast<float>(u1);
    t.s[i] = t.s[i - 1] + gaussLength(path, u0, u1);
  }
  return t;
}

float parameterAtDistance(const ArcLengthTable& t, double distance) {
  if (!t.validate().empty()) return 0.0f;
  if (distance <= 0.0) return t.u.front();
  if (distance >= t.length()) return t.u.back();
  const size_t hi = static_cast<size_t>(std::upper_bound(t.s.begin(), t.s.end(), distance) - t.s.begin());
  const size_t lo = hi - 1;
  const double u0 = t.u[lo], u1 = t.u[hi];
  // Linear guess inside the table interval, then Newton on s(u) - S = 0 where
  // s(u) = s[lo] + integral of |P'| from u0 to u, kept inside [u0, u1].
  double u = u0 + (u1 - u0) * (distance - t.s[lo]) / (t.s[hi] - t.s[lo]);
  for (int i = 0; i < 4; ++i) {
    const double f = t.s[lo] + gaussLength(*t.path, u0, u) - distance;
    const double d = speed(*t.path, u);
    if (!(d > 0.0)) break;
    const double next = std::min(u1, std::max(u0, u - f / d));
    if (std::abs(next - u) < 1e-9 * (u1 - u0 + 1e-30)) {
      u = next;
      break;
    }
    u = next;
  }
  return static_cast<float>(u);
}

std::string DistanceProfile::validate() const {
  if (!(duration > 0.0) || !std::isfinite(duration)) return "the duration must be a positive number";
  if (!std::isfinite(distance) || distance < 0.0) return "the distance must be a non-negative number";
  if (kind == Kind::ParabolicEase && !(0.0 <= accelEnd && accelEnd <= decelStart && decelStart <= 1.0))
    return "ease fractions must satisfy 0 <= accelEnd <= decelStart <= 1";
  if (kind == Kind::VelocityCurve && (!velocity || velocity->keyCount() == 0))
    return "a velocity curve needs a channel with keys";
  return {};
}

void prepareDistanceProfile(DistanceProfile& p, int samples) {
  p.integral.clear();
  if (p.kind != DistanceProfile::Kind::VelocityCurve || !p.velocity || samples < 1) return;
  // Simpson's rule on each of `samples` intervals of v(t).
  p.integral.resize(samples + 1, 0.0);
  const double h = p.duration / samples;
  auto v = [&](double t) { return static_cast<double>(sampleChannel(*p.velocity, static_cast<float>(t)).x); };
  for (int i = 1; i <= samples; ++i) {
    const double a = h * (i - 1), b = h * i;
    p.integral[i] = p.integral[i - 1] + h / 6.0 * (v(a) + 4.0 * v(0.5 * (a + b)) + v(b));
  }
}

double distanceAt(const DistanceProfile& p, double t) {
  const double T = p.duration, D = p.distance;
  t = std::min(T, std::max(0.0, t));
  const double x = t / T;
  switch (p.kind) {
    case DistanceProfile::Kind::ConstantSpeed: return D * x;
    case DistanceProfile::Kind::SineEase: return D * 0.5 * (1.0 - std::cos(glm::pi<double>() * x));
    case DistanceProfile::Kind::ParabolicEase: {
      // Speed rises linearly to v0 over [0, a], stays v0, falls linearly to 0 over [d, 1];
      // v0 is fixed by the total: v0 (a/2 + (d - a) + (1 - d)/2) = D.
      const double a = p.accelEnd, d = p.decelStart;
      const double v0 = D / (0.5 * a + (d - a) + 0.5 * (1.0 - d));
      if (x < a) return v0 * x * x / (2.0 * a);
      if (x <= d) return v0 * (0.5 * a + (x - a));
      const double r = 1.0 - x;
      return D - v0 * r * r / (2.0 * (1.0 - d));
    }
    case DistanceProfile::Kind::VelocityCurve: {
      if (p.integral.size() < 2) return 0.0;
      const double f = x * (p.integral.size() - 1);
      const size_t i = std::min(p.integral.size() - 2, static_cast<size_t>(f));
      return p.integral[i] + (p.integral[i + 1] - p.integral[i]) * (f - static_cast<double>(i));
    }
  }
  return 0.0;
}

glm::vec3 positionAtTime(const ArcLengthTable& table, const DistanceProfile& profile, double t) {
  if (!table.validate().empty()) return glm::vec3(0.0f);
  const double s = std::min(table.length(), std::max(0.0, distanceAt(profile, t)));
  return glm::vec3(sampleChannel(*table.path, parameterAtDistance(table, s)));
}

}  // namespace kinema
