#include "render/raster_draw.h"

#include <algorithm>
#include <cmath>

#include <stb_easy_font.h>

namespace kinema::raster {

void blend(Image& img, int x, int y, const Rgb& color, float a) {
  if (x < 0 || y < 0 || x >= img.width || y >= img.height || a <= 0.0f) return;
  a = std::min(1.0f, a);
  std::uint8_t* p = img.pixel(x, y);
  for (int i = 0; i < 3; ++i) p[i] = static_cast<std::uint8_t>(std::lround(p[i] + (color[i] - p[i]) * a));
  p[3] = 255;
}

void line(Image& img, glm::vec2 a, glm::vec2 b, float width, const Rgb& color, const glm::ivec4& clip, float opacity) {
  const float r = 0.5f * width;
  const int x0 = std::max(clip.x, static_cast<int>(std::floor(std::min(a.x, b.x) - r - 1)));
  const int x1 = std::min(clip.z, static_cast<int>(std::ceil(std::max(a.x, b.x) + r + 1)));
  const int y0 = std::max(clip.y, static_cast<int>(std::floor(std::min(a.y, b.y) - r - 1)));
  const int y1 = std::min(clip.w, static_cast<int>(std::ceil(std::max(a.y, b.y) + r + 1)));
  const glm::vec2 d = b - a;
  const float len2 = glm::dot(d, d);
  for (int y = y0; y < y1; ++y)
    for (int x = x0; x < x1; ++x) {
      const glm::vec2 p(x + 0.5f, y + 0.5f);
      const float t = len2 > 0 ? std::clamp(glm::dot(p - a, d) / len2, 0.0f, 1.0f) : 0.0f;
      const float dist = glm::length(p - (a + t * d));
      blend(img, x, y, color, std::min(1.0f, r + 0.5f - dist) * opacity);
    }
}

void dot(Image& img, glm::vec2 c, float radius, const Rgb& color, float opacity) {
  for (int y = static_cast<int>(c.y - radius - 1); y <= static_cast<int>(c.y + radius + 1); ++y)
    for (int x = static_cast<int>(c.x - radius - 1); x <= static_cast<int>(c.x + radius + 1); ++x)
      blend(img, x, y, color,
            std::min(1.0f, radius + 0.5f - glm::length(glm::vec2(x + 0.5f, y + 0.5f) - c)) * opacity);
}

void ring(Image& img, glm::vec2 c, float radius, float width, const Rgb& color, float opacity) {
  const float r = 0.5f * width, reach = radius + r + 1.0f;
  const int x0 = std::max(0, static_cast<int>(std::floor(c.x - reach)));
  const int x1 = std::min(img.width, static_cast<int>(std::ceil(c.x + reach)));
  const int y0 = std::max(0, static_cast<int>(std::floor(c.y - reach)));
  const int y1 = std::min(img.height, static_cast<int>(std::ceil(c.y + reach)));
  for (int y = y0; y < y1; ++y)
    for (int x = x0; x < x1; ++x) {
      const float d = std::abs(glm::length(glm::vec2(x + 0.5f, y + 0.5f) - c) - radius);
      blend(img, x, y, color, std::min(1.0f, r + 0.5f - d) * opacity);
    }
}

void polygon(Image& img, const std::vector<glm::vec2>& pts, const Rgb& color, float opacity) {
  if (pts.size() < 3) return;
  glm::vec2 lo = pts[0], hi = pts[0];
  for (const glm::vec2& p : pts) {
    lo = glm::min(lo, p);
    hi = glm::max(hi, p);
  }
  const int y0 = std::max(0, static_cast<int>(std::floor(lo.y))), y1 = std::min(img.height, static_cast<int>(std::ceil(hi.y)) + 1);
  const int x0 = std::max(0, static_cast<int>(std::floor(lo.x))), x1 = std::min(img.width, static_cast<int>(std::ceil(hi.x)) + 1);
  if (x0 >= x1) return;
  constexpr int kSub = 4;
  std::vector<float> coverage(static_cast<size_t>(x1 - x0));
  std::vector<float> crossings;
  for (int y = y0; y < y1; ++y) {
    std::fill(coverage.begin(), coverage.end(), 0.0f);
    for (int sy = 0; sy < kSub; ++sy) {
      const float yy = y + (sy + 0.5f) / kSub;
      crossings.clear();
      for (size_t i = 0; i < pts.size(); ++i) {
        const glm::vec2 a = pts[i], b = pts[(i + 1) % pts.size()];
        if ((a.y <= yy) != (b.y <= yy)) crossings.push_back(a.x + (yy - a.y) / (b.y - a.y) * (b.x - a.x));
      }
      std::sort(crossings.begin(), crossings.end());
      for (size_t k = 0; k + 1 < crossings.size(); k += 2) {
        // Horizontal coverage of [xa, xb) in each pixel, exactly.
        const float xa = std::max(crossings[k], static_cast<float>(x0)), xb = std::min(crossings[k + 1], static_cast<float>(x1));
        for (int x = static_cast<int>(std::floor(xa)); x < x1 && x < xb; ++x) {
          const float c = std::min(xb, x + 1.0f) - std::max(xa, static_cast<float>(x));
          if (c > 0.0f) coverage[x - x0] += c / kSub;
        }
      }
    }
    for (int x = x0; x < x1; ++x) blend(img, x, y, color, coverage[x - x0] * opacity);
  }
}

void rect(Image& img, int x0, int y0, int x1, int y1, const Rgb& color) {
  for (int y = std::max(0, y0); y < std::min(img.height, y1); ++y)
    for (int x = std::max(0, x0); x < std::min(img.width, x1); ++x) blend(img, x, y, color, 1.0f);
}

// stb_easy_font builds glyphs from axis-aligned quads; each is filled at `scale`.
void text(Image& img, int x, int y, const std::string& s, const Rgb& color, int scale) {
  static thread_local std::vector<char> buffer(60000);
  std::string copy = s;
  unsigned char c[4] = {0, 0, 0, 255};
  const int quads = stb_easy_font_print(0, 0, copy.data(), c, buffer.data(), static_cast<int>(buffer.size()));
  const float* v = reinterpret_cast<const float*>(buffer.data());
  for (int q = 0; q < quads; ++q) {
    const float* a = v + q * 16;  // 4 vertices of (x, y, z, color) = 4 floats each
    const float qx0 = a[0], qy0 = a[1], qx1 = a[8], qy1 = a[9];
    rect(img, x + static_cast<int>(qx0 * scale), y + static_cast<int>(qy0 * scale), x + static_cast<int>(qx1 * scale),
         y + static_cast<int>(qy1 * scale), color);
  }
}

int textWidth(const std::string& s) {
  std::string copy = s;
  return stb_easy_font_width(copy.data());
}

}  // namespace kinema::raster
