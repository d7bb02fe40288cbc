#pragma once
#include <memory>
#include <string>

#include "render/gl_context.h"
#include "render/mesh_renderer.h"
#include "render/offscreen_target.h"
#include "render/skeleton_renderer.h"

namespace kinema {

// The largest off-screen image the OpenGL implementation makes: the smallest of
// GL_MAX_TEXTURE_SIZE, GL_MAX_RENDERBUFFER_SIZE and GL_MAX_VIEWPORT_DIMS (pixels).
struct RenderSizeLimit {
  int width = 0, height = 0;  // 0 until a context has been opened
  std::string renderer;       // GL_RENDERER, for messages
  std::string limitedBy;      // which limit decided, e.g. "GL_MAX_RENDERBUFFER_SIZE 8192"
  bool known() const { return width > 0 && height > 0; }
};

// Reads RenderSizeLimit from the current context.
RenderSizeLimit queryRenderSizeLimit();

// A headless context, the renderer and an off-screen target of one size, kept together so
// a sequence reuses them frame after frame.
class HeadlessRenderer {
 public:
  // Fails before allocating anything when width x height is beyond the implementation's
  // limit; `largest`, when given, receives the limit once the context is open.
  static Result<std::unique_ptr<HeadlessRenderer>> open(HeadlessBackend backend, int width, int height,
                                                        RenderSizeLimit* largest = nullptr);
  // Draws the frame (its viewport is set to the whole target) and reads the pixels back.
  Image render(FrameDescription frame);
  const HeadlessContext& context() const { return *context_; }
  int samples() const { return target_->samples(); }
  // Meshes for FrameDescription::meshes: upload a scene once, then point frames at it.
  MeshRenderer& meshes() { return *meshes_; }

 private:
  // Declared first so it is destroyed last: the GL objects below need it current.
  std::unique_ptr<HeadlessContext> context_;
  std::unique_ptr<SkeletonRenderer> renderer_;
  std::unique_ptr<MeshRenderer> meshes_;
  std::unique_ptr<OffscreenTarget> target_;
  int width_ = 0, height_ = 0;
};

}  // namespace kinema
