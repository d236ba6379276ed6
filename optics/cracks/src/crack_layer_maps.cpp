#include "impasto/cracks/crack_layer_maps.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

namespace impasto::cracks {

using paintcore::kTileCells;
using paintcore::kTileSize;
static_assert(CrackMap::kTileSize == paintcore::kTileSize, "crack map tiles are canvas tiles");

paintcore::CrackLayer to_crack_layer(const CrackMap& map) {
  paintcore::CrackLayer layer;
  map.for_each_crack([&](int x, int y, const CrackCell& cell) {
    const int index = (y / kTileSize) * map.tiles_x() + x / kTileSize;
    const auto local = static_cast<std::size_t>((y % kTileSize) * kTileSize + x % kTileSize);
    layer.ensure_tile(index).cells[local] = {cell.depth_mm, cell.half_width_mm,
                                             static_cast<std::uint8_t>(cell.shape),
                                             cell.exposed_layer};
  });
  return layer;
}

CrackMap to_crack_map(const paintcore::CrackLayer& layer, int width_cells, int height_cells,
                      double cell_mm) {
  CrackMap map(width_cells, height_cells, cell_mm);
  for (int index = 0; index < layer.tile_extent(); ++index) {
    const paintcore::CrackTile* tile = layer.tile(index);
    if (tile == nullptr) continue;
    const int x0 = (index % map.tiles_x()) * kTileSize;
    const int y0 = (index / map.tiles_x()) * kTileSize;
    for (int cell = 0; cell < kTileCells; ++cell) {
      const paintcore::CrackRecord& r = tile->cells[static_cast<std::size_t>(cell)];
      if (!r.has_crack()) continue;
      if (r.shape >= kAllShapes.size()) {
        throw std::runtime_error("crack layer: tile " + std::to_string(index) + " cell " +
                                 std::to_string(cell) + ": unknown shape code " +
                                 std::to_string(r.shape));
      }
      map.set(x0 + cell % kTileSize, y0 + cell / kTileSize,
              {r.depth_mm, r.half_width_mm, static_cast<CavityShape>(r.shape), r.exposed_layer});
    }
  }
  return map;
}

CrackMap crack_map_of(const paintcore::Painting& painting) {
  const paintcore::Canvas& canvas = painting.canvas();
  return to_crack_map(painting.cracks(), canvas.width_cells(), canvas.height_cells(),
                      canvas.cell_mm());
}

void set_painting_cracks(paintcore::Painting& painting, const CrackMap& map) {
  const paintcore::Canvas& canvas = painting.canvas();
  if (map.width() != canvas.width_cells() || map.height() != canvas.height_cells() ||
      std::abs(map.cell_mm() - canvas.cell_mm()) > 1e-9 * canvas.cell_mm()) {
    throw std::runtime_error(
        "crack map of " + std::to_string(map.width()) + "x" + std::to_string(map.height()) +
        " cells of " + std::to_string(map.cell_mm()) + " mm does not fit the painting's " +
        std::to_string(canvas.width_cells()) + "x" + std::to_string(canvas.height_cells()) +
        " cells of " + std::to_string(canvas.cell_mm()) + " mm");
  }
  painting.set_cracks(to_crack_layer(map));
}

PaintFilm DryFilm::film() const {
  PaintFilm film;
  for (const std::vector<float>& layer : layer_thickness_mm)
    film.layer_thickness_mm.emplace_back(layer);
  return film;
}

DryFilm dry_film_of(const paintcore::Painting& painting) {
  const paintcore::Canvas& canvas = painting.canvas();
  const int width = canvas.width_cells();
  DryFilm film;
  for (const paintcore::DryLayer& layer : canvas.dry_layers()) {
    std::vector<float>& thickness = film.layer_thickness_mm.emplace_back(
        static_cast<std::size_t>(width) * static_cast<std::size_t>(canvas.height_cells()), 0.0f);
    for (const paintcore::DryTile& tile : layer.tiles) {
      const int x0 = (tile.tile_index % canvas.tiles_x()) * kTileSize;
      const int y0 = (tile.tile_index / canvas.tiles_x()) * kTileSize;
      for (int cell = 0; cell < kTileCells; ++cell) {
        const int x = x0 + cell % kTileSize, y = y0 + cell / kTileSize;
        if (x >= width || y >= canvas.height_cells()) continue;
        thickness[static_cast<std::size_t>(y) * static_cast<std::size_t>(width) +
                  static_cast<std::size_t>(x)] = tile.volume_mm[static_cast<std::size_t>(cell)];
      }
    }
  }
  return film;
}

void crack_painting(paintcore::Painting& painting, const CraquelureSettings& settings) {
  if (painting.canvas().dry_layers().empty()) {
    throw std::runtime_error("craquelure: the painting has no dry paint to crack (dry it first)");
  }
  CrackMap map = crack_map_of(painting);
  const DryFilm film = dry_film_of(painting);
  generate_craquelure(map, film.film(), settings);
  set_painting_cracks(painting, map);
}

void stamp_crack(paintcore::Painting& painting, const CrackStroke& stroke) {
  CrackMap map = crack_map_of(painting);
  stamp_crack(map, stroke);
  set_painting_cracks(painting, map);
}

}  // namespace impasto::cracks
