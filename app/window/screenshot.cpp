#include "window/screenshot.hpp"

#include <impasto/render/image.hpp>
#include <impasto/render_gl/gl.hpp>

#include <cstdint>
#include <vector>

namespace impasto::app::window {

void save_window_screenshot(const std::filesystem::path& file, int framebuffer_w,
                            int framebuffer_h) {
  std::vector<std::uint8_t> rgba(static_cast<std::size_t>(framebuffer_w) * framebuffer_h * 4);
  glBindFramebuffer(GL_READ_FRAMEBUFFER, 0);
  glReadBuffer(GL_BACK);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glReadPixels(0, 0, framebuffer_w, framebuffer_h, GL_RGBA, GL_UNSIGNED_BYTE, rgba.data());
  render::Image image;
  image.width = framebuffer_w;
  image.height = framebuffer_h;
  image.rgb.resize(static_cast<std::size_t>(framebuffer_w) * framebuffer_h * 3);
  for (int y = 0; y < framebuffer_h; ++y) {
    const std::uint8_t* row =
        rgba.data() + static_cast<std::size_t>(framebuffer_h - 1 - y) * framebuffer_w * 4;
    for (int x = 0; x < framebuffer_w; ++x) {
      float* out = image.pixel(x, y);
      for (int c = 0; c < 3; ++c) out[c] = row[4 * x + c] / 255.0f;
    }
  }
  render::write_png(file, image);
}

}  // namespace impasto::app::window
