#include "anchor_timing.h"

#include <algorithm>
#include <ctime>

namespace kinema::anchor {

double threadSeconds() {
  timespec ts{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
  return static_cast<double>(ts.tv_sec) + 1e-9 * static_cast<double>(ts.tv_nsec);
}

double median(std::vector<double> v) {
  if (v.empty()) return 0.0;
  std::sort(v.begin(), v.end());
  const size_t m = v.size() / 2;
  return v.size() % 2 ? v[m] : 0.5 * (v[m - 1] + v[m]);
}

void printHeader(const char* title) {
  std::printf("\n%s\n| work | Kinema | anchor | ratio |\n|---|---|---|---|\n", title);
}

void printRow(const std::string& work, const SideBySide& r, const char* unit, const std::string& anchorName) {
  std::printf("| %s | %.3g %s | %s %.3g | %.2f |\n", work.c_str(), r.kinema, unit, anchorName.c_str(), r.anchor,
              r.ratio());
  std::fflush(stdout);
}

}  // namespace kinema::anchor
