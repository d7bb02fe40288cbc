#include "render/frame_pass_timer.h"

#include <glad/gl.h>

#include <algorithm>
#include <cstdio>
#include <numeric>

namespace kinema {

namespace {
double median(std::vector<double> v) {
  if (v.empty()) return 0.0;
  std::nth_element(v.begin(), v.begin() + v.size() / 2, v.end());
  return v[v.size() / 2];
}
}  // namespace

void FramePassTimer::beginFrame() {
  frameStart_ = last_ = std::chrono::steady_clock::now();
  for (Pass& p : passes_) p.ms.resize(frames_ + 1, 0.0);
}

void FramePassTimer::charge(const char* pass) {
  const auto now = std::chrono::steady_clock::now();
  const double ms = std::chrono::duration<double, std::milli>(now - last_).count();
  last_ = now;
  auto it = std::find_if(passes_.begin(), passes_.end(), [pass](const Pass& p) { return p.name == pass; });
  if (it == passes_.end()) {
    passes_.push_back({pass, std::vector<double>(frames_ + 1, 0.0)});
    it = passes_.end() - 1;
  }
  it->ms[frames_] += ms;
}

void FramePassTimer::mark(const char* pass) {
  glFinish();
  charge(pass);
}

void FramePassTimer::markCpu(const char* pass) { charge(pass); }

void FramePassTimer::endFrame() {
  frameMs_.push_back(std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - frameStart_).count());
  ++frames_;
}

std::string FramePassTimer::report(size_t skipFrames) const {
  std::string out;
  if (frames_ <= skipFrames) return out;
  const auto tail = [skipFrames](const std::vector<double>& v) {
    return std::vector<double>(v.begin() + static_cast<std::ptrdiff_t>(std::min(skipFrames, v.size())), v.end());
  };
  const double frame = median(tail(frameMs_));
  char line[160];
  for (const Pass& p : passes_) {
    const std::vector<double> t = tail(p.ms);
    const double mean = t.empty() ? 0.0 : std::accumulate(t.begin(), t.end(), 0.0) / static_cast<double>(t.size());
    const double m = median(t);
    std::snprintf(line, sizeof line, "  %-28s median %6.2f ms  mean %6.2f ms  (%4.1f %% of the median frame)\n",
                  p.name.c_str(), m, mean, frame > 0.0 ? 100.0 * m / frame : 0.0);
    out += line;
  }
  std::snprintf(line, sizeof line, "  %-28s median %6.2f ms\n", "whole frame", frame);
  out += line;
  return out;
}

}  // namespace kinema
