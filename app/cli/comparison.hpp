#pragma once
// How far two paintings (or a painting and an image, or two images) are apart as a viewer sees
// them: CIEDE2000 per pixel under D65 and, for two paintings, the surface height in mm. Used
// by `impasto compare` and the Python module.
#include <impasto/paintcore/painting.hpp>
#include <impasto/render/image.hpp>

#include <optional>
#include <string>
#include <vector>

namespace impasto::app {

struct Comparison {
  int width = 0, height = 0;
  std::vector<double> de00;  // per pixel, row-major
  double de00_mean = 0.0, de00_p95 = 0.0, de00_max = 0.0;
  double threshold = 1.0;
  long pixels_over = 0;                                 // pixels whose dE00 is above threshold
  std::optional<double> height_mm_mean, height_mm_max;  // two paintings only
};

// A painting as compare sees it: rendered with the default settings, in linear sRGB.
render::Image linear_view(const paintcore::Painting& painting);

// Two linear sRGB images of one size (throws naming them otherwise: `first` and `second` are
// their names in messages).
Comparison compare_images(const render::Image& a, const render::Image& b, double threshold,
                          const std::string& first, const std::string& second);

// compare_images of their views, and their surface heights.
Comparison compare_paintings(const paintcore::Painting& a, const paintcore::Painting& b,
                             double threshold, const std::string& first, const std::string& second);

}  // namespace impasto::app
