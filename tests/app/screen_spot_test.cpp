// Finding the light's dot in a screenshot (screen_spot.hpp), as `impasto bench window
// --light-drag` does before it drags the Light panel's disc.
#include <gtest/gtest.h>

#include <cmath>

#include "screen_spot.hpp"

namespace impasto::app {
namespace {

constexpr std::array<std::uint8_t, 3> kDot = {255, 220, 80};

render::Image grey(int w, int h) {
  render::Image image{w, h, std::vector<float>(3 * static_cast<std::size_t>(w) * h, 0.2f)};
  return image;
}

void disc(render::Image& image, double cx, double cy, double r, std::array<std::uint8_t, 3> c) {
  for (int y = 0; y < image.height; ++y) {
    for (int x = 0; x < image.width; ++x) {
      if (std::hypot(x - cx, y - cy) > r) continue;
      for (int k = 0; k < 3; ++k) image.pixel(x, y)[k] = c[k] / 255.0f;
    }
  }
}

TEST(ScreenSpot, FindsTheCentreOfOneSmallSpotOfExactlyThatColour) {
  render::Image screen = grey(200, 120);
  disc(screen, 150.0, 40.0, 6.0, kDot);
  disc(screen, 150.0, 90.0, 6.0, {255, 221, 80});  // a near colour is another colour
  const auto spot = find_colour_spot(screen, kDot, 100, 18, 24);
  ASSERT_TRUE(spot);
  EXPECT_NEAR(spot->x, 150.0, 0.01);
  EXPECT_NEAR(spot->y, 40.0, 0.01);
  EXPECT_GT(spot->pixels, 100);
}

TEST(ScreenSpot, NoSpotWhereTheColourIsSpreadTooFewOrLeftOfTheSearch) {
  render::Image screen = grey(200, 120);
  disc(screen, 150.0, 40.0, 6.0, kDot);
  disc(screen, 150.0, 100.0, 6.0, kDot);  // two of them: not one spot
  EXPECT_FALSE(find_colour_spot(screen, kDot, 100, 18, 24));
  render::Image tiny = grey(200, 120);
  disc(tiny, 150.0, 40.0, 1.0, kDot);  // a few pixels: not the dot
  EXPECT_FALSE(find_colour_spot(tiny, kDot, 100, 18, 24));
  render::Image left = grey(200, 120);
  disc(left, 50.0, 40.0, 6.0, kDot);  // on the canvas's side of the window
  EXPECT_FALSE(find_colour_spot(left, kDot, 100, 18, 24));
  EXPECT_TRUE(find_colour_spot(left, kDot, 0, 18, 24));
}

}  // namespace
}  // namespace impasto::app
