#pragma once
#include <string>

#include <glad/gl.h>

namespace kinema {

// The editor's whole window drawn into a colour + depth framebuffer of its own, which keeps
// its pixels from one frame to the next (a window's back buffer is undefined after a swap):
// a frame redraws only the rectangles that changed and then copies the whole picture into
// the window, as Blender 2.7's "Triple Buffer" window draw method did. Sizes are
// framebuffer pixels. Create, use and destroy it with one context current.
class WindowCanvas {
 public:
  WindowCanvas() = default;
  ~WindowCanvas();
  WindowCanvas(const WindowCanvas&) = delete;
  WindowCanvas& operator=(const WindowCanvas&) = delete;

  // Binds a width x height canvas for drawing, made anew when the size changed. `kept` is
  // set when it still holds the previous frame's pixels (false after a new size or forget():
  // draw everything). Empty string on success.
  std::string begin(int width, int height, bool& kept);
  // Copies the whole canvas into the window's framebuffer (0) and leaves that bound.
  void present() const;
  GLuint framebuffer() const { return fbo_; }
  // The next begin() reports the pixels as lost (the caller drew elsewhere, or failed midway).
  void forget() { kept_ = false; }

 private:
  void release();
  int width_ = 0, height_ = 0;
  bool kept_ = false;
  GLuint fbo_ = 0, color_ = 0, depth_ = 0;
};

}  // namespace kinema
