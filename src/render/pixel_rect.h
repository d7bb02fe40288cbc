#pragma once
#include <vector>

namespace kinema {

// A rectangle of whole pixels, [x0, x1) x [y0, y1), in whichever pixel space its user names
// (framebuffer pixels with GL's rows from the bottom, or window pixels from the top). Empty
// when either side has no width.
struct PixelRect {
  int x0 = 0, y0 = 0, x1 = 0, y1 = 0;

  bool empty() const { return x1 <= x0 || y1 <= y0; }
  long long area() const { return empty() ? 0 : static_cast<long long>(x1 - x0) * (y1 - y0); }
  int width() const { return empty() ? 0 : x1 - x0; }
  int height() const { return empty() ? 0 : y1 - y0; }
  bool operator==(const PixelRect& o) const { return x0 == o.x0 && y0 == o.y0 && x1 == o.x1 && y1 == o.y1; }
  bool operator!=(const PixelRect& o) const { return !(*this == o); }
  // The smallest rectangle holding both (an empty one adds nothing).
  PixelRect united(const PixelRect& o) const;
  PixelRect intersected(const PixelRect& o) const;
  bool intersects(const PixelRect& o) const { return !intersected(o).empty(); }
  bool contains(const PixelRect& o) const { return o.empty() || (o.x0 >= x0 && o.y0 >= y0 && o.x1 <= x1 && o.y1 <= y1); }
  // Grown by `pixels` on every side.
  PixelRect grown(int pixels) const;
  // The whole pixels that a real-valued box [minX, maxX] x [minY, maxY] touches, rounded
  // outwards (NaN or infinite bounds: `whole`).
  static PixelRect covering(double minX, double minY, double maxX, double maxY, const PixelRect& whole);
};

// Rectangles that together cover every pixel of `rects`, pairwise disjoint, at most `most`
// of them (at least 1): overlapping ones are merged into their bounding rectangle, and
// while there are too many, the pair whose bounding rectangle adds the fewest pixels. Empty
// rectangles are dropped. Disjointness is what lets a caller draw each pixel once per layer.
std::vector<PixelRect> mergeDamage(std::vector<PixelRect> rects, int most);

}  // namespace kinema
