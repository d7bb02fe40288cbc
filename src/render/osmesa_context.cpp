// Headless OpenGL through OSMesa, Mesa's off-screen software renderer (toolchain.md). Built
// only with KINEMA_WITH_OSMESA; OSMesa is deprecated upstream, so it stays optional.
#include "render/gl_context.h"

#ifdef KINEMA_HAVE_OSMESA
// glad first: it stands in for GL/gl.h, which osmesa.h would otherwise include.
#include <glad/gl.h>
#include <GL/osmesa.h>

#include <vector>
#endif

namespace kinema {

#ifdef KINEMA_HAVE_OSMESA
namespace {

class OsMesaContext : public HeadlessContext {
 public:
  ~OsMesaContext() override {
    if (context_) OSMesaDestroyContext(context_);
  }
  const char* backendName() const override { return "osmesa"; }

  std::string open() {
    const int attributes[] = {OSMESA_FORMAT, OSMESA_RGBA, OSMESA_DEPTH_BITS, 24, OSMESA_STENCIL_BITS, 8,
                              OSMESA_PROFILE, OSMESA_CORE_PROFILE, OSMESA_CONTEXT_MAJOR_VERSION, 3,
                              OSMESA_CONTEXT_MINOR_VERSION, 3, 0};
    context_ = OSMesaCreateContextAttribs(attributes, nullptr);
    if (!context_) return "OSMesa cannot create an OpenGL 3.3 core context";
    // OSMesa needs a colour buffer to be current; rendering goes to our own framebuffer.
    buffer_.assign(16 * 16 * 4, 0);
    if (!OSMesaMakeCurrent(context_, buffer_.data(), GL_UNSIGNED_BYTE, 16, 16))
      return "OSMesa cannot make its context current";
    const int version = gladLoadGL(reinterpret_cast<GLADloadfunc>(OSMesaGetProcAddress));
    if (GLAD_VERSION_MAJOR(version) * 10 + GLAD_VERSION_MINOR(version) < 33)
      return "OSMesa gave an OpenGL context older than 3.3";
    return {};
  }

 private:
  OSMesaContext context_ = nullptr;
  std::vector<unsigned char> buffer_;
};

}  // namespace

bool osMesaAvailable() { return true; }

Result<std::unique_ptr<HeadlessContext>> createOsMesaContext() {
  auto context = std::make_unique<OsMesaContext>();
  const std::string error = context->open();
  if (!error.empty()) return Result<std::unique_ptr<HeadlessContext>>::failure(error);
  return std::unique_ptr<HeadlessContext>(std::move(context));
}
#else
bool osMesaAvailable() { return false; }

Result<std::unique_ptr<HeadlessContext>> createOsMesaContext() {
  return Result<std::unique_ptr<HeadlessContext>>::failure(
      "this kinema was built without OSMesa (configure with libosmesa6-dev installed and -DKINEMA_WITH_OSMESA=ON)");
}
#endif

}  // namespace kinema
