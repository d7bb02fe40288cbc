#include "editor/window/back_buffer_probe.h"

#include <glad/gl.h>
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include <vector>

namespace kinema {

bool backBufferSurvivesSwaps(GLFWwindow* window) {
  int w = 0, h = 0;
  glfwGetFramebufferSize(window, &w, &h);
  if (w <= 0 || h <= 0) return false;
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  glViewport(0, 0, w, h);
  glDisable(GL_SCISSOR_TEST);
  glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  std::vector<unsigned char> pixels(static_cast<size_t>(w) * h * 4);
  bool kept = true;
  for (const int grey : {60, 61}) {
    glClearColor(grey / 255.0f, grey / 255.0f, grey / 255.0f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT);
    glfwSwapBuffers(window);
    glReadBuffer(GL_BACK);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glReadPixels(0, 0, w, h, GL_RGBA, GL_UNSIGNED_BYTE, pixels.data());
    for (size_t i = 0; i < pixels.size() && kept; i += 4)
      kept = pixels[i] == grey && pixels[i + 1] == grey && pixels[i + 2] == grey;
  }
  return kept && glGetError() == GL_NO_ERROR;
}

}  // namespace kinema
