#include "impasto/render_gl/fullscreen_pass.hpp"

#include "embedded_shaders.hpp"

namespace impasto::render_gl {

ShaderSource fullscreen_vertex_shader() {
  return {GL_VERTEX_SHADER, "fullscreen_vert.glsl", shaders::fullscreen_vert};
}

FullscreenPass::FullscreenPass(std::string fragment_name, std::string fragment_source)
    : program_({fullscreen_vertex_shader(),
                {GL_FRAGMENT_SHADER, std::move(fragment_name), std::move(fragment_source)}}) {
  glGenVertexArrays(1, &vertex_array_);  // core profile draws need a bound VAO, even empty
}

FullscreenPass::~FullscreenPass() {
  glDeleteVertexArrays(1, &vertex_array_);
}

void FullscreenPass::draw() const {
  glBindVertexArray(vertex_array_);
  glDrawArrays(GL_TRIANGLES, 0, 3);
  glBindVertexArray(0);
}

}  // namespace impasto::render_gl
