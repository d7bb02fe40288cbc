#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include "core/result.h"

namespace kinema {

// An 8-bit RGBA image, rows top to bottom.
struct Image {
  int width = 0;
  int height = 0;
  std::vector<std::uint8_t> rgba;  // width * height * 4

  Image() = default;
  Image(int w, int h) : width(w), height(h), rgba(static_cast<size_t>(w) * h * 4, 0) {}
  std::uint8_t* pixel(int x, int y) { return &rgba[(static_cast<size_t>(y) * width + x) * 4]; }
  const std::uint8_t* pixel(int x, int y) const { return &rgba[(static_cast<size_t>(y) * width + x) * 4]; }
  // Reverses the row order (OpenGL reads pixels bottom row first).
  void flipVertically();
};

// PNG through Debian's stb. Saving goes through writeFileAtomically.
std::string savePng(const std::string& path, const Image& image);
Result<Image> loadPng(const std::string& path);
// PNG bytes in memory (glTF embeds textures, .kinema stores them as base64). The pixel
// arrays are width * height * 4 RGBA bytes, first row at the top.
std::string encodePng(int width, int height, const std::uint8_t* rgba);  // "" on failure
bool decodePng(const std::string& bytes, int& width, int& height, std::vector<std::uint8_t>& rgba);
// The size a PNG's header states, read without decoding (for memory budgets); false when
// the bytes are not an image stb reads.
bool pngSize(const std::string& bytes, int& width, int& height);

}  // namespace kinema
