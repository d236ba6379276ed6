// The whole-tile entry point: validates the renderer's arrays once, skips tiles and cells
// without flakes, and accumulates the sparkles of every light.
#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

#include "impasto/flakes/sparkles.hpp"
#include "light_checks.hpp"

namespace impasto::flakes {

std::size_t SparkleRenderer::add_tile(const FlakeTile& tile, std::span<const Light> lights,
                                      const View& view, std::span<float> radiance) const {
  const std::size_t cells = static_cast<std::size_t>(std::max(tile.width, 0)) *
                            static_cast<std::size_t>(std::max(tile.height, 0));
  auto where = [&](std::size_t i) {
    return " at cell (" + std::to_string(tile.first_ix + static_cast<int>(i % tile.width)) + ", " +
           std::to_string(tile.first_iy + static_cast<int>(i / tile.width)) + ")";
  };
  if (tile.concentration.size() != cells) {
    throw std::runtime_error("flake tile: concentration has " +
                             std::to_string(tile.concentration.size()) + " values for " +
                             std::to_string(cells) + " cells");
  }
  bool any = false;
  for (std::size_t i = 0; i < cells; ++i) {
    const float c = tile.concentration[i];
    if (!(c >= 0.0f) || !std::isfinite(c)) {
      throw std::runtime_error("flake tile: concentration is " + std::to_string(c) + where(i));
    }
    any = any || c > 0.0f;
  }
  if (!any) return 0;  // no flake paint here: no work, nothing written

  const std::size_t nodes = tables_.wavelength_count();
  auto expect = [&](std::span<const float> values, std::size_t per_cell, const char* name) {
    if (!values.empty() && values.size() != cells * per_cell) {
      throw std::runtime_error(std::string("flake tile: ") + name + " has " +
                               std::to_string(values.size()) + " values, expected " +
                               std::to_string(cells * per_cell));
    }
  };
  if (tile.thickness_mm.size() != cells) {
    throw std::runtime_error("flake tile: thickness_mm has " +
                             std::to_string(tile.thickness_mm.size()) + " values for " +
                             std::to_string(cells) + " cells");
  }
  expect(tile.surface_height_mm, 1, "surface_height_mm");
  expect(tile.normals, 3, "normals");
  if (radiance.size() != cells * nodes) {
    throw std::runtime_error("flake tile: radiance has " + std::to_string(radiance.size()) +
                             " values, expected " + std::to_string(cells * nodes));
  }
  if (!(tile.cell_size_mm > 0.0) || !std::isfinite(tile.cell_size_mm)) {
    throw std::runtime_error("flake tile: cell_size_mm must be positive and finite");
  }
  for (const Light& light : lights) check_light(light, nodes);

  std::size_t evaluated = 0;
  std::vector<double> cell_radiance(nodes);
  for (std::size_t i = 0; i < cells; ++i) {
    if (tile.concentration[i] <= 0.0f) continue;
    const int x = static_cast<int>(i % tile.width), y = static_cast<int>(i / tile.width);
    FlakeCell cell;
    cell.ix = tile.first_ix + x;
    cell.iy = tile.first_iy + y;
    const double height = tile.surface_height_mm.empty() ? 0.0 : tile.surface_height_mm[i];
    cell.center_mm = {(cell.ix + 0.5) * tile.cell_size_mm, (cell.iy + 0.5) * tile.cell_size_mm,
                      height};
    if (!tile.normals.empty()) {
      const Vec3 n{tile.normals[3 * i], tile.normals[3 * i + 1], tile.normals[3 * i + 2]};
      if (!(n.z > 0.0) || !std::isfinite(length(n))) {
        throw std::runtime_error("flake tile: normal must point up and be finite" + where(i));
      }
      cell.normal = normalized(n);
    }
    cell.area_mm2 = tile.cell_size_mm * tile.cell_size_mm;
    cell.flake_concentration = tile.concentration[i];
    cell.thickness_mm = tile.thickness_mm[i];
    if (!(cell.thickness_mm >= 0.0) || !std::isfinite(cell.thickness_mm) ||
        !std::isfinite(height)) {
      throw std::runtime_error("flake tile: thickness or height is not a finite length" + where(i));
    }
    ++evaluated;
    std::fill(cell_radiance.begin(), cell_radiance.end(), 0.0);
    int sparkles = 0;
    for (const Light& light : lights) sparkles += add_cell(cell, light, view, cell_radiance);
    if (sparkles == 0) continue;
    float* out = radiance.data() + i * nodes;
    for (std::size_t w = 0; w < nodes; ++w) out[w] += static_cast<float>(cell_radiance[w]);
  }
  return evaluated;
}

}  // namespace impasto::flakes
