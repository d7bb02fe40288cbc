#pragma once
#include <string>
#include <vector>

#include <glad/gl.h>

namespace kinema {

// A linked GLSL program. Owns the GL object; the context that made it must be current when
// it is destroyed.
class ShaderProgram {
 public:
  ShaderProgram() = default;
  ~ShaderProgram();
  ShaderProgram(const ShaderProgram&) = delete;
  ShaderProgram& operator=(const ShaderProgram&) = delete;

  // Compiles and links; returns an empty string or the driver's log with the shader's name.
  // `feedbackVaryings`: vertex outputs captured by transform feedback (interleaved); they
  // must be named before linking.
  std::string build(const char* name, const char* vertexSource, const char* fragmentSource,
                    const std::vector<const char*>& feedbackVaryings = {});
  GLuint id() const { return id_; }
  GLint uniform(const char* name) const { return glGetUniformLocation(id_, name); }

 private:
  GLuint id_ = 0;
};

}  // namespace kinema
