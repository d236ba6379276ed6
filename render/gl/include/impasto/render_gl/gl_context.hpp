#pragma once
// Headless OpenGL contexts: render without a window (tests, `impasto render --gpu`,
// benchmarks). EGL surfaceless is preferred; OSMesa is the fallback.
#include <memory>
#include <string>

namespace impasto::render_gl {

enum class HeadlessBackend {
  kAuto,    // EGL surfaceless, else OSMesa
  kEgl,     // EGL on Mesa's surfaceless platform (a pbuffer-capable config, no surface)
  kOsMesa,  // Mesa's off-screen library
};

// An OpenGL 4.5 core context with no window. Draw into a Framebuffer; the default
// framebuffer is not usable. One context per thread at a time.
class GlContext {
 public:
  virtual ~GlContext() = default;
  GlContext(const GlContext&) = delete;
  GlContext& operator=(const GlContext&) = delete;

  // Makes the context current on the calling thread (and loads GL entry points for it).
  virtual void make_current() = 0;
  // "egl" or "osmesa".
  virtual std::string backend_name() const = 0;

 protected:
  GlContext() = default;
};

// A current headless context; throws std::runtime_error saying why none could be made.
std::unique_ptr<GlContext> create_headless_context(
    HeadlessBackend backend = HeadlessBackend::kAuto);

}  // namespace impasto::render_gl
