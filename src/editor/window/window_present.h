#pragma once
#include <vector>

#include "render/pixel_rect.h"

struct GLFWwindow;

namespace kinema {

// How a drawn frame reaches the screen. A swap shows the whole back buffer: Mesa's software
// GLX sends every pixel of it to the X server (0.3 ms at 1280 x 800, as much as an empty
// ImGui frame draws). Where the back buffer is kept between frames (backBufferSurvivesSwaps)
// and GLX_MESA_copy_sub_buffer is offered, a frame drawn only where it changed shows just
// those rectangles (glXCopySubBufferMESA, which flushes first and leaves the back buffer as
// it is), and a frame that changed nothing shows nothing new. The whole buffer is still
// swapped for the first frame, after a resize and after the X server lost the window's
// pixels (an expose: markExposed).
class WindowPresenter {
 public:
  // Looks up the extension through the window's current GLX context; `backBufferKept` as
  // probed for the window. Without both, present() always swaps.
  WindowPresenter(GLFWwindow* window, bool backBufferKept);

  // The window's pixels were lost or covered (GLFW's refresh callback): the next present()
  // shows the whole buffer.
  void markExposed() { whole_ = true; }
  // Shows the back buffer. `rects` (framebuffer pixels, rows from the bottom, disjoint): the
  // only parts that differ from what the window shows, or null when the frame was drawn
  // whole. Returns true when it copied rectangles (or nothing) instead of swapping.
  bool present(const std::vector<PixelRect>* rects, int framebufferWidth, int framebufferHeight);

 private:
  using CopySubBuffer = void (*)(void* display, unsigned long drawable, int x, int y, int width, int height);
  GLFWwindow* window_ = nullptr;
  CopySubBuffer copySubBuffer_ = nullptr;
  void* display_ = nullptr;
  unsigned long drawable_ = 0;
  bool whole_ = true;
  int width_ = -1, height_ = -1;  // the framebuffer size last shown whole
};

}  // namespace kinema
