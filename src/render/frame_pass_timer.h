#pragma once
#include <chrono>
#include <string>
#include <vector>

namespace kinema {

// Where a frame's time goes, pass by pass, for measurement only (kinema edit
// --report-frame-passes): mark() waits until the GL has finished everything issued so far
// (glFinish), then charges the wall time since the previous mark to the named pass. The
// waits serialise the CPU and the GL, so a frame timed this way is slower than a plain one;
// the split is what it is for. Times in milliseconds.
class FramePassTimer {
 public:
  void beginFrame();
  // Charges the time since the previous mark (or beginFrame) to `pass`; a pass marked twice
  // in a frame adds up.
  void mark(const char* pass);
  // Charges the time since the previous mark to `pass` without waiting for the GL (CPU work
  // that issued no GL calls since the previous mark).
  void markCpu(const char* pass);
  void endFrame();
  // One line per pass in first-seen order: median and mean over the frames after the first
  // `skipFrames`, and the share of the median frame; then the frame's total.
  std::string report(size_t skipFrames) const;

 private:
  void charge(const char* pass);
  struct Pass {
    std::string name;
    std::vector<double> ms;  // one entry per frame (0 where the pass did not run)
  };
  std::vector<Pass> passes_;
  std::vector<double> frameMs_;
  std::chrono::steady_clock::time_point frameStart_, last_;
  size_t frames_ = 0;
};

}  // namespace kinema
