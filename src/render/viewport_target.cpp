#include "render/viewport_target.h"

#include <algorithm>

namespace kinema {

ViewportTarget::~ViewportTarget() { release(); }

void ViewportTarget::release() {
  const GLuint fbos[] = {drawFbo_, keptFbo_};
  const GLuint rbs[] = {color_, depth_, keptColor_, keptDepth_};
  glDeleteFramebuffers(2, fbos);
  glDeleteRenderbuffers(4, rbs);
  drawFbo_ = color_ = depth_ = keptFbo_ = keptColor_ = keptDepth_ = 0;
  resolved_ = false;
}

namespace {
GLuint renderbuffer(GLenum format, int samples, int width, int height) {
  GLuint rb = 0;
  glGenRenderbuffers(1, &rb);
  glBindRenderbuffer(GL_RENDERBUFFER, rb);
  if (samples > 1)
    glRenderbufferStorageMultisample(GL_RENDERBUFFER, samples, format, width, height);
  else
    glRenderbufferStorage(GL_RENDERBUFFER, format, width, height);
  return rb;
}
GLuint framebuffer(GLuint color, GLuint depth) {
  GLuint fbo = 0;
  glGenFramebuffers(1, &fbo);
  glBindFramebuffer(GL_FRAMEBUFFER, fbo);
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, color);
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, depth);
  return fbo;
}
}  // namespace

std::string ViewportTarget::begin(int width, int height, int samples) {
  width = std::max(width, 1);
  height = std::max(height, 1);
  if (width != width_ || height != height_ || samples != requested_) {
    release();
    GLint driverMax = 0;
    glGetIntegerv(GL_MAX_SAMPLES, &driverMax);
    width_ = width;
    height_ = height;
    requested_ = samples;
    samples_ = std::max(1, std::min(samples, static_cast<int>(driverMax)));
    keptColor_ = renderbuffer(GL_RGBA8, 1, width, height);
    keptDepth_ = renderbuffer(GL_DEPTH_COMPONENT24, 1, width, height);
    keptFbo_ = framebuffer(keptColor_, keptDepth_);
    if (samples_ > 1) {
      color_ = renderbuffer(GL_RGBA8, samples_, width, height);
      depth_ = renderbuffer(GL_DEPTH_COMPONENT24, samples_, width, height);
      drawFbo_ = framebuffer(color_, depth_);
    }
    const bool complete = glCheckFramebufferStatus(GL_FRAMEBUFFER) == GL_FRAMEBUFFER_COMPLETE;
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    if (!complete) {
      const std::string what = std::to_string(width) + "x" + std::to_string(height) + " with " +
                               std::to_string(samples_) + " samples";
      release();
      requested_ = -1;
      return "the driver cannot make the 3D view's framebuffer (" + what + ")";
    }
  }
  resolved_ = false;
  glBindFramebuffer(GL_FRAMEBUFFER, samples_ > 1 ? drawFbo_ : keptFbo_);
  return {};
}

void ViewportTarget::resolve() {
  if (samples_ > 1) {
    glBindFramebuffer(GL_READ_FRAMEBUFFER, drawFbo_);
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, keptFbo_);
    glBlitFramebuffer(0, 0, width_, height_, 0, 0, width_, height_, GL_COLOR_BUFFER_BIT, GL_NEAREST);
  }
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  resolved_ = keptFbo_ != 0;
}

void ViewportTarget::present(int x, int y, GLuint into) const {
  if (!resolved_) return;
  glBindFramebuffer(GL_READ_FRAMEBUFFER, keptFbo_);
  glBindFramebuffer(GL_DRAW_FRAMEBUFFER, into);
  glBlitFramebuffer(0, 0, width_, height_, x, y, x + width_, y + height_, GL_COLOR_BUFFER_BIT, GL_NEAREST);
  glBindFramebuffer(GL_FRAMEBUFFER, into);
}

}  // namespace kinema
