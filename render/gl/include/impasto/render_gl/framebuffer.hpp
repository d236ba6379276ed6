#pragma once
// An off-screen render target (one colour texture) and its read-back.
#include <cstdint>
#include <vector>

#include "impasto/render_gl/texture.hpp"

namespace impasto::render_gl {

class Framebuffer {
 public:
  // format: kRGBA32F to compare with the CPU reference, kRGBA8 for display.
  Framebuffer(int width, int height, TexelFormat format);
  ~Framebuffer();
  Framebuffer(const Framebuffer&) = delete;
  Framebuffer& operator=(const Framebuffer&) = delete;

  // Binds it as the draw target with a viewport covering it.
  void bind() const;
  int width() const { return color_.width(); }
  int height() const { return color_.height(); }
  const Texture& color() const { return color_; }
  GLuint id() const { return id_; }  // for glBlitFramebuffer

  // Row 0 first = the bottom row in GL's convention; callers that draw with y down in
  // their projection get image order. RGBA, 4 values a pixel.
  std::vector<float> read_rgba_float() const;
  std::vector<std::uint8_t> read_rgba8() const;

 private:
  Texture color_;
  GLuint id_ = 0;
};

}  // namespace impasto::render_gl
