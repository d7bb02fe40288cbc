#include "anim/frame_grid.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include "anim/clip.h"

namespace kinema {

float FrameGrid::frameToTime(long long frame) const {
  return static_cast<float>(static_cast<double>(frame) * secondsPerFrame);
}

double FrameGrid::timeToFrame(double time) const { return time / secondsPerFrame; }

long long FrameGrid::nearestFrame(double time) const {
  const double f = timeToFrame(time);
  return std::isfinite(f) ? std::llround(std::clamp(f, -1e12, 1e12)) : 0;
}

FrameGrid documentFrameGrid(double documentFrameRate) {
  const bool usable = std::isfinite(documentFrameRate) && documentFrameRate > 0.0;
  return FrameGrid{1.0 / (usable ? documentFrameRate : kDefaultFrameRate)};
}

FrameGrid ownFrameGrid(const Clip& clip) { return FrameGrid{hasOwnFrameRate(clip) ? clip.frameTime : 0.0}; }

bool hasOwnFrameRate(const Clip& clip) { return clip.frameTime > 0.0 && std::isfinite(clip.frameTime); }

FrameGrid frameGridOf(const Clip& clip, double documentFrameRate) {
  if (clip.frameTime > 0.0 && std::isfinite(clip.frameTime)) return FrameGrid{clip.frameTime};
  return documentFrameGrid(documentFrameRate);
}

namespace {

// Every time lies on the grid of `step` seconds: within a thousandth of a frame, plus the
// float rounding of the time itself (key times are 32-bit floats).
bool allOnGrid(const std::vector<float>& times, double step) {
  for (float t : times) {
    const double n = double(t) / step;
    const double slack = 1e-3 + 4.0 * std::abs(double(t)) * 1.2e-7 / step;
    if (std::abs(n - std::round(n)) > slack) return false;
  }
  return true;
}

// Keys at least this many a second are a frame grid of their own (frames per second).
constexpr double kDenseKeyRate = 10.0;

}  // namespace

namespace {
std::vector<float> sortedKeyTimes(const Clip& clip) {
  std::vector<float> times;
  for (const Channel& ch : clip.channels) times.insert(times.end(), ch.times.begin(), ch.times.end());
  std::sort(times.begin(), times.end());
  times.erase(std::unique(times.begin(), times.end()), times.end());
  return times;
}
}  // namespace

bool keysOnGrid(const Clip& clip, const FrameGrid& grid) {
  return grid.secondsPerFrame > 0.0 && allOnGrid(sortedKeyTimes(clip), grid.secondsPerFrame);
}

double keyGridFrameTime(const Clip& clip) {
  const std::vector<float> times = sortedKeyTimes(clip);
  if (times.size() < 2) return 0.0;
  for (float t : times)
    if (!std::isfinite(t)) return 0.0;
  double step = 0.0;
  for (size_t k = 0; k + 1 < times.size(); ++k) {
    const double d = double(times[k + 1]) - times[k];
    if (d > 0.0 && (step == 0.0 || d < step)) step = d;
  }
  // Key times are floats: the whole span over its frame count estimates the step better.
  const double span = double(times.back()) - times.front();
  const double frames = std::round(span / step);
  if (frames >= 1.0 && frames < 1e9) step = span / frames;
  const bool usable = step >= 1.0 / kMaxFrameRate * (1.0 - 1e-9) && step <= 1.0 / kMinFrameRate * (1.0 + 1e-9);
  const bool keysOnStep = usable && allOnGrid(times, step);
  // A dense grid (mocap, baked keys) is the file's rate; sparse keys (a few a second, set by
  // hand) lie on many grids, and the file was most likely made at a common rate.
  static const double kCommonRates[] = {24.0, 25.0, 30.0, 48.0, 50.0, 60.0, 100.0, 120.0};
  if (keysOnStep && step <= 1.0 / kDenseKeyRate) {
    // The step measured from float times, snapped to the common rate it is (1/24, not 0.04166662).
    for (double rate : kCommonRates)
      if (std::abs(rate * step - 1.0) < 1e-4 && allOnGrid(times, 1.0 / rate)) return 1.0 / rate;
    return step;
  }
  for (double rate : kCommonRates)
    if (allOnGrid(times, 1.0 / rate)) return 1.0 / rate;
  return keysOnStep ? step : 0.0;
}

}  // namespace kinema
