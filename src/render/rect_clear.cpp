#include "render/rect_clear.h"

namespace kinema {

namespace {

// Pixels to clip space at the far plane (z = w: window depth 1.0 in the default depth range).
const char* const kVertex = R"(#version 330 core
layout(location = 0) in vec2 aPixel;
uniform vec2 uSize;
void main() { gl_Position = vec4(aPixel / uSize * 2.0 - 1.0, 1.0, 1.0); }
)";
const char* const kFragment = R"(#version 330 core
uniform vec4 uColor;
out vec4 fragColor;
void main() { fragColor = uColor; }
)";

}  // namespace

RectClear::~RectClear() {
  if (vao_) glDeleteVertexArrays(1, &vao_);
  if (vertices_) glDeleteBuffers(1, &vertices_);
}

std::string RectClear::init() {
  if (const std::string error = program_.build("rect_clear", kVertex, kFragment); !error.empty()) return error;
  glGenVertexArrays(1, &vao_);
  glGenBuffers(1, &vertices_);
  glBindVertexArray(vao_);
  glBindBuffer(GL_ARRAY_BUFFER, vertices_);
  glEnableVertexAttribArray(0);
  glVertexAttribPointer(0, 2, GL_FLOAT, GL_FALSE, 2 * sizeof(float), nullptr);
  glBindVertexArray(0);
  return "";
}

void RectClear::clear(const std::vector<PixelRect>& rects, int framebufferWidth, int framebufferHeight,
                      const glm::vec4& color) {
  corners_.clear();
  for (const PixelRect& r : rects) {
    if (r.empty()) continue;
    const float x0 = float(r.x0), y0 = float(r.y0), x1 = float(r.x1), y1 = float(r.y1);
    corners_.insert(corners_.end(), {x0, y0, x1, y0, x1, y1, x0, y0, x1, y1, x0, y1});
  }
  glDisable(GL_SCISSOR_TEST);
  glDisable(GL_BLEND);
  glDisable(GL_CULL_FACE);
  glEnable(GL_DEPTH_TEST);
  glDepthMask(GL_TRUE);
  glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  glUseProgram(program_.id());
  glBindVertexArray(vao_);
  if (!corners_.empty()) {
    glUniform2f(program_.uniform("uSize"), float(framebufferWidth), float(framebufferHeight));
    glUniform4f(program_.uniform("uColor"), color.r, color.g, color.b, color.a);
    glBindBuffer(GL_ARRAY_BUFFER, vertices_);
    glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(corners_.size() * sizeof(float)), corners_.data(),
                 GL_STREAM_DRAW);
    glDepthFunc(GL_ALWAYS);  // every pixel of a rectangle, whatever depth it held
    glDrawArrays(GL_TRIANGLES, 0, static_cast<GLsizei>(corners_.size() / 2));
  }
  glDepthFunc(GL_LESS);
}

}  // namespace kinema
