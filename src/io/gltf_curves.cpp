#include "io/gltf_curves.h"

#include <algorithm>
#include <cmath>

#include "anim/bezier_handles.h"
#include "anim/sampling.h"
#include "anim/tcb_spline.h"
#include "core/rotation.h"

namespace kinema {

const char* toString(GltfInterpolation interpolation) {
  switch (interpolation) {
    case GltfInterpolation::Step: return "STEP";
    case GltfInterpolation::Linear: return "LINEAR";
    case GltfInterpolation::CubicSpline: return "CUBICSPLINE";
  }
  return "LINEAR";
}

namespace {

bool isRotation(const Channel& ch) { return ch.target == ChannelTarget::Rotation || ch.target == ChannelTarget::Euler; }
int componentsOf(const Channel& ch) {
  if (isRotation(ch)) return 4;
  return ch.target == ChannelTarget::Scalar ? 1 : 3;
}

Interpolation modeOf(const Channel& ch, int k) { return ch.keys.empty() ? ch.interpolation : ch.keys[k].interpolation; }

glm::quat toQuat(const glm::vec4& v) { return glm::quat(v.w, v.x, v.y, v.z); }

// The channel's value at `time` as the numbers glTF stores: Euler angles become a unit
// quaternion (x, y, z, w).
glm::vec4 gltfValue(const Channel& ch, float time) {
  const glm::vec4 v = sampleChannel(ch, time);
  if (ch.target != ChannelTarget::Euler) return v;
  const glm::quat q = eulerToQuat(glm::vec3(v), ch.eulerOrder);
  return {q.x, q.y, q.z, q.w};
}

// The key's value as stored: rotations normalised, Euler keys converted.
glm::vec4 keyValue(const Channel& ch, int k) {
  if (ch.target == ChannelTarget::Euler) {
    const glm::quat q = eulerToQuat(glm::vec3(ch.values[k]), ch.eulerOrder);
    return {q.x, q.y, q.z, q.w};
  }
  if (ch.target == ChannelTarget::Rotation) {
    const glm::quat q = safeNormalize(toQuat(ch.values[k]));
    return {q.x, q.y, q.z, q.w};
  }
  return ch.values[k];
}

// The Hermite tangents (per second) of the segment from key k to k+1 when the segment
// is exactly a cubic in time: out of key k and into key k+1.
bool segmentTangents(const Channel& ch, int k, glm::vec4& out, glm::vec4& in) {
  const float dt = ch.times[k + 1] - ch.times[k];
  switch (modeOf(ch, k)) {
    case Interpolation::Linear:
      out = in = (ch.values[k + 1] - ch.values[k]) / dt;
      return true;
    case Interpolation::Hermite:
      out = ch.settings(k).outTangent;
      in = ch.keys.empty() ? glm::vec4(0.0f) : ch.keys[k + 1].inTangent;
      return true;
    case Interpolation::CatmullRom:
    case Interpolation::TCB: {
      const bool tcb = modeOf(ch, k) == Interpolation::TCB;
      glm::vec4 unusedIn, unusedOut;
      tcbTangents(ch, k, tcb, unusedIn, out);
      tcbTangents(ch, k + 1, tcb, in, unusedOut);
      return true;
    }
    case Interpolation::Bezier: {
      // With both handles a third of the interval long the time axis is linear in the
      // curve parameter, so the value is a cubic in time with these end slopes.
      const BezierHandles a = effectiveHandles(ch, k), b = effectiveHandles(ch, k + 1);
      const float third = dt / 3.0f, tol = 1e-5f * dt;
      if (std::abs(a.rightTime - third) > tol || std::abs(b.leftTime + third) > tol) return false;
      out = a.rightValue / a.rightTime;
      in = b.leftValue / b.leftTime;
      return true;
    }
    default: return false;
  }
}

void push(std::vector<float>& to, const glm::vec4& v, int n) {
  for (int i = 0; i < n; ++i) to.push_back(v[i]);
}

// Angle between two rotations given as (x, y, z, w), robust near zero (acos is not).
double rotationAngle(const glm::vec4& a, const glm::vec4& b) {
  const glm::quat d = glm::inverse(safeNormalize(toQuat(a))) * safeNormalize(toQuat(b));
  const double v = std::sqrt(double(d.x) * d.x + double(d.y) * d.y + double(d.z) * d.z);
  return 2.0 * std::atan2(v, std::abs(double(d.w)));
}

double difference(const std::vector<float>& a, const glm::vec4& b, bool rotation, int n) {
  if (rotation) return rotationAngle(glm::vec4(a[0], a[1], a[2], a[3]), b);
  double d2 = 0.0;
  for (int i = 0; i < n; ++i) d2 += (double(a[i]) - b[i]) * (double(a[i]) - b[i]);
  return std::sqrt(d2);
}

const float kProbes[] = {0.125f, 0.25f, 0.5f, 0.75f, 0.875f};

// Largest difference between the sampler and the channel at points inside every
// segment of `times` (the sampler's own keys).
double maxDeviation(const GltfSampler& s, const Channel& ch, int element, int elements) {
  const bool rotation = isRotation(ch);
  double worst = 0.0;
  for (size_t k = 0; k + 1 < s.times.size(); ++k) {
    for (float u : kProbes) {
      const float t = s.times[k] + u * (s.times[k + 1] - s.times[k]);
      std::vector<float> got = evaluateGltfSampler(s, rotation, t);
      if (elements > 1) got = {got[element]};
      worst = std::max(worst, difference(got, gltfValue(ch, t), rotation, s.components / elements));
    }
  }
  return worst;
}

// Key times plus evenly spaced points inside every segment longer than 1/rate.
std::vector<float> sampleTimes(const std::vector<float>& keys, double rate) {
  std::vector<float> out;
  for (size_t k = 0; k < keys.size(); ++k) {
    out.push_back(keys[k]);
    if (k + 1 == keys.size()) break;
    const double dt = double(keys[k + 1]) - keys[k];
    const int steps = static_cast<int>(std::ceil(dt * rate - 1e-6));
    for (int j = 1; j < steps; ++j) out.push_back(static_cast<float>(keys[k] + dt * j / steps));
  }
  return out;
}

void resample(const Channel& ch, double rate, const std::string& reason, GltfSampler& s) {
  const bool rotation = isRotation(ch);
  s = GltfSampler{};
  s.components = componentsOf(ch);
  s.interpolation = GltfInterpolation::Linear;
  s.resampled = true;
  s.reason = reason;
  s.times = sampleTimes(ch.times, rate);
  glm::vec4 previous(0, 0, 0, 1);
  for (float t : s.times) {
    glm::vec4 v = gltfValue(ch, t);
    if (rotation && glm::dot(v, previous) < 0.0f) v = -v;  // one hemisphere: slerp agrees either way
    previous = v;
    push(s.values, v, s.components);
  }
  s.maxError = maxDeviation(s, ch, 0, 1);
}

}  // namespace

GltfSampler toGltfSampler(const Channel& ch, double rate) {
  GltfSampler s;
  s.components = componentsOf(ch);
  const int n = ch.keyCount(), c = s.components;
  const bool rotation = isRotation(ch);
  s.times = ch.times;
  if (n <= 1) {
    s.interpolation = GltfInterpolation::Linear;
    if (n == 1) push(s.values, keyValue(ch, 0), c);
    return s;
  }
  bool allStep = true, allLinear = true, allCubic = true;
  for (int k = 0; k + 1 < n; ++k) {
    const Interpolation m = modeOf(ch, k);
    allStep = allStep && m == Interpolation::Step;
    allLinear = allLinear && m == Interpolation::Linear;
    // Rotations: Hermite, or Bezier (quaternion F-curves) whose handles make a cubic in time.
    allCubic = allCubic && (m == Interpolation::Hermite || m == Interpolation::Bezier);
  }
  std::string reason;
  if (allStep) {
    s.interpolation = GltfInterpolation::Step;
    for (int k = 0; k < n; ++k) push(s.values, keyValue(ch, k), c);
  } else if (allLinear && ch.target != ChannelTarget::Euler) {
    s.interpolation = GltfInterpolation::Linear;
    glm::vec4 previous(0, 0, 0, 1);
    for (int k = 0; k < n; ++k) {
      glm::vec4 v = keyValue(ch, k);
      if (rotation && glm::dot(v, previous) < 0.0f) v = -v;  // our slerp takes the short arc
      previous = v;
      push(s.values, v, c);
    }
  } else if (ch.target == ChannelTarget::Euler) {
    reason = "Euler angles are not interpolated like quaternions";
  } else if (rotation && !allCubic) {
    reason = "glTF rotations are slerped or cubic; this curve is neither";
  } else {
    // CUBICSPLINE: each segment sets the out-tangent of its first key and the in-tangent
    // of its second; the file's first in-tangent and last out-tangent are never used.
    std::vector<glm::vec4> in(n, glm::vec4(0.0f)), out(n, glm::vec4(0.0f));
    for (int k = 0; k + 1 < n && reason.empty(); ++k) {
      if (rotation && modeOf(ch, k) == Interpolation::Hermite) {
        out[k] = ch.settings(k).outTangent;
        in[k + 1] = ch.keys.empty() ? glm::vec4(0.0f) : ch.keys[k + 1].inTangent;
      } else if (!segmentTangents(ch, k, out[k], in[k + 1])) {
        reason = std::string(toString(modeOf(ch, k))) + " keys are not a cubic in time";
      }
    }
    if (reason.empty()) {
      s.interpolation = GltfInterpolation::CubicSpline;
      for (int k = 0; k < n; ++k) {
        push(s.values, in[k], c);
        push(s.values, rotation ? ch.values[k] : keyValue(ch, k), c);
        push(s.values, out[k], c);
      }
    }
  }
  if (reason.empty()) {
    // Only exact conversions get here; a mismatch means an assumption above is wrong.
    const double tol = rotation ? 1e-4 : 1e-4 * (1.0 + [&] {
      double m = 0.0;
      for (const glm::vec4& v : ch.values) m = std::max(m, double(glm::length(v)));
      return m;
    }());
    if (maxDeviation(s, ch, 0, 1) <= tol) return s;
    reason = "the exact conversion did not reproduce the curve";
  }
  resample(ch, rate, reason, s);
  return s;
}

GltfSampler toGltfWeightsSampler(const std::vector<const Channel*>& perTarget, const std::vector<float>& defaults,
                                 double rate) {
  const int targets = static_cast<int>(perTarget.size());
  std::vector<GltfSampler> each(targets);
  int firstIndex = -1;
  for (int k = 0; k < targets; ++k) {
    if (!perTarget[k]) continue;
    each[k] = toGltfSampler(*perTarget[k], rate);
    if (firstIndex < 0) firstIndex = k;
  }
  GltfSampler s;
  s.components = targets;
  if (firstIndex < 0) return s;
  const Channel* first = perTarget[firstIndex];
  bool exact = true;
  for (int k = 0; k < targets; ++k)
    if (perTarget[k])
      exact = exact && !each[k].resampled && perTarget[k]->times == first->times &&
              each[k].interpolation == each[firstIndex].interpolation;
  if (exact) {
    s.interpolation = each[firstIndex].interpolation;
    s.times = first->times;
    const int slots = s.interpolation == GltfInterpolation::CubicSpline ? 3 : 1;
    for (size_t key = 0; key < s.times.size(); ++key)
      for (int slot = 0; slot < slots; ++slot)
        for (int k = 0; k < targets; ++k) {
          const bool valueSlot = slots == 1 || slot == 1;
          s.values.push_back(perTarget[k] ? each[k].values[key * slots + slot] : (valueSlot ? defaults[k] : 0.0f));
        }
    return s;
  }
  // One grid for every target: all key times, filled in to the rate.
  std::vector<float> keys;
  for (const Channel* ch : perTarget)
    if (ch) keys.insert(keys.end(), ch->times.begin(), ch->times.end());
  std::sort(keys.begin(), keys.end());
  keys.erase(std::unique(keys.begin(), keys.end()), keys.end());
  s.interpolation = GltfInterpolation::Linear;
  s.resampled = true;
  s.reason = "the morph weight channels do not share key times and interpolation";
  s.times = sampleTimes(keys, rate);
  for (float t : s.times)
    for (int k = 0; k < targets; ++k) s.values.push_back(perTarget[k] ? sampleChannel(*perTarget[k], t).x : defaults[k]);
  for (int k = 0; k < targets; ++k)
    if (perTarget[k]) s.maxError = std::max(s.maxError, maxDeviation(s, *perTarget[k], k, targets));
  return s;
}

std::vector<float> evaluateGltfSampler(const GltfSampler& s, bool rotation, float time) {
  const int n = static_cast<int>(s.times.size()), c = s.components;
  const bool cubic = s.interpolation == GltfInterpolation::CubicSpline;
  auto element = [&](int key, int slot) {  // slot: 0 in-tangent, 1 value, 2 out-tangent
    const size_t at = cubic ? (static_cast<size_t>(key) * 3 + slot) * c : static_cast<size_t>(key) * c;
    return std::vector<float>(s.values.begin() + at, s.values.begin() + at + c);
  };
  if (n == 0) return std::vector<float>(c, 0.0f);
  if (time <= s.times[0]) return element(0, 1);
  if (time >= s.times[n - 1]) return element(n - 1, 1);
  const int k = static_cast<int>(std::upper_bound(s.times.begin(), s.times.end(), time) - s.times.begin()) - 1;
  const float t0 = s.times[k], dt = s.times[k + 1] - t0, u = (time - t0) / dt;
  if (s.interpolation == GltfInterpolation::Step) return element(k, 1);
  std::vector<float> a = element(k, 1), b = element(k + 1, 1), r(c);
  if (!cubic) {
    if (!rotation) {
      for (int i = 0; i < c; ++i) r[i] = a[i] + u * (b[i] - a[i]);
      return r;
    }
    const glm::quat q = slerpShortest(toQuat({a[0], a[1], a[2], a[3]}), toQuat({b[0], b[1], b[2], b[3]}), u);
    return {q.x, q.y, q.z, q.w};
  }
  // glTF 2.0 Appendix C: p(u) = (2u^3-3u^2+1) v_k + dt (u^3-2u^2+u) b_k + (-2u^3+3u^2) v_k+1 + dt (u^3-u^2) a_k+1.
  const std::vector<float> outK = element(k, 2), inK1 = element(k + 1, 0);
  const float u2 = u * u, u3 = u2 * u;
  for (int i = 0; i < c; ++i)
    r[i] = (2 * u3 - 3 * u2 + 1) * a[i] + dt * (u3 - 2 * u2 + u) * outK[i] + (-2 * u3 + 3 * u2) * b[i] +
           dt * (u3 - u2) * inK1[i];
  if (rotation) {
    const glm::quat q = safeNormalize(toQuat({r[0], r[1], r[2], r[3]}));
    return {q.x, q.y, q.z, q.w};
  }
  return r;
}

}  // namespace kinema
