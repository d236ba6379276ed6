#include "impasto/render_gl/gl_context.hpp"

#include <stdexcept>

#include "headless_backends.hpp"

namespace impasto::render_gl {

std::unique_ptr<GlContext> create_headless_context(HeadlessBackend backend) {
  switch (backend) {
    case HeadlessBackend::kEgl:
      return create_egl_context();
    case HeadlessBackend::kOsMesa:
      return create_osmesa_context();
    case HeadlessBackend::kAuto:
      break;
  }
  try {
    return create_egl_context();
  } catch (const std::exception& egl_failure) {
    try {
      return create_osmesa_context();
    } catch (const std::exception& osmesa_failure) {
      throw std::runtime_error(std::string("no headless OpenGL context: ") + egl_failure.what() +
                               "; " + osmesa_failure.what());
    }
  }
}

}  // namespace impasto::render_gl
