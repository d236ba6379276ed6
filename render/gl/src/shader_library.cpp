#include "impasto/render_gl/shader_library.hpp"

#include "embedded_shaders.hpp"

namespace impasto::render_gl {

const char* km_glsl() {
  return shaders::km_lib;
}
const char* shading_glsl() {
  return shaders::shading_lib;
}

}  // namespace impasto::render_gl
