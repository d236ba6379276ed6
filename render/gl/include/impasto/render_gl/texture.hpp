#pragma once
// GPU textures of canvas data (float grids) with region updates, so that only the tiles the
// simulation touched travel to the GPU.
#include "impasto/render_gl/gl.hpp"

namespace impasto::render_gl {

enum class TexelFormat {
  kR32F,     // one float per texel
  kRG32F,    // two floats per texel (wet volume, total height)
  kRGBA32F,  // four floats per texel (four pigment slots, four reflectance nodes)
  kRGBA8,    // display colour
};

int channel_count(TexelFormat format);

// A 2D texture (layers == 0) or a 2D array texture (layers >= 1), sampled with texelFetch
// (nearest, clamp to edge): one texel is one canvas cell.
class Texture {
 public:
  Texture() = default;
  Texture(int width, int height, int layers, TexelFormat format);
  ~Texture();
  Texture(Texture&& other) noexcept;
  Texture& operator=(Texture&& other) noexcept;
  Texture(const Texture&) = delete;
  Texture& operator=(const Texture&) = delete;

  // Writes the region [x, x+w) × [y, y+h) of `layer` (0 for a 2D texture) from `texels`,
  // whose rows are `row_stride` texels apart (float for the 32F formats, bytes for RGBA8).
  // Throws std::out_of_range for a region outside the texture.
  void upload(int x, int y, int w, int h, int layer, const void* texels, int row_stride);

  void bind(int unit) const;
  GLuint id() const { return id_; }
  GLenum target() const { return layers_ == 0 ? GL_TEXTURE_2D : GL_TEXTURE_2D_ARRAY; }
  int width() const { return width_; }
  int height() const { return height_; }
  int layers() const { return layers_; }
  TexelFormat format() const { return format_; }

 private:
  GLuint id_ = 0;
  int width_ = 0, height_ = 0, layers_ = 0;
  TexelFormat format_ = TexelFormat::kR32F;
};

}  // namespace impasto::render_gl
