#pragma once
// The headless context back-ends, each in its own file (their platform headers clash).
#include <memory>

#include "impasto/render_gl/gl_context.hpp"

namespace impasto::render_gl {

// Each returns a current context or throws std::runtime_error saying why not.
std::unique_ptr<GlContext> create_egl_context();
std::unique_ptr<GlContext> create_osmesa_context();

}  // namespace impasto::render_gl
