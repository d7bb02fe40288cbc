#pragma once
#include <cstdint>
#include <vector>

#include "core/math.h"
#include "render/pixel_rect.h"

namespace kinema {

// Culling for a partial redraw (FrameDescription::limit): the 3D view is drawn with the
// scissor box on `limit`, and a software rasteriser still transforms, sets up and bins
// every triangle outside it (about 0.1 us each on llvmpipe). Leaving out what cannot reach
// `limit` keeps the pixels inside it exactly as drawing everything would: the rest keep
// their order, so depth ties resolve as before.
struct ScreenRegion {
  glm::mat4 viewProjection{1.0f};  // world space -> clip space, as the shaders draw
  PixelRect viewport;              // glViewport's rectangle, framebuffer pixels, rows from the bottom
  PixelRect limit;                 // the pixels drawn (the scissor box); empty: the whole viewport

  // Whether culling can leave anything out: a limit smaller than the viewport.
  bool culls() const { return !limit.empty() && !limit.contains(viewport); }
  // Whether world points whose screen bounds are those of `corners` may cover a pixel of
  // `limit`: true when their pixel box, grown by kScreenCullMargin, meets it, and whenever a
  // corner is at or behind the camera plane (the clipper makes new corners there).
  bool mayCover(const glm::vec3* corners, int count) const;
  // The same for a box in a shape's own space placed by `model` (its 8 corners).
  bool boxMayCover(const glm::mat4& model, const glm::vec3& min, const glm::vec3& max) const;
};

// Pixels added on every side of a primitive's screen box before it is tested against the
// limit: covers rounding between this projection (float, as the shader) and the rasteriser's.
constexpr double kScreenCullMargin = 2.0;

// Working memory of appendTrianglesInRegion, kept by the caller so a frame allocates nothing.
struct ScreenCullScratch {
  std::vector<glm::dvec2> pixel;  // each vertex's framebuffer pixel
  std::vector<char> usable;       // 0: at or behind the camera plane, or not finite
};

// Of a triangle list (three indices a triangle into `positions`, world space, `stride`
// floats apart), the triangles that may cover a pixel of region.limit, appended to `out` in
// their order. Indices out of range are dropped with their triangle (the rasteriser would
// read garbage).
void appendTrianglesInRegion(const ScreenRegion& region, const float* positions, size_t stride, size_t vertexCount,
                             const std::vector<uint32_t>& indices, std::vector<uint32_t>& out,
                             ScreenCullScratch& scratch);

}  // namespace kinema
