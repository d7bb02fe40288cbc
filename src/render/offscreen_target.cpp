#include "render/offscreen_target.h"

#include <algorithm>

namespace kinema {

OffscreenTarget::~OffscreenTarget() {
  const GLuint fbos[] = {drawFbo_, resolveFbo_};
  const GLuint rbs[] = {color_, depth_, resolveColor_};
  glDeleteFramebuffers(2, fbos);
  glDeleteRenderbuffers(3, rbs);
}

std::string OffscreenTarget::create(int width, int height, int maxSamples) {
  width_ = width;
  height_ = height;
  GLint driverMax = 0;
  glGetIntegerv(GL_MAX_SAMPLES, &driverMax);
  samples_ = std::max(0, std::min(maxSamples, static_cast<int>(driverMax)));

  // Large targets may be beyond what the driver can multisample (llvmpipe keeps each
  // buffer under 2 GiB): fewer samples, down to none, before giving up.
  for (;;) {
    glGenRenderbuffers(1, &color_);
    glBindRenderbuffer(GL_RENDERBUFFER, color_);
    glRenderbufferStorageMultisample(GL_RENDERBUFFER, samples_, GL_RGBA8, width, height);
    glGenRenderbuffers(1, &depth_);
    glBindRenderbuffer(GL_RENDERBUFFER, depth_);
    glRenderbufferStorageMultisample(GL_RENDERBUFFER, samples_, GL_DEPTH_COMPONENT24, width, height);
    glGenFramebuffers(1, &drawFbo_);
    glBindFramebuffer(GL_FRAMEBUFFER, drawFbo_);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, color_);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, depth_);
    if (glCheckFramebufferStatus(GL_FRAMEBUFFER) == GL_FRAMEBUFFER_COMPLETE) break;
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    glDeleteFramebuffers(1, &drawFbo_);
    const GLuint rbs[] = {color_, depth_};
    glDeleteRenderbuffers(2, rbs);
    drawFbo_ = color_ = depth_ = 0;
    for (int k = 0; k < 16 && glGetError() != GL_NO_ERROR; ++k) {
    }
    if (samples_ == 0)
      return "the driver cannot make a " + std::to_string(width) + "x" + std::to_string(height) + " framebuffer";
    samples_ /= 2;
    if (samples_ == 1) samples_ = 0;
  }

  glGenRenderbuffers(1, &resolveColor_);
  glBindRenderbuffer(GL_RENDERBUFFER, resolveColor_);
  glRenderbufferStorage(GL_RENDERBUFFER, GL_RGBA8, width, height);
  glGenFramebuffers(1, &resolveFbo_);
  glBindFramebuffer(GL_FRAMEBUFFER, resolveFbo_);
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, resolveColor_);
  if (glCheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE)
    return "the driver cannot make a " + std::to_string(width) + "x" + std::to_string(height) + " resolve framebuffer";
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  return {};
}

void OffscreenTarget::bind() const { glBindFramebuffer(GL_FRAMEBUFFER, drawFbo_); }

Image OffscreenTarget::read() const {
  glBindFramebuffer(GL_READ_FRAMEBUFFER, drawFbo_);
  glBindFramebuffer(GL_DRAW_FRAMEBUFFER, resolveFbo_);
  glBlitFramebuffer(0, 0, width_, height_, 0, 0, width_, height_, GL_COLOR_BUFFER_BIT, GL_NEAREST);
  glBindFramebuffer(GL_READ_FRAMEBUFFER, resolveFbo_);
  Image image(width_, height_);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glReadPixels(0, 0, width_, height_, GL_RGBA, GL_UNSIGNED_BYTE, image.rgba.data());
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  image.flipVertically();
  return image;
}

}  // namespace kinema
