#pragma once
// Comparing a GPU image with the CPU reference, shared by the GL test files.
#include <algorithm>
#include <cmath>
#include <cstddef>

#include "impasto/render/image.hpp"

namespace impasto::render_gl::test {

// Max |a - b| over every channel of two images of the same size.
inline double max_difference(const render::Image& a, const render::Image& b) {
  double worst = 0.0;
  for (std::size_t i = 0; i < a.rgb.size(); ++i)
    worst = std::max(worst, std::abs(double(a.rgb[i]) - b.rgb[i]));
  return worst;
}

// How far `actual` is from `expected` (same size): the largest channel difference and the
// pixel where it is (the first such), and the mean over every channel.
struct ImageDifference {
  double max = 0.0, mean = 0.0;
  int worst_x = 0, worst_y = 0;
};

inline ImageDifference compare_images(const render::Image& actual, const render::Image& expected) {
  ImageDifference result;
  double sum = 0.0;
  for (int y = 0; y < expected.height; ++y)
    for (int x = 0; x < expected.width; ++x)
      for (int ch = 0; ch < 3; ++ch) {
        const double d = std::abs(double(actual.pixel(x, y)[ch]) - expected.pixel(x, y)[ch]);
        sum += d;
        if (d > result.max) {
          result.max = d;
          result.worst_x = x;
          result.worst_y = y;
        }
      }
  result.mean = sum / (3.0 * expected.width * expected.height);
  return result;
}

}  // namespace impasto::render_gl::test
