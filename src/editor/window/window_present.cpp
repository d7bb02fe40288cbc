#include "editor/window/window_present.h"

#include <GLFW/glfw3.h>

namespace kinema {

WindowPresenter::WindowPresenter(GLFWwindow* window, bool backBufferKept) : window_(window) {
  // GLFW asks the context's platform (GLX here; an EGL context does not offer it). Through
  // GLX's own lookup, which also returns its core entry points: no GLX or X11 headers (they
  // would bring a gl.h before glad's) and nothing to link.
  if (!backBufferKept || !glfwExtensionSupported("GLX_MESA_copy_sub_buffer")) return;
  using GetDisplay = void* (*)();
  using GetDrawable = unsigned long (*)();
  const auto display = reinterpret_cast<GetDisplay>(glfwGetProcAddress("glXGetCurrentDisplay"));
  const auto drawable = reinterpret_cast<GetDrawable>(glfwGetProcAddress("glXGetCurrentDrawable"));
  const auto copy = reinterpret_cast<CopySubBuffer>(glfwGetProcAddress("glXCopySubBufferMESA"));
  if (!display || !drawable || !copy) return;
  display_ = display();
  drawable_ = drawable();
  if (display_ && drawable_) copySubBuffer_ = copy;
}

bool WindowPresenter::present(const std::vector<PixelRect>* rects, int framebufferWidth, int framebufferHeight) {
  const bool resized = framebufferWidth != width_ || framebufferHeight != height_;
  if (!copySubBuffer_ || !rects || whole_ || resized) {
    glfwSwapBuffers(window_);
    whole_ = false;
    width_ = framebufferWidth, height_ = framebufferHeight;
    return false;
  }
  for (const PixelRect& r : *rects)
    if (!r.empty()) copySubBuffer_(display_, drawable_, r.x0, r.y0, r.width(), r.height());
  return true;
}

}  // namespace kinema
