#include "impasto/render_gl/gpu_display_transform.hpp"

#include <OpenColorIO/OpenColorIO.h>

#include <stdexcept>

#include "impasto/render/display_ocio.hpp"

namespace OCIO = OCIO_NAMESPACE;

namespace impasto::render_gl {
namespace {

void set_lut_parameters(GLenum target, OCIO::Interpolation interpolation) {
  const GLint filter = interpolation == OCIO::INTERP_NEAREST ? GL_NEAREST : GL_LINEAR;
  glTexParameteri(target, GL_TEXTURE_MIN_FILTER, filter);
  glTexParameteri(target, GL_TEXTURE_MAG_FILTER, filter);
  glTexParameteri(target, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  glTexParameteri(target, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
  glTexParameteri(target, GL_TEXTURE_WRAP_R, GL_CLAMP_TO_EDGE);
}

}  // namespace

GpuDisplayTransform::GpuDisplayTransform(render::DisplayEncoding encoding) : encoding_(encoding) {
  const OCIO::ConstConfigRcPtr config = OCIO::Config::CreateRaw();
  const OCIO::ConstProcessorRcPtr processor =
      config->getProcessor(render::display_ocio_transform(encoding));
  OCIO::GpuShaderDescRcPtr desc = OCIO::GpuShaderDesc::CreateShaderDesc();
  desc->setLanguage(OCIO::GPU_LANGUAGE_GLSL_1_3);
  desc->setFunctionName("ocio_display");
  desc->setResourcePrefix("ocio_");
  processor->getDefaultGPUProcessor()->extractGpuShaderInfo(desc);
  if (desc->getNumUniforms() != 0) {
    throw std::runtime_error("display transform: dynamic OpenColorIO uniforms are not supported");
  }
  glsl_ = desc->getShaderText();

  for (unsigned i = 0; i < desc->getNumTextures(); ++i) {
    const char* texture_name = nullptr;
    const char* sampler_name = nullptr;
    unsigned width = 0, height = 0;
    OCIO::GpuShaderDesc::TextureType channel{};
    OCIO::Interpolation interpolation{};
    desc->getTexture(i, texture_name, sampler_name, width, height, channel, interpolation);
    const float* values = nullptr;
    desc->getTextureValues(i, values);
    const bool red_only = channel == OCIO::GpuShaderDesc::TEXTURE_RED_CHANNEL;
    const GLint internal = red_only ? GL_R32F : GL_RGB32F;
    const GLenum format = red_only ? GL_RED : GL_RGB;
    Lut lut{height > 1 ? GLenum{GL_TEXTURE_2D} : GLenum{GL_TEXTURE_1D}, 0, sampler_name};
    glGenTextures(1, &lut.texture);
    glBindTexture(lut.target, lut.texture);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    if (lut.target == GL_TEXTURE_2D) {
      glTexImage2D(GL_TEXTURE_2D, 0, internal, static_cast<GLsizei>(width),
                   static_cast<GLsizei>(height), 0, format, GL_FLOAT, values);
    } else {
      glTexImage1D(GL_TEXTURE_1D, 0, internal, static_cast<GLsizei>(width), 0, format, GL_FLOAT,
                   values);
    }
    set_lut_parameters(lut.target, interpolation);
    luts_.push_back(std::move(lut));
  }
  for (unsigned i = 0; i < desc->getNum3DTextures(); ++i) {
    const char* texture_name = nullptr;
    const char* sampler_name = nullptr;
    unsigned edge = 0;
    OCIO::Interpolation interpolation{};
    desc->get3DTexture(i, texture_name, sampler_name, edge, interpolation);
    const float* values = nullptr;
    desc->get3DTextureValues(i, values);
    Lut lut{GL_TEXTURE_3D, 0, sampler_name};
    glGenTextures(1, &lut.texture);
    glBindTexture(GL_TEXTURE_3D, lut.texture);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    const auto size = static_cast<GLsizei>(edge);
    glTexImage3D(GL_TEXTURE_3D, 0, GL_RGB32F, size, size, size, 0, GL_RGB, GL_FLOAT, values);
    set_lut_parameters(GL_TEXTURE_3D, interpolation);
    luts_.push_back(std::move(lut));
  }
}

GpuDisplayTransform::~GpuDisplayTransform() {
  for (const Lut& lut : luts_) glDeleteTextures(1, &lut.texture);
}

int GpuDisplayTransform::bind(const ShaderProgram& program, int first_unit) const {
  int unit = first_unit;
  for (const Lut& lut : luts_) {
    glActiveTexture(GL_TEXTURE0 + static_cast<GLenum>(unit));
    glBindTexture(lut.target, lut.texture);
    glUniform1i(program.uniform(lut.sampler), unit);
    ++unit;
  }
  return unit;
}

}  // namespace impasto::render_gl
