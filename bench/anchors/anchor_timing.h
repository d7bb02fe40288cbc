#pragma once
// Side-by-side timing for the anchor comparisons: the two sides run in alternating rounds
// (so both see the same machine load), each round timed in CPU time of this thread; the
// figure is the median over rounds, in nanoseconds per item.
#include <algorithm>
#include <cstdio>
#include <string>
#include <vector>

namespace kinema::anchor {

// CPU time of the calling thread, seconds.
double threadSeconds();

double median(std::vector<double> v);

struct SideBySide {
  double kinema = 0.0;  // ns per item
  double anchor = 0.0;  // ns per item
  double ratio() const { return kinema / anchor; }
};

// Calls each side's `run()` in batches sized to about `roundSeconds`, alternating for
// `rounds` rounds; `items` is the work one call does (joints, vertices, solves).
template <class K, class A>
SideBySide alternate(K&& kinemaSide, A&& anchorSide, double items, int rounds = 11, double roundSeconds = 0.03) {
  auto batchFor = [&](auto& f) {
    long n = 1;
    for (;;) {
      const double t0 = threadSeconds();
      for (long i = 0; i < n; ++i) f();
      const double dt = threadSeconds() - t0;
      if (dt > 0.2 * roundSeconds) return std::max(1L, static_cast<long>(n * roundSeconds / dt));
      n *= 4;
    }
  };
  const long nk = batchFor(kinemaSide), na = batchFor(anchorSide);
  std::vector<double> k, a;
  for (int r = 0; r < rounds; ++r) {
    double t0 = threadSeconds();
    for (long i = 0; i < nk; ++i) kinemaSide();
    k.push_back((threadSeconds() - t0) * 1e9 / (nk * items));
    t0 = threadSeconds();
    for (long i = 0; i < na; ++i) anchorSide();
    a.push_back((threadSeconds() - t0) * 1e9 / (na * items));
  }
  return {median(k), median(a)};
}



// One row of the printed table: "| work | Kinema | anchor | ratio |".
void printRow(const std::string& work, const SideBySide& r, const char* unit, const std::string& anchorName);
void printHeader(const char* title);

}  // namespace kinema::anchor
