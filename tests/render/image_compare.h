#pragma once
// Golden-image helpers shared by the render tests.
#include <gtest/gtest.h>

#include <cstdlib>
#include <string>

#include "io/image.h"

namespace kinema::test {

// Pixels that differ by more than `tolerance` in some channel; -1 when the sizes differ.
inline int differingPixels(const Image& a, const Image& b, int tolerance) {
  if (a.width != b.width || a.height != b.height) return -1;
  int n = 0;
  for (size_t i = 0; i < a.rgba.size(); i += 4)
    for (int c = 0; c < 4; ++c)
      if (std::abs(int(a.rgba[i + c]) - int(b.rgba[i + c])) > tolerance) {
        ++n;
        break;
      }
  return n;
}

// The PNG at `path`, or an empty image and a test failure naming why.
inline Image loadImageOrFail(const std::string& path) {
  Result<Image> image = loadPng(path);
  EXPECT_TRUE(image.ok()) << image.error();
  return image ? image.value() : Image();
}

}  // namespace kinema::test
