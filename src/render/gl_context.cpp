#include "render/gl_context.h"

#include <glad/gl.h>

namespace kinema {

std::string HeadlessContext::description() const {
  const char* renderer = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
  const char* version = reinterpret_cast<const char*>(glGetString(GL_VERSION));
  return std::string(renderer ? renderer : "?") + " | " + (version ? version : "?");
}

bool softwareRasterizer() {
  const char* renderer = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
  const std::string name = renderer ? renderer : "";
  return name.find("llvmpipe") != std::string::npos || name.find("softpipe") != std::string::npos;
}

Result<std::unique_ptr<HeadlessContext>> createHeadlessContext(HeadlessBackend backend) {
  return backend == HeadlessBackend::Egl ? createEglContext() : createOsMesaContext();
}

}  // namespace kinema
