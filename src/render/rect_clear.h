#pragma once
#include <string>
#include <vector>

#include <glad/gl.h>
#include <glm/vec4.hpp>

#include "render/pixel_rect.h"
#include "render/shader_program.h"

namespace kinema {

// Clears rectangles of the bound framebuffer to a colour and the far depth (1.0, what
// glClearDepth(1.0) gives), all of them in one draw call; the stencil is left alone. Mesa's
// state tracker turns every scissored glClear into a quad of its own, with the whole pipeline
// state saved and restored around it: for the editor's changed-only frames (a few rectangles
// each) one draw of its own is cheaper on llvmpipe (docs/editor-panels.md has the figure).
// Rectangles are framebuffer pixels, rows from the bottom, within framebufferWidth x Height,
// the viewport covering that framebuffer.
// Afterwards: this program and vertex array bound, depth test on with GL_LESS and depth
// writes on, blending, face culling and the scissor test off, every colour channel written.
class RectClear {
 public:
  RectClear() = default;
  ~RectClear();
  RectClear(const RectClear&) = delete;
  RectClear& operator=(const RectClear&) = delete;

  // Compiles the program and makes the buffers with the current context; empty on success.
  std::string init();
  void clear(const std::vector<PixelRect>& rects, int framebufferWidth, int framebufferHeight, const glm::vec4& color);

 private:
  ShaderProgram program_;
  GLuint vao_ = 0, vertices_ = 0;
  std::vector<float> corners_;  // two triangles a rectangle, x y in pixels, kept between frames
};

}  // namespace kinema
