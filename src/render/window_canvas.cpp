#include "render/window_canvas.h"

#include <algorithm>

namespace kinema {

WindowCanvas::~WindowCanvas() { release(); }

void WindowCanvas::release() {
  glDeleteFramebuffers(1, &fbo_);
  const GLuint rbs[] = {color_, depth_};
  glDeleteRenderbuffers(2, rbs);
  fbo_ = color_ = depth_ = 0;
  width_ = height_ = 0;
  kept_ = false;
}

std::string WindowCanvas::begin(int width, int height, bool& kept) {
  width = std::max(width, 1);
  height = std::max(height, 1);
  if (width != width_ || height != height_ || !fbo_) {
    release();
    glGenRenderbuffers(1, &color_);
    glBindRenderbuffer(GL_RENDERBUFFER, color_);
    glRenderbufferStorage(GL_RENDERBUFFER, GL_RGBA8, width, height);
    glGenRenderbuffers(1, &depth_);
    glBindRenderbuffer(GL_RENDERBUFFER, depth_);
    glRenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH_COMPONENT24, width, height);
    glBindRenderbuffer(GL_RENDERBUFFER, 0);
    glGenFramebuffers(1, &fbo_);
    glBindFramebuffer(GL_FRAMEBUFFER, fbo_);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, color_);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, depth_);
    const bool complete = glCheckFramebufferStatus(GL_FRAMEBUFFER) == GL_FRAMEBUFFER_COMPLETE;
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    if (!complete) {
      release();
      kept = false;
      return "the driver cannot make the window's " + std::to_string(width) + "x" + std::to_string(height) +
             " framebuffer for partial redraws";
    }
    width_ = width;
    height_ = height;
  }
  kept = kept_;
  kept_ = true;
  glBindFramebuffer(GL_FRAMEBUFFER, fbo_);
  return {};
}

void WindowCanvas::present() const {
  if (!fbo_) return;
  glBindFramebuffer(GL_READ_FRAMEBUFFER, fbo_);
  glBindFramebuffer(GL_DRAW_FRAMEBUFFER, 0);
  glBlitFramebuffer(0, 0, width_, height_, 0, 0, width_, height_, GL_COLOR_BUFFER_BIT, GL_NEAREST);
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

}  // namespace kinema
