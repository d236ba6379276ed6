#include "impasto/render_gl/texture.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>
#include <utility>

namespace impasto::render_gl {
namespace {

struct GlFormat {
  GLint internal;
  GLenum format;
  GLenum type;
};

GlFormat gl_format(TexelFormat format) {
  switch (format) {
    case TexelFormat::kR32F:
      return {GL_R32F, GL_RED, GL_FLOAT};
    case TexelFormat::kRG32F:
      return {GL_RG32F, GL_RG, GL_FLOAT};
    case TexelFormat::kRGBA32F:
      return {GL_RGBA32F, GL_RGBA, GL_FLOAT};
    case TexelFormat::kRGBA8:
      return {GL_RGBA8, GL_RGBA, GL_UNSIGNED_BYTE};
  }
  throw std::logic_error("unknown texel format");
}

}  // namespace

int channel_count(TexelFormat format) {
  return format == TexelFormat::kR32F ? 1 : 4;
}

Texture::Texture(int width, int height, int layers, TexelFormat format)
    : width_(width), height_(height), layers_(layers), format_(format) {
  GLint max_size = 0;
  glGetIntegerv(GL_MAX_TEXTURE_SIZE, &max_size);
  if (width <= 0 || height <= 0 || width > max_size || height > max_size || layers < 0) {
    throw std::runtime_error("texture size " + std::to_string(width) + "x" +
                             std::to_string(height) + " is outside 1.." + std::to_string(max_size));
  }
  const GlFormat f = gl_format(format);
  glGenTextures(1, &id_);
  glBindTexture(target(), id_);
  if (layers_ == 0) {
    glTexImage2D(GL_TEXTURE_2D, 0, f.internal, width, height, 0, f.format, f.type, nullptr);
  } else {
    glTexImage3D(GL_TEXTURE_2D_ARRAY, 0, f.internal, width, height, layers, 0, f.format, f.type,
                 nullptr);
  }
  glTexParameteri(target(), GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTexParameteri(target(), GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  glTexParameteri(target(), GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  glTexParameteri(target(), GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
  glTexParameteri(target(), GL_TEXTURE_MAX_LEVEL, 0);
  if (glGetError() != GL_NO_ERROR) {
    glDeleteTextures(1, &id_);
    id_ = 0;
    throw std::runtime_error("texture " + std::to_string(width) + "x" + std::to_string(height) +
                             "x" + std::to_string(layers) + ": out of GPU memory or unsupported");
  }
}

Texture::~Texture() {
  if (id_ != 0) glDeleteTextures(1, &id_);
}

Texture::Texture(Texture&& other) noexcept
    : id_(std::exchange(other.id_, 0)),
      width_(other.width_),
      height_(other.height_),
      layers_(other.layers_),
      format_(other.format_) {}

Texture& Texture::operator=(Texture&& other) noexcept {
  if (this != &other) {
    if (id_ != 0) glDeleteTextures(1, &id_);
    id_ = std::exchange(other.id_, 0);
    width_ = other.width_;
    height_ = other.height_;
    layers_ = other.layers_;
    format_ = other.format_;
  }
  return *this;
}

void Texture::upload(int x, int y, int w, int h, int layer, const void* texels, int row_stride) {
  if (x < 0 || y < 0 || w < 0 || h < 0 || x + w > width_ || y + h > height_ || layer < 0 ||
      layer >= std::max(layers_, 1) || row_stride < w) {
    throw std::out_of_range("texture upload region outside the texture");
  }
  if (w == 0 || h == 0) return;
  const GlFormat f = gl_format(format_);
  glBindTexture(target(), id_);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  glPixelStorei(GL_UNPACK_ROW_LENGTH, row_stride);
  if (layers_ == 0) {
    glTexSubImage2D(GL_TEXTURE_2D, 0, x, y, w, h, f.format, f.type, texels);
  } else {
    glTexSubImage3D(GL_TEXTURE_2D_ARRAY, 0, x, y, layer, w, h, 1, f.format, f.type, texels);
  }
  glPixelStorei(GL_UNPACK_ROW_LENGTH, 0);
}

void Texture::bind(int unit) const {
  glActiveTexture(GL_TEXTURE0 + static_cast<GLenum>(unit));
  glBindTexture(target(), id_);
}

}  // namespace impasto::render_gl
