#pragma once
// Checks on rendered images shared by the renderer's tests.
#include <gtest/gtest.h>

#include <cstddef>

#include "impasto/render/image.hpp"

namespace impasto::render {

// The same size and the same value in every channel of every pixel.
inline void expect_identical(const Image& a, const Image& b) {
  ASSERT_EQ(a.width, b.width);
  ASSERT_EQ(a.height, b.height);
  std::size_t differing = 0;
  for (std::size_t i = 0; i < a.rgb.size(); ++i) differing += a.rgb[i] != b.rgb[i] ? 1 : 0;
  EXPECT_EQ(differing, 0u);
}

// Relative luminance of a linear sRGB pixel.
inline float luminance(const Image& image, int x, int y) {
  const float* p = image.pixel(x, y);
  return 0.2126f * p[0] + 0.7152f * p[1] + 0.0722f * p[2];
}

}  // namespace impasto::render
