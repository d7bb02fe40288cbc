#include "io/image.h"

#include <stb_image.h>
#include <stb_image_write.h>

#include <algorithm>
#include <cstdint>
#include <cstdlib>

#include "io/atomic_write.h"
#include "io/input_limits.h"
#include "io/message_text.h"
#include "io/text_file.h"

namespace kinema {

void Image::flipVertically() {
  const size_t row = static_cast<size_t>(width) * 4;
  for (int y = 0; y < height / 2; ++y)
    std::swap_ranges(rgba.begin() + y * row, rgba.begin() + (y + 1) * row, rgba.begin() + (height - 1 - y) * row);
}

std::string savePng(const std::string& path, const Image& image) {
  if (image.width <= 0 || image.height <= 0 || image.rgba.size() != static_cast<size_t>(image.width) * image.height * 4)
    return path + ": not saved: the image is empty or its size is inconsistent";
  std::string bytes;
  auto append = [](void* context, void* data, int size) {
    static_cast<std::string*>(context)->append(static_cast<const char*>(data), static_cast<size_t>(size));
  };
  if (!stbi_write_png_to_func(append, &bytes, image.width, image.height, 4, image.rgba.data(), image.width * 4))
    return path + ": PNG encoding failed";
  return writeFileAtomically(path, bytes);
}

Result<Image> loadPng(const std::string& path) {
  // Through the readers' checks (regular files only, the size cap) and the image budget.
  std::string bytes;
  const InputLimits limits;
  if (std::string e = readTextFile(path, bytes, limits.maxFileBytes); !e.empty()) return Result<Image>::failure(e);
  Image image;
  if (!pngSize(bytes, image.width, image.height)) return Result<Image>::failure(path + ": not a PNG image");
  if (static_cast<size_t>(image.width) * static_cast<size_t>(image.height) * 4 > imageBudgetBytes(bytes.size(), limits))
    return Result<Image>::failure(path + ": " + std::to_string(image.width) + " x " + std::to_string(image.height) +
                                  " pixels would take more than the file's size + " +
                                  std::to_string(limits.imageBytesOverFileSize >> 20) +
                                  " MB (InputLimits::imageBytesOverFileSize)");
  if (!decodePng(bytes, image.width, image.height, image.rgba))
    return Result<Image>::failure(path + ": cannot read PNG: " + cutForMessage(stbi_failure_reason() ? stbi_failure_reason() : "not a PNG image"));
  return image;
}

std::string encodePng(int width, int height, const std::uint8_t* rgba) {
  std::string bytes;
  if (width <= 0 || height <= 0) return bytes;
  auto append = [](void* context, void* data, int size) {
    static_cast<std::string*>(context)->append(static_cast<const char*>(data), static_cast<size_t>(size));
  };
  if (!stbi_write_png_to_func(append, &bytes, width, height, 4, rgba, width * 4)) bytes.clear();
  return bytes;
}

bool decodePng(const std::string& bytes, int& width, int& height, std::vector<std::uint8_t>& rgba) {
  if (bytes.empty() || bytes.size() > static_cast<size_t>(INT32_MAX)) return false;
  int channels = 0;
  const auto* bytesIn = reinterpret_cast<const unsigned char*>(bytes.data());
  // The header's size is checked before decoding: a file must not make us allocate gigabytes.
  if (!stbi_info_from_memory(bytesIn, static_cast<int>(bytes.size()), &width, &height, &channels) ||
      static_cast<long long>(width) * height > (1LL << 26))
    return false;
  unsigned char* data = stbi_load_from_memory(reinterpret_cast<const unsigned char*>(bytes.data()),
                                              static_cast<int>(bytes.size()), &width, &height, &channels, 4);
  if (!data) return false;
  rgba.assign(data, data + static_cast<size_t>(width) * height * 4);
  stbi_image_free(data);
  return true;
}

}  // namespace kinema

namespace kinema {

bool pngSize(const std::string& bytes, int& width, int& height) {
  int channels = 0;
  if (bytes.empty() || bytes.size() > static_cast<size_t>(INT32_MAX)) return false;
  return stbi_info_from_memory(reinterpret_cast<const unsigned char*>(bytes.data()), static_cast<int>(bytes.size()),
                               &width, &height, &channels) != 0 &&
         width > 0 && height > 0;
}

}  // namespace kinema
