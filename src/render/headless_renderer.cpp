#include "render/headless_renderer.h"

namespace kinema {

Result<std::unique_ptr<HeadlessRenderer>> HeadlessRenderer::open(HeadlessBackend backend, int width, int height) {
  using R = Result<std::unique_ptr<HeadlessRenderer>>;
  Result<std::unique_ptr<HeadlessContext>> context = createHeadlessContext(backend);
  if (!context) return R::failure(context.error());
  std::unique_ptr<HeadlessRenderer> r(new HeadlessRenderer());
  r->context_ = std::move(context.value());
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
