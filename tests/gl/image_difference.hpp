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

}  // namespace impasto::render_gl::test
