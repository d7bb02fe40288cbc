#pragma once
#include <memory>
#include <string>

#include "core/result.h"

namespace kinema {

// A headless OpenGL 3.3 core context, current on the calling thread from creation until it
// is destroyed, with glad loaded for it. Draw into an OffscreenTarget.
class HeadlessContext {
 public:
  virtual ~HeadlessContext() = default;
  virtual const char* backendName() const = 0;
  // GL_RENDERER and GL_VERSION, for messages ("llvmpipe (LLVM 15.0.6, 256 bits) | 4.5 ...").
  std::string description() const;
};

enum class HeadlessBackend { Egl, OsMesa };

// Whether the current context rasterises on the CPU (Mesa's llvmpipe or softpipe, by
// GL_RENDERER): where the editor deforms meshes on the CPU and redraws only what changed.
bool softwareRasterizer();

// EGL on Mesa's surfaceless platform (falling back to the device platform): no display,
// no window system, no GPU needed.
Result<std::unique_ptr<HeadlessContext>> createEglContext();
// OSMesa (software only); fails with a clear message when built without it.
Result<std::unique_ptr<HeadlessContext>> createOsMesaContext();
bool osMesaAvailable();

Result<std::unique_ptr<HeadlessContext>> createHeadlessContext(HeadlessBackend backend);

}  // namespace kinema
