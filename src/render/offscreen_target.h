#pragma once
#include <string>

#include <glad/gl.h>

#include "io/image.h"

namespace kinema {

// A framebuffer object to draw into without a window: a multisampled colour + depth target
// (up to 4 samples, as many as the driver offers) resolved into a plain one for reading.
class OffscreenTarget {
 public:
  OffscreenTarget() = default;
  ~OffscreenTarget();
  OffscreenTarget(const OffscreenTarget&) = delete;
  OffscreenTarget& operator=(const OffscreenTarget&) = delete;

  // Creates the buffers with the current context; empty string on success.
  std::string create(int width, int height, int maxSamples = 4);
  void bind() const;  // as the draw framebuffer
  // Resolves the samples and reads the pixels, top row first.
  Image read() const;
  int samples() const { return samples_; }

 private:
  int width_ = 0, height_ = 0, samples_ = 0;
  GLuint drawFbo_ = 0, color_ = 0, depth_ = 0;
  GLuint resolveFbo_ = 0, resolveColor_ = 0;
};

}  // namespace kinema
