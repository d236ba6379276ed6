// Mesa's off-screen library: a GL 4.5 core context rendering into client memory. Only the
// fallback: Dear ImGui's GL backend does not run on it, EGL surfaceless does.
#include <stdexcept>

#include "headless_backends.hpp"
#include "proc_loader.hpp"

#ifdef IMPASTO_HAVE_OSMESA
#include <GL/osmesa.h>

#include <vector>

namespace impasto::render_gl {
namespace {

class OsMesaContext final : public GlContext {
 public:
  OsMesaContext() {
    const int attributes[] = {OSMESA_FORMAT,
                              OSMESA_RGBA,
                              OSMESA_DEPTH_BITS,
                              0,
                              OSMESA_PROFILE,
                              OSMESA_CORE_PROFILE,
                              OSMESA_CONTEXT_MAJOR_VERSION,
                              4,
                              OSMESA_CONTEXT_MINOR_VERSION,
                              5,
                              0};
    context_ = OSMesaCreateContextAttribs(attributes, nullptr);
    if (!context_) throw std::runtime_error("OSMesa: could not create a GL 4.5 core context");
  }

  ~OsMesaContext() override { OSMesaDestroyContext(context_); }

  void make_current() override {
    // OSMesa needs a colour buffer to be current; Impasto draws into framebuffer objects.
    if (!OSMesaMakeCurrent(context_, backing_.data(), GL_UNSIGNED_BYTE, 1, 1)) {
      throw std::runtime_error("OSMesa: OSMesaMakeCurrent failed");
    }
    load_gl_entry_points(reinterpret_cast<GlProcLoader>(&OSMesaGetProcAddress));
  }

  std::string backend_name() const override { return "osmesa"; }

 private:
  OSMesaContext context_ = nullptr;
  std::vector<unsigned char> backing_ = std::vector<unsigned char>(4);
};

}  // namespace

std::unique_ptr<GlContext> create_osmesa_context() {
  auto context = std::make_unique<OsMesaContext>();
  context->make_current();
  return context;
}

}  // namespace impasto::render_gl

#else

namespace impasto::render_gl {
std::unique_ptr<GlContext> create_osmesa_context() {
  throw std::runtime_error("OSMesa: this build has no OSMesa (install libosmesa6-dev)");
}
}  // namespace impasto::render_gl

#endif
