#pragma once
// Draws a fragment shader over the whole viewport (one triangle, no vertex data).
#include <string>

#include "impasto/render_gl/shader_program.hpp"

namespace impasto::render_gl {

// The vertex shader every full-viewport pass shares: it writes `out vec2 uv` (0..1 from
// the bottom-left of the viewport).
ShaderSource fullscreen_vertex_shader();

class FullscreenPass {
 public:
  // Links fullscreen_vertex_shader() with the given fragment shader.
  FullscreenPass(std::string fragment_name, std::string fragment_source);
  ~FullscreenPass();
  FullscreenPass(const FullscreenPass&) = delete;
  FullscreenPass& operator=(const FullscreenPass&) = delete;

  const ShaderProgram& program() const { return program_; }
  // Draws into the bound framebuffer; the program must be in use with its uniforms set.
  void draw() const;

 private:
  ShaderProgram program_;
  GLuint vertex_array_ = 0;
};

}  // namespace impasto::render_gl
