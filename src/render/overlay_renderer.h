#pragma once
#include <string>
#include <vector>

#include <glad/gl.h>

#include "render/overlay_draw_list.h"
#include "render/shader_program.h"

namespace kinema {

// Draws an OverlayDrawList with OpenGL 3.3 core. Wide lines and handles are expanded into
// triangles on the CPU in clip space (core profiles need not support glLineWidth > 1), so
// widths are exact pixels on every driver. Scene-layer items keep the depth test; OnTop
// items are drawn after with it off. Create, init() and destroy with the context current.
class OverlayRenderer {
 public:
  OverlayRenderer() = default;
  ~OverlayRenderer();
  OverlayRenderer(const OverlayRenderer&) = delete;
  OverlayRenderer& operator=(const OverlayRenderer&) = delete;

  std::string init();  // empty on success
  // `viewProjection` maps world to clip space; the viewport (width x height pixels) is bound.
  void draw(const OverlayDrawList& list, const glm::mat4& viewProjection, int width, int height);

  // One vertex of the triangles sent to the GPU: clip-space position and colour.
  struct Vertex {
    glm::vec4 clip;
    glm::vec4 color;
  };
  // The triangles for one layer (exposed for tests: pure CPU, no GL).
  static void appendTriangles(const OverlayDrawList& list, OverlayDrawList::Layer layer, const glm::mat4& viewProjection,
                              glm::vec2 viewportSize, std::vector<Vertex>& out);
  static void appendScreenTriangles(const OverlayDrawList& list, glm::vec2 viewportSize, std::vector<Vertex>& out);

 private:
  void upload(const std::vector<Vertex>& vertices);
  ShaderProgram program_;
  GLuint vao_ = 0, buffer_ = 0;
  std::vector<Vertex> scratch_;
};

}  // namespace kinema
