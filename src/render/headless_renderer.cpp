#include "render/headless_renderer.h"

#include <algorithm>

namespace kinema {

RenderSizeLimit queryRenderSizeLimit() {
  GLint texture = 0, renderbuffer = 0, viewport[2] = {0, 0};
  glGetIntegerv(GL_MAX_TEXTURE_SIZE, &texture);
  glGetIntegerv(GL_MAX_RENDERBUFFER_SIZE, &renderbuffer);
  glGetIntegerv(GL_MAX_VIEWPORT_DIMS, viewport);
  RenderSizeLimit limit;
  const GLubyte* name = glGetString(GL_RENDERER);
  limit.renderer = name ? reinterpret_cast<const char*>(name) : "unknown renderer";
  limit.width = std::min({texture, renderbuffer, viewport[0]});
  limit.height = std::min({texture, renderbuffer, viewport[1]});
  const int smallest = std::min(limit.width, limit.height);
  limit.limitedBy = smallest == renderbuffer ? "GL_MAX_RENDERBUFFER_SIZE " + std::to_string(renderbuffer)
                    : smallest == texture    ? "GL_MAX_TEXTURE_SIZE " + std::to_string(texture)
                                             : "GL_MAX_VIEWPORT_DIMS " + std::to_string(viewport[0]) + "x" +
                                                   std::to_string(viewport[1]);
  return limit;
}

Result<std::unique_ptr<HeadlessRenderer>> HeadlessRenderer::open(HeadlessBackend backend, int width, int height,
                                                                 RenderSizeLimit* largest) {
  using R = Result<std::unique_ptr<HeadlessRenderer>>;
  Result<std::unique_ptr<HeadlessContext>> context = createHeadlessContext(backend);
  if (!context) return R::failure(context.error());
  std::unique_ptr<HeadlessRenderer> r(new HeadlessRenderer());
  r->context_ = std::move(context.value());
  const RenderSizeLimit limit = queryRenderSizeLimit();
  if (largest) *largest = limit;
  if (limit.known() && (width > limit.width || height > limit.height))
    return R::failure(std::string(r->context_->backendName()) + ": " + std::to_string(width) + "x" +
                      std::to_string(height) + " is larger than " + limit.renderer + " makes (at most " +
                      std::to_string(limit.width) + "x" + std::to_string(limit.height) + ", " + limit.limitedBy + ")");
  r->width_ = width;
  r->height_ = height;
  r->renderer_ = std::make_unique<SkeletonRenderer>();
  std::string error = r->renderer_->init();
  r->meshes_ = std::make_unique<MeshRenderer>();
  if (error.empty()) error = r->meshes_->init();
  if (error.empty()) {
    r->target_ = std::make_unique<OffscreenTarget>();
    error = r->target_->create(width, height);
  }
  if (!error.empty()) return R::failure(std::string(r->context_->backendName()) + ": " + error);
  return r;
}

Image HeadlessRenderer::render(FrameDescription frame) {
  frame.x = frame.y = 0;
  frame.width = width_;
  frame.height = height_;
  target_->bind();
  renderer_->draw(frame);
  return target_->read();
}

}  // namespace kinema
