#pragma once
#include <string>
#include <vector>

#include "anim/clip.h"

namespace kinema {

// glTF's three sampler interpolations.
enum class GltfInterpolation { Step, Linear, CubicSpline };
const char* toString(GltfInterpolation interpolation);  // "STEP", "LINEAR", "CUBICSPLINE"

// One channel as a glTF animation sampler: key times and output values, `components`
// numbers per element (3 translation/scale, 4 rotation as x, y, z, w, 1 per morph
// target). CUBICSPLINE outputs hold in-tangent, value, out-tangent per key (glTF layout,
// tangents per second); for weights the in-tangents of every target come first.
struct GltfSampler {
  GltfInterpolation interpolation = GltfInterpolation::Linear;
  std::vector<float> times;
  std::vector<float> values;
  int components = 3;
  // Set when the curve could not be written exactly and was sampled at `rate` instead:
  // why, and the largest difference seen between the file's curve and ours (radians for
  // rotations, value units otherwise).
  bool resampled = false;
  std::string reason;
  double maxError = 0.0;
};

// Converts a Translation, Scale, Rotation or Euler channel (rotations become quaternions).
// Step and Linear keys map to STEP and LINEAR; Hermite, Catmull-Rom, TCB, linear and
// Bezier segments whose handles are a third of the key interval long map to CUBICSPLINE
// with the exact tangents; rotations whose segments are all Hermite map to CUBICSPLINE
// (our Hermite rotation is glTF's). Anything else is sampled every 1/rate seconds (and at
// every key) as LINEAR. Every exact conversion is checked against sampleChannel at points
// inside each segment and falls back to resampling when it does not match.
GltfSampler toGltfSampler(const Channel& channel, double rate);

// The morph weights of one node: perTarget[k] is the "weights/K" channel or null (then
// the target keeps `defaults[k]`). Exact when the channels share key times and convert
// exactly with the same interpolation; otherwise all are resampled on one time grid.
GltfSampler toGltfWeightsSampler(const std::vector<const Channel*>& perTarget, const std::vector<float>& defaults,
                                 double rate);

// The value of a glTF sampler at `time` (clamped), following the glTF specification's
// formulas; rotations are slerped (LINEAR) or normalised (CUBICSPLINE). Element `element`
// of `components` numbers. Used to check conversions and by tests.
std::vector<float> evaluateGltfSampler(const GltfSampler& sampler, bool rotation, float time);

}  // namespace kinema
