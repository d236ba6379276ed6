#include "impasto/render/box_filter.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <stdexcept>
#include <vector>

namespace impasto::render {
namespace {

// Per pixel along one axis: the first cell its footprint [start + p z, start + (p + 1) z)
// meets and the share of the footprint each cell from there holds.
struct Footprint {
  int first_cell = 0;
  std::vector<double> weights;
};

std::vector<Footprint> footprints(double start, double cells_per_pixel, int pixels) {
  std::vector<Footprint> out(static_cast<std::size_t>(pixels));
  for (int p = 0; p < pixels; ++p) {
    const double a = start + p * cells_per_pixel, b = a + cells_per_pixel;
    Footprint& f = out[static_cast<std::size_t>(p)];
    f.first_cell = static_cast<int>(std::floor(a));
    for (int c = f.first_cell; c < b; ++c) {
      f.weights.push_back((std::min(b, c + 1.0) - std::max(a, 1.0 * c)) / cells_per_pixel);
    }
  }
  return out;
}

}  // namespace

Image box_filtered(const Image& cells, double cells_per_pixel, int width, int height) {
  if (!(cells_per_pixel >= 1.0) || width < 1 || height < 1 || cells.width < 1 || cells.height < 1) {
    throw std::invalid_argument("box_filtered: a view of at least one pixel, >= 1 cell a pixel");
  }
  const auto columns =
      footprints(0.5 * (cells.width - width * cells_per_pixel), cells_per_pixel, width);
  const auto rows =
      footprints(0.5 * (cells.height - height * cells_per_pixel), cells_per_pixel, height);
  Image out{
      width, height,
      std::vector<float>(3 * static_cast<std::size_t>(width) * static_cast<std::size_t>(height))};
  for (int y = 0; y < height; ++y) {
    const Footprint& row = rows[static_cast<std::size_t>(y)];
    for (int x = 0; x < width; ++x) {
      const Footprint& column = columns[static_cast<std::size_t>(x)];
      double sum[3] = {0.0, 0.0, 0.0};
      for (std::size_t j = 0; j < row.weights.size(); ++j) {
        const int cy = std::clamp(row.first_cell + static_cast<int>(j), 0, cells.height - 1);
        for (std::size_t i = 0; i < column.weights.size(); ++i) {
          const int cx = std::clamp(column.first_cell + static_cast<int>(i), 0, cells.width - 1);
          const double weight = row.weights[j] * column.weights[i];
          const float* cell = cells.pixel(cx, cy);
          for (int c = 0; c < 3; ++c) sum[c] += weight * cell[c];
        }
      }
      for (int c = 0; c < 3; ++c) out.pixel(x, y)[c] = static_cast<float>(sum[c]);
    }
  }
  return out;
}

}  // namespace impasto::render
