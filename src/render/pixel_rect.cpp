#include "render/pixel_rect.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace kinema {

PixelRect PixelRect::united(const PixelRect& o) const {
  if (o.empty()) return *this;
  if (empty()) return o;
  return {std::min(x0, o.x0), std::min(y0, o.y0), std::max(x1, o.x1), std::max(y1, o.y1)};
}

PixelRect PixelRect::intersected(const PixelRect& o) const {
  PixelRect r{std::max(x0, o.x0), std::max(y0, o.y0), std::min(x1, o.x1), std::min(y1, o.y1)};
  return r.empty() ? PixelRect{} : r;
}

PixelRect PixelRect::grown(int pixels) const {
  if (empty()) return *this;
  return {x0 - pixels, y0 - pixels, x1 + pixels, y1 + pixels};
}

PixelRect PixelRect::covering(double minX, double minY, double maxX, double maxY, const PixelRect& whole) {
  if (!std::isfinite(minX) || !std::isfinite(minY) || !std::isfinite(maxX) || !std::isfinite(maxY)) return whole;
  if (maxX < minX || maxY < minY) return {};
  // Clamp before converting: a point far outside must not overflow an int.
  const double lo = -1e7, hi = 1e7;
  const int x0 = static_cast<int>(std::floor(std::clamp(minX, lo, hi)));
  const int y0 = static_cast<int>(std::floor(std::clamp(minY, lo, hi)));
  const int x1 = static_cast<int>(std::floor(std::clamp(maxX, lo, hi))) + 1;
  const int y1 = static_cast<int>(std::floor(std::clamp(maxY, lo, hi))) + 1;
  return PixelRect{x0, y0, x1, y1};
}

std::vector<PixelRect> mergeDamage(std::vector<PixelRect> rects, int most) {
  most = std::max(most, 1);
  rects.erase(std::remove_if(rects.begin(), rects.end(), [](const PixelRect& r) { return r.empty(); }), rects.end());
  // Merge overlapping pairs until none overlap (a merge can make a new overlap: start again).
  for (bool merged = true; merged;) {
    merged = false;
    for (size_t i = 0; i < rects.size() && !merged; ++i)
      for (size_t j = i + 1; j < rects.size() && !merged; ++j)
        if (rects[i].intersects(rects[j])) {
          rects[i] = rects[i].united(rects[j]);
          rects.erase(rects.begin() + static_cast<long>(j));
          merged = true;
        }
  }
  // Too many: merge the pair whose union adds the fewest pixels, then settle overlaps again.
  while (static_cast<int>(rects.size()) > most) {
    size_t bi = 0, bj = 1;
    long long best = std::numeric_limits<long long>::max();
    for (size_t i = 0; i < rects.size(); ++i)
      for (size_t j = i + 1; j < rects.size(); ++j) {
        const long long cost = rects[i].united(rects[j]).area() - rects[i].area() - rects[j].area();
        if (cost < best) best = cost, bi = i, bj = j;
      }
    rects[bi] = rects[bi].united(rects[bj]);
    rects.erase(rects.begin() + static_cast<long>(bj));
    return mergeDamage(std::move(rects), most);
  }
  return rects;
}

}  // namespace kinema
