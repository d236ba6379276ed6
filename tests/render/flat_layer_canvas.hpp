#pragma once
// One flat tile of a uniform paint layer, no weave: what the colour tests render to compare
// the renderer's flat layer with a measurement or a swatch.
#include <algorithm>
#include <numeric>
#include <vector>

#include "impasto/paintcore/canvas.hpp"

namespace impasto::test {

// A tile holding `depth_mm` of paint of these concentrations (by volume, any total) in every
// cell, slot i the i-th concentration.
inline paintcore::Canvas flat_layer_canvas(const std::vector<double>& concentrations,
                                           float depth_mm) {
  const int slots = static_cast<int>(concentrations.size());
  paintcore::Canvas canvas({paintcore::kTileSize, paintcore::kTileSize, 254.0, 0});
  paintcore::Tile& tile = canvas.ensure_tile(0, slots);
  const double total = std::accumulate(concentrations.begin(), concentrations.end(), 0.0);
  tile.wet_volume_mm.fill(depth_mm);
  for (int s = 0; s < slots; ++s) {
    const auto amount =
        static_cast<float>(depth_mm * concentrations[static_cast<std::size_t>(s)] / total);
    std::fill_n(tile.pigment(s), paintcore::kTileCells, amount);
  }
  return canvas;
}

}  // namespace impasto::test
