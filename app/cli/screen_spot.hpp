#pragma once
// Finding a small mark of one exact colour in a screenshot: where `impasto bench window`
// puts the pointer to drag a widget it cannot ask the window about (the light's dot).
#include <impasto/render/image.hpp>

#include <array>
#include <cstdint>
#include <optional>

namespace impasto::app {

struct ScreenSpot {
  double x = 0, y = 0;  // the centre of its pixels, window pixels
  int pixels = 0;
};

// The pixels of exactly `colour` (8-bit, as an 8-bit screenshot read back holds it) with x at
// least min_x: their centre, if there are at least min_pixels and they fit in a square of
// max_extent pixels (one spot, not the colour spread over the window); none otherwise.
std::optional<ScreenSpot> find_colour_spot(const render::Image& screen,
                                           std::array<std::uint8_t, 3> colour, int min_x,
                                           int min_pixels, int max_extent);

}  // namespace impasto::app
