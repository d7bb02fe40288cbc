#pragma once
#include <string>

#include <glad/gl.h>

namespace kinema {

// The editor's 3D view drawn into a framebuffer of its own (the window's has one sample per
// pixel): a multisampled colour + depth target for the still picture, resolved into a
// single-sample copy that is copied into the window and kept, so a frame where nothing in
// the view changed shows the copy again without drawing. With one sample it is also the
// whole window's kept copy for changed-only redraws where the window's back buffer does not
// survive a swap (window_redraw.h): drawn into, then presented whole. Sizes are framebuffer
// pixels. Create, use and destroy it with one context current.
class ViewportTarget {
 public:
  ViewportTarget() = default;
  ~ViewportTarget();
  ViewportTarget(const ViewportTarget&) = delete;
  ViewportTarget& operator=(const ViewportTarget&) = delete;

  // Binds a width x height target with up to `samples` samples per pixel (as many as the
  // driver offers) for drawing, made anew when the size or the count changed. Empty string
  // on success.
  std::string begin(int width, int height, int samples);
  // Resolves what was drawn since begin() into the kept single-sample copy.
  void resolve();
  // Copies the kept picture into framebuffer `into` (0: the window's) with its lower left
  // corner at x, y, within the scissor box when GL_SCISSOR_TEST is on; leaves `into` bound.
  void present(int x, int y, GLuint into = 0) const;
  // True when a resolved picture of this size is kept.
  bool holds(int width, int height) const { return resolved_ && width == width_ && height == height_; }
  void forget() { resolved_ = false; }
  int samples() const { return samples_; }  // of the target begin() bound last
  // The framebuffer begin() bound for drawing (the kept one with one sample).
  GLuint boundFramebuffer() const { return samples_ > 1 ? drawFbo_ : keptFbo_; }

 private:
  void release();
  int width_ = 0, height_ = 0, samples_ = 0, requested_ = -1;
  bool resolved_ = false;
  GLuint drawFbo_ = 0, color_ = 0, depth_ = 0;    // multisampled (none when one sample)
  GLuint keptFbo_ = 0, keptColor_ = 0, keptDepth_ = 0;  // single sample: the picture shown
};

}  // namespace kinema
