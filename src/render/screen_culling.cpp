#include "render/screen_culling.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace kinema {
namespace {

// A point's framebuffer pixel, or false at or behind the camera plane.
bool toPixel(const ScreenRegion& r, const glm::vec3& p, glm::dvec2& out) {
  const glm::vec4 c = r.viewProjection * glm::vec4(p, 1.0f);
  if (!(c.w > 1e-6f)) return false;
  out = {r.viewport.x0 + (double(c.x) / c.w * 0.5 + 0.5) * r.viewport.width(),
         r.viewport.y0 + (double(c.y) / c.w * 0.5 + 0.5) * r.viewport.height()};
  return true;
}

bool boxMeets(const ScreenRegion& r, const glm::dvec2& lo, const glm::dvec2& hi) {
  const double m = kScreenCullMargin;
  return hi.x + m >= r.limit.x0 && lo.x - m <= r.limit.x1 && hi.y + m >= r.limit.y0 && lo.y - m <= r.limit.y1;
}

}  // namespace

bool ScreenRegion::mayCover(const glm::vec3* corners, int count) const {
  if (!culls()) return true;
  glm::dvec2 lo(std::numeric_limits<double>::max()), hi(-std::numeric_limits<double>::max()), p;
  for (int i = 0; i < count; ++i) {
    if (!toPixel(*this, corners[i], p) || !std::isfinite(p.x) || !std::isfinite(p.y)) return true;
    lo = glm::min(lo, p), hi = glm::max(hi, p);
  }
  return boxMeets(*this, lo, hi);
}

bool ScreenRegion::boxMayCover(const glm::mat4& model, const glm::vec3& min, const glm::vec3& max) const {
  glm::vec3 corners[8];
  for (int k = 0; k < 8; ++k)
    corners[k] = glm::vec3(model * glm::vec4(k & 1 ? max.x : min.x, k & 2 ? max.y : min.y, k & 4 ? max.z : min.z, 1.0f));
  return mayCover(corners, 8);
}

void appendTrianglesInRegion(const ScreenRegion& region, const float* positions, size_t stride, size_t vertexCount,
                             const std::vector<uint32_t>& indices, std::vector<uint32_t>& out,
                             ScreenCullScratch& scratch) {
  if (!region.culls()) {
    for (size_t t = 0; t + 2 < indices.size(); t += 3)
      if (indices[t] < vertexCount && indices[t + 1] < vertexCount && indices[t + 2] < vertexCount)
        out.insert(out.end(), {indices[t], indices[t + 1], indices[t + 2]});
    return;
  }
  // Each vertex projected once: its pixel, or "no pixel" (behind the camera, not finite).
  std::vector<glm::dvec2>& pixel = scratch.pixel;
  std::vector<char>& usable = scratch.usable;
  pixel.resize(vertexCount);
  usable.resize(vertexCount);
  for (size_t v = 0; v < vertexCount; ++v) {
    const float* p = positions + v * stride;
    usable[v] = toPixel(region, glm::vec3(p[0], p[1], p[2]), pixel[v]) && std::isfinite(pixel[v].x) &&
                std::isfinite(pixel[v].y);
  }
  for (size_t t = 0; t + 2 < indices.size(); t += 3) {
    const uint32_t a = indices[t], b = indices[t + 1], c = indices[t + 2];
    if (a >= vertexCount || b >= vertexCount || c >= vertexCount) continue;
    if (usable[a] && usable[b] && usable[c] &&
        !boxMeets(region, glm::min(pixel[a], glm::min(pixel[b], pixel[c])), glm::max(pixel[a], glm::max(pixel[b], pixel[c]))))
      continue;
    out.insert(out.end(), {a, b, c});
  }
}

}  // namespace kinema
