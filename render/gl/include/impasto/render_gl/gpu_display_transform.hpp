#pragma once
// The display transform on the GPU: the same OpenColorIO transform as the CPU's
// render::DisplayTransform, emitted by OCIO as GLSL (`vec4 ocio_display(vec4 xyz)`) with
// any lookup textures it asks for.
#include <string>
#include <vector>

#include "impasto/render/display.hpp"
#include "impasto/render_gl/shader_program.hpp"

namespace impasto::render_gl {

class GpuDisplayTransform {
 public:
  // Needs a current GL context when the transform uses lookup textures.
  explicit GpuDisplayTransform(render::DisplayEncoding encoding);
  ~GpuDisplayTransform();
  GpuDisplayTransform(const GpuDisplayTransform&) = delete;
  GpuDisplayTransform& operator=(const GpuDisplayTransform&) = delete;

  render::DisplayEncoding encoding() const { return encoding_; }
  // GLSL (for #version 330 core) defining `vec4 ocio_display(vec4 xyz)` and its samplers.
  const std::string& glsl() const { return glsl_; }
  // Binds the lookup textures to units first_unit, first_unit + 1, ... and points the
  // program's samplers at them. The program must be in use. Returns the next free unit.
  int bind(const ShaderProgram& program, int first_unit) const;

 private:
  struct Lut {
    GLenum target;
    GLuint texture;
    std::string sampler;
  };
  render::DisplayEncoding encoding_;
  std::string glsl_;
  std::vector<Lut> luts_;
};

}  // namespace impasto::render_gl
