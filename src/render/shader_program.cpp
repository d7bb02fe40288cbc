#include "render/shader_program.h"

#include <vector>

namespace kinema {

namespace {
std::string compile(GLenum type, const char* source, GLuint& shader) {
  shader = glCreateShader(type);
  glShaderSource(shader, 1, &source, nullptr);
  glCompileShader(shader);
  GLint ok = 0;
  glGetShaderiv(shader, GL_COMPILE_STATUS, &ok);
  if (ok) return {};
  GLint length = 0;
  glGetShaderiv(shader, GL_INFO_LOG_LENGTH, &length);
  std::vector<char> log(static_cast<size_t>(std::max(length, 1)), '\0');
  glGetShaderInfoLog(shader, length, nullptr, log.data());
  return std::string(type == GL_VERTEX_SHADER ? "vertex" : "fragment") + " shader: " + log.data();
}
}  // namespace

ShaderProgram::~ShaderProgram() {
  if (id_) glDeleteProgram(id_);
}

std::string ShaderProgram::build(const char* name, const char* vertexSource, const char* fragmentSource,
                                 const std::vector<const char*>& feedbackVaryings) {
  GLuint vs = 0, fs = 0;
  std::string error = compile(GL_VERTEX_SHADER, vertexSource, vs);
  if (error.empty()) error = compile(GL_FRAGMENT_SHADER, fragmentSource, fs);
  if (error.empty()) {
    id_ = glCreateProgram();
    glAttachShader(id_, vs);
    glAttachShader(id_, fs);
    if (!feedbackVaryings.empty())
      glTransformFeedbackVaryings(id_, static_cast<GLsizei>(feedbackVaryings.size()), feedbackVaryings.data(),
                                  GL_INTERLEAVED_ATTRIBS);
    glLinkProgram(id_);
    GLint ok = 0;
    glGetProgramiv(id_, GL_LINK_STATUS, &ok);
    if (!ok) {
      char log[2048] = {};
      glGetProgramInfoLog(id_, sizeof log, nullptr, log);
      error = std::string("link: ") + log;
      glDeleteProgram(id_);
      id_ = 0;
    }
  }
  if (vs) glDeleteShader(vs);
  if (fs) glDeleteShader(fs);
  if (!error.empty()) {
    while (!error.empty() && (error.back() == '\n' || error.back() == '\r')) error.pop_back();
    return std::string("shader program ") + name + ": " + error;
  }
  return {};
}

}  // namespace kinema
