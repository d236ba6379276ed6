// render::box_filtered: a zoomed-out view as a box filter makes it, checked against sums done
// by hand and the limits (one cell a pixel is the image itself; a uniform image stays uniform;
// the mean of a view that covers the image whole is the image's mean).
#include "impasto/render/box_filter.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

namespace impasto::render {
namespace {

// Cell (x, y) holds x + 10 y in every channel.
Image ramp(int width, int height) {
  Image image{width, height, std::vector<float>(3 * static_cast<std::size_t>(width * height))};
  for (int y = 0; y < height; ++y) {
    for (int x = 0; x < width; ++x) {
      for (int c = 0; c < 3; ++c) image.pixel(x, y)[c] = static_cast<float>(x + 10 * y);
    }
  }
  return image;
}

TEST(BoxFilter, OneCellAPixelIsTheImageItself) {
  const Image cells = ramp(7, 5);
  const Image view = box_filtered(cells, 1.0, 7, 5);
  EXPECT_EQ(view.rgb, cells.rgb);
}

TEST(BoxFilter, WholeBlocksAreTheirMeans) {
  const Image cells = ramp(8, 6);
  const Image view = box_filtered(cells, 2.0, 4, 3);
  // Pixel (1, 2) covers cells x 2..3, y 4..5: mean x 2.5, mean y 4.5.
  EXPECT_FLOAT_EQ(view.pixel(1, 2)[0], 2.5f + 45.0f);
}

TEST(BoxFilter, PartCellsCountByTheShareOfTheFootprintTheyHold) {
  // A 5-cell row seen as 4 pixels of 1.25 cells: pixel 1 covers [1.25, 2.5) — 3/4 of cell 1
  // and 1/2 of cell 2, over 1.25.
  Image cells{5, 1, {}};
  for (int x = 0; x < 5; ++x) cells.rgb.insert(cells.rgb.end(), 3, static_cast<float>(x * x));
  const Image view = box_filtered(cells, 1.25, 4, 1);
  EXPECT_NEAR(view.pixel(1, 0)[1], (0.75 * 1.0 + 0.5 * 4.0) / 1.25, 1e-6);
  // The view covers the row whole: its mean is the row's.
  double mean = 0.0;
  for (int x = 0; x < 4; ++x) mean += view.pixel(x, 0)[2] / 4.0;
  EXPECT_NEAR(mean, (0.0 + 1.0 + 4.0 + 9.0 + 16.0) / 5.0, 1e-5);
}

TEST(BoxFilter, AUniformImageStaysUniform) {
  Image cells{9, 9, std::vector<float>(3 * 81, 0.375f)};
  const Image view = box_filtered(cells, 1.7, 5, 5);
  for (float v : view.rgb) EXPECT_NEAR(v, 0.375f, 1e-6f);
}

TEST(BoxFilter, RefusesAMagnifiedOrEmptyView) {
  const Image cells = ramp(4, 4);
  EXPECT_THROW(box_filtered(cells, 0.5, 8, 8), std::invalid_argument);
  EXPECT_THROW(box_filtered(cells, std::nan(""), 2, 2), std::invalid_argument);
  EXPECT_THROW(box_filtered(cells, 2.0, 0, 2), std::invalid_argument);
}

}  // namespace
}  // namespace impasto::render
