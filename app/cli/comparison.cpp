#include "comparison.hpp"

#include <impasto/data/colorimetry.hpp>
#include <impasto/data/lights.hpp>
#include <impasto/render/display.hpp>
#include <impasto/render/relief_maps.hpp>
#include <impasto/render/render_painting.hpp>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace impasto::app {

namespace {

std::vector<data::Lab> to_lab(const render::Image& image) {
  const auto m = render::invert_3x3(render::xyz_to_linear_srgb());
  const data::Xyz white = data::white_point(data::light_from_spec("D65"));
  std::vector<data::Lab> lab;
  lab.reserve(image.rgb.size() / 3);
  for (std::size_t i = 0; i + 2 < image.rgb.size(); i += 3) {
    const double r = image.rgb[i], g = image.rgb[i + 1], b = image.rgb[i + 2];
    const data::Xyz xyz{100.0 * (m[0] * r + m[1] * g + m[2] * b),
                        100.0 * (m[3] * r + m[4] * g + m[5] * b),
                        100.0 * (m[6] * r + m[7] * g + m[8] * b)};
    lab.push_back(data::xyz_to_lab(xyz, white));
  }
  return lab;
}

}  // namespace

render::Image linear_view(const paintcore::Painting& painting) {
  render::RenderSettings settings;
  settings.display = render::DisplayEncoding::linear_srgb;
  return render::render_painting(painting, settings);
}

Comparison compare_images(const render::Image& a, const render::Image& b, double threshold,
                          const std::string& first, const std::string& second) {
  if (a.width != b.width || a.height != b.height || a.rgb.empty())
    throw std::runtime_error("compare: " + first + " is " + std::to_string(a.width) + "x" +
                             std::to_string(a.height) + ", " + second + " is " +
                             std::to_string(b.width) + "x" + std::to_string(b.height));
  Comparison c;
  c.width = a.width;
  c.height = a.height;
  c.threshold = threshold;
  const std::vector<data::Lab> la = to_lab(a), lb = to_lab(b);
  c.de00.resize(la.size());
  for (std::size_t i = 0; i < la.size(); ++i) c.de00[i] = data::ciede2000(la[i], lb[i]);
  for (double d : c.de00) {
    c.de00_mean += d / static_cast<double>(c.de00.size());
    c.pixels_over += d > threshold;
  }
  std::vector<double> sorted = c.de00;
  std::sort(sorted.begin(), sorted.end());
  c.de00_p95 = sorted[static_cast<std::size_t>(0.95 * static_cast<double>(sorted.size() - 1))];
  c.de00_max = sorted.back();
  return c;
}

Comparison compare_paintings(const paintcore::Painting& a, const paintcore::Painting& b,
                             double threshold, const std::string& first,
                             const std::string& second) {
  Comparison c = compare_images(linear_view(a), linear_view(b), threshold, first, second);
  const render::HeightGrid ha = render::surface_heights(a.canvas());
  const render::HeightGrid hb = render::surface_heights(b.canvas());
  double height_max = 0.0, height_mean = 0.0;
  for (std::size_t i = 0; i < ha.mm.size() && i < hb.mm.size(); ++i) {
    const double d = std::abs(static_cast<double>(ha.mm[i]) - hb.mm[i]);
    height_max = std::max(height_max, d);
    height_mean += d / static_cast<double>(ha.mm.size());
  }
  c.height_mm_mean = height_mean;
  c.height_mm_max = height_max;
  return c;
}

}  // namespace impasto::app
