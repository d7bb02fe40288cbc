#pragma once
// Anti-aliased CPU drawing into an Image (no OpenGL): lines, dots, rings, filled polygons
// and stb_easy_font text. Shared by the curve plots and the teaching figures.
#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "core/math.h"
#include "io/image.h"

namespace kinema::raster {

using Rgb = std::array<std::uint8_t, 3>;

// Blends `color` into pixel (x, y) with coverage a in [0, 1] (outside the image: nothing).
void blend(Image& img, int x, int y, const Rgb& color, float a);
// A segment `width` pixels wide, anti-aliased by the distance of each pixel centre to it,
// clipped to the pixel rectangle clip = (x0, y0, x1, y1), x1/y1 exclusive.
void line(Image& img, glm::vec2 a, glm::vec2 b, float width, const Rgb& color, const glm::ivec4& clip,
          float opacity = 1.0f);
void dot(Image& img, glm::vec2 center, float radius, const Rgb& color, float opacity = 1.0f);
// A circle outline `width` pixels wide.
void ring(Image& img, glm::vec2 center, float radius, float width, const Rgb& color, float opacity = 1.0f);
// A filled polygon (even-odd rule), 4x4 samples per pixel for the edges.
void polygon(Image& img, const std::vector<glm::vec2>& points, const Rgb& color, float opacity = 1.0f);
void rect(Image& img, int x0, int y0, int x1, int y1, const Rgb& color);
// stb_easy_font text with its top left at (x, y), each font pixel `scale` pixels wide.
void text(Image& img, int x, int y, const std::string& s, const Rgb& color, int scale = 1);
int textWidth(const std::string& s);  // in font pixels (multiply by the scale)

}  // namespace kinema::raster
