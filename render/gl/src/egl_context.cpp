// EGL on Mesa's surfaceless platform: a GL 4.5 core context with no window and no X.
#include <EGL/egl.h>
#include <EGL/eglext.h>

#include <cstdio>
#include <stdexcept>
#include <string>

#include "headless_backends.hpp"
#include "proc_loader.hpp"

namespace impasto::render_gl {
namespace {

std::string egl_error(const char* call) {
  return std::string("EGL: ") + call + " failed (error 0x" + [] {
    char hex[16];
    std::snprintf(hex, sizeof hex, "%04X", static_cast<unsigned>(eglGetError()));
    return std::string(hex);
  }() + ")";
}

class EglContext final : public GlContext {
 public:
  EglContext() {
    auto get_platform_display = reinterpret_cast<PFNEGLGETPLATFORMDISPLAYEXTPROC>(
        eglGetProcAddress("eglGetPlatformDisplayEXT"));
    if (!get_platform_display) throw std::runtime_error("EGL: no eglGetPlatformDisplayEXT");
    display_ = get_platform_display(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr);
    if (display_ == EGL_NO_DISPLAY) throw std::runtime_error(egl_error("eglGetPlatformDisplay"));
    EGLint major = 0, minor = 0;
    if (!eglInitialize(display_, &major, &minor)) {
      throw std::runtime_error(egl_error("eglInitialize"));
    }
    try {
      create_context();
    } catch (...) {
      eglTerminate(display_);
      throw;
    }
  }

  ~EglContext() override {
    if (eglGetCurrentContext() == context_) {
      eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
    }
    eglDestroyContext(display_, context_);
    eglTerminate(display_);
    eglReleaseThread();
  }

  void make_current() override {
    if (!eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, context_)) {
      throw std::runtime_error(egl_error("eglMakeCurrent"));
    }
    load_gl_entry_points(reinterpret_cast<GlProcLoader>(&eglGetProcAddress));
  }

  std::string backend_name() const override { return "egl"; }

 private:
  void create_context() {
    // Surfaceless still needs a config; Mesa offers GL only on pbuffer-capable ones.
    const EGLint config_attributes[] = {EGL_SURFACE_TYPE, EGL_PBUFFER_BIT, EGL_RENDERABLE_TYPE,
                                        EGL_OPENGL_BIT, EGL_NONE};
    EGLConfig config = nullptr;
    EGLint count = 0;
    if (!eglChooseConfig(display_, config_attributes, &config, 1, &count) || count == 0) {
      throw std::runtime_error("EGL: no config with OpenGL and pbuffer support");
    }
    if (!eglBindAPI(EGL_OPENGL_API)) throw std::runtime_error(egl_error("eglBindAPI"));
    const EGLint context_attributes[] = {EGL_CONTEXT_MAJOR_VERSION,
                                         4,
                                         EGL_CONTEXT_MINOR_VERSION,
                                         5,
                                         EGL_CONTEXT_OPENGL_PROFILE_MASK,
                                         EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT,
                                         EGL_NONE};
    context_ = eglCreateContext(display_, config, EGL_NO_CONTEXT, context_attributes);
    if (context_ == EGL_NO_CONTEXT) throw std::runtime_error(egl_error("eglCreateContext"));
  }

  EGLDisplay display_ = EGL_NO_DISPLAY;
  EGLContext context_ = EGL_NO_CONTEXT;
};

}  // namespace

std::unique_ptr<GlContext> create_egl_context() {
  auto context = std::make_unique<EglContext>();
  context->make_current();
  return context;
}

}  // namespace impasto::render_gl
