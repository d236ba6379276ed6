#pragma once
// A linked GLSL program made from source strings; compile and link errors carry the
// driver's info log and the name of the shader that failed.
#include <string>
#include <string_view>
#include <vector>

#include "impasto/render_gl/gl.hpp"

namespace impasto::render_gl {

struct ShaderSource {
  GLenum stage;      // GL_VERTEX_SHADER, GL_FRAGMENT_SHADER, ...
  std::string name;  // for error messages, e.g. "km_shading.frag"
  std::string text;  // the complete GLSL source, #version line included
};

class ShaderProgram {
 public:
  ShaderProgram() = default;
  // Compiles and links; throws std::runtime_error("<name>: <info log>") on failure.
  explicit ShaderProgram(const std::vector<ShaderSource>& sources);
  ~ShaderProgram();
  ShaderProgram(ShaderProgram&& other) noexcept;
  ShaderProgram& operator=(ShaderProgram&& other) noexcept;
  ShaderProgram(const ShaderProgram&) = delete;
  ShaderProgram& operator=(const ShaderProgram&) = delete;

  GLuint id() const { return id_; }
  void use() const { glUseProgram(id_); }
  // -1 when the uniform does not exist or was optimised away (GL ignores writes to -1).
  GLint uniform(std::string_view name) const;

 private:
  GLuint id_ = 0;
};

}  // namespace impasto::render_gl
