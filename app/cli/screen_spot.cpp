#include "screen_spot.hpp"

#include <algorithm>
#include <cmath>

namespace impasto::app {

std::optional<ScreenSpot> find_colour_spot(const render::Image& screen,
                                           std::array<std::uint8_t, 3> colour, int min_x,
                                           int min_pixels, int max_extent) {
  int count = 0, x0 = screen.width, x1 = -1, y0 = screen.height, y1 = -1;
  double sum_x = 0, sum_y = 0;
  for (int y = 0; y < screen.height; ++y) {
    for (int x = std::max(0, min_x); x < screen.width; ++x) {
      const float* p = screen.pixel(x, y);
      bool same = true;
      for (int c = 0; c < 3; ++c) same &= std::lround(p[c] * 255.0f) == colour[c];
      if (!same) continue;
      ++count;
      sum_x += x;
      sum_y += y;
      x0 = std::min(x0, x);
      x1 = std::max(x1, x);
      y0 = std::min(y0, y);
      y1 = std::max(y1, y);
    }
  }
  if (count < std::max(1, min_pixels) || x1 - x0 >= max_extent || y1 - y0 >= max_extent) {
    return std::nullopt;
  }
  return ScreenSpot{sum_x / count, sum_y / count, count};
}

}  // namespace impasto::app
