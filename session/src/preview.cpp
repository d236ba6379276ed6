#include "impasto/session/preview.hpp"

#include <algorithm>
#include <cmath>

namespace impasto::session {

void preview_slot_color(int slot, float rgb[3]) {
  // Hues spread by the golden angle, so neighbouring slots never look alike.
  const float hue = std::fmod(static_cast<float>(slot) * 0.618034f + 0.6f, 1.0f) * 6.0f;
  const float c = 0.75f, x = c * (1.0f - std::fabs(std::fmod(hue, 2.0f) - 1.0f)), m = 0.1f;
  const int sector = static_cast<int>(hue) % 6;
  const float table[6][3] = {{c, x, 0}, {x, c, 0}, {0, c, x}, {0, x, c}, {x, 0, c}, {c, 0, x}};
  for (int i = 0; i < 3; ++i) rgb[i] = table[sector][i] + m;
}

render::Image render_preview(const paintcore::Painting& painting) {
  const auto& canvas = painting.canvas();
  const int width = canvas.width_cells(), height = canvas.height_cells();
  const int slots = painting.slot_count();
  const double cell_mm = canvas.cell_mm();
  render::Image image{width, height, std::vector<float>(3 * std::size_t(width) * height)};

  auto surface = [&](int x, int y) {
    x = std::clamp(x, 0, width - 1);
    y = std::clamp(y, 0, height - 1);
    return static_cast<double>(canvas.base_height_mm(x, y)) + canvas.dry_height_mm(x, y) +
           canvas.wet_volume_mm(x, y);
  };
  // A light from the upper left, 45 degrees up.
  const double light[3] = {-0.5, -0.5, std::sqrt(0.5)};
  std::vector<float> slot_rgb(3 * std::size_t(std::max(slots, 1)));
  for (int s = 0; s < slots; ++s) preview_slot_color(s, &slot_rgb[3 * std::size_t(s)]);

  for (int y = 0; y < height; ++y) {
    for (int x = 0; x < width; ++x) {
      float colour[3] = {0.93f, 0.91f, 0.86f};  // primed canvas
      const double volume = canvas.wet_volume_mm(x, y);
      if (volume > 0) {
        float mix[3] = {0, 0, 0};
        double pigment_total = 0;
        for (int s = 0; s < slots; ++s) {
          const double amount = canvas.pigment_mm(x, y, s);
          pigment_total += amount;
          for (int i = 0; i < 3; ++i) mix[i] += static_cast<float>(amount) * slot_rgb[3 * s + i];
        }
        if (pigment_total > 0) {
          const float cover = static_cast<float>(1.0 - std::exp(-volume / 0.02));
          for (int i = 0; i < 3; ++i) {
            colour[i] += cover * (mix[i] / static_cast<float>(pigment_total) - colour[i]);
          }
        }
      } else if (canvas.dry_height_mm(x, y) > 0) {
        for (float& c : colour) c *= 0.8f;  // dried paint, colour unknown to the preview
      }
      const double dx = (surface(x + 1, y) - surface(x - 1, y)) / (2 * cell_mm);
      const double dy = (surface(x, y + 1) - surface(x, y - 1)) / (2 * cell_mm);
      const double norm = std::sqrt(dx * dx + dy * dy + 1);
      const double lambert = (-dx * light[0] - dy * light[1] + light[2]) / norm;
      const float shade =
          static_cast<float>(0.35 + 0.65 * std::clamp(lambert / light[2], 0.0, 1.6));
      float* out = image.pixel(x, y);
      for (int i = 0; i < 3; ++i) out[i] = std::clamp(colour[i] * shade, 0.0f, 1.0f);
    }
  }
  return image;
}

}  // namespace impasto::session
