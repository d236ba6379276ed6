// Painting::coarsened: the painting on a coarser canvas for a small picture of it (a
// thumbnail renders a few hundred cells across, not the whole canvas). Each coarse cell holds
// the mean of the block of cells it covers: heights and pigment amounts alike, so a block's
// paint is its cells' paint mixed (concentration = summed amounts / summed volume).
#include <algorithm>
#include <map>
#include <stdexcept>
#include <string>

#include "impasto/paintcore/paint_surface.hpp"
#include "painting_impl.hpp"

namespace impasto::paintcore {
namespace {

// A dry layer's tile being summed: its volume and every slot's amounts.
struct DrySums {
  std::vector<float> volume_mm;
  std::vector<float> pigment_mm;  // slot-major, every slot
};

}  // namespace

Painting Painting::coarsened(int factor) const {
  const Impl& p = *impl_;
  const Canvas& fine = p.canvas;
  if (factor < 1 || factor > kMaxCanvasCells)
    throw std::runtime_error("coarsened painting: field 'factor' must be in 1.." +
                             std::to_string(kMaxCanvasCells) + ", got " + std::to_string(factor));
  const int fw = fine.width_cells(), fh = fine.height_cells();
  CanvasSpec spec = fine.spec();
  spec.width_cells = (fw + factor - 1) / factor;
  spec.height_cells = (fh + factor - 1) / factor;
  spec.dpi /= factor;
  // The cloth's threads are finer than a coarse cell: sampled there they would alias into
  // noise, and their mean is flat.
  spec.weave_seed = 0;
  validate(spec);  // a dpi under 1 is refused here, naming the field
  std::unique_ptr<Impl> coarse_impl = p.resampled(spec);
  Canvas& coarse = coarse_impl->canvas;
  const int slots = slot_count();
  // The share of a coarse cell's mean that one fine cell carries. A block the canvas's edge
  // cuts counts its cells beyond the edge as bare, as the coarse canvas reaches past the edge:
  // the paint's volume stays what it was.
  const float share = 1.0f / (static_cast<float>(factor) * static_cast<float>(factor));
  // The fine cell whose medium and varnish a block shows (a finish is not averaged).
  const auto is_block_centre = [&](int x, int y) {
    const int cx = x / factor, cy = y / factor;
    return x == std::min(cx * factor + factor / 2, fw - 1) &&
           y == std::min(cy * factor + factor / 2, fh - 1);
  };
  const auto coarse_cell = [&](int x, int y) {
    const int cx = x / factor, cy = y / factor;
    return std::pair{coarse.tile_index(cx / kTileSize, cy / kTileSize),
                     (cy % kTileSize) * kTileSize + cx % kTileSize};
  };

  for (int index = 0; index < fine.tile_count(); ++index) {
    const Tile* tile = fine.tile(index);
    if (!tile) continue;
    const int tx = index % fine.tiles_x(), ty = index / fine.tiles_x();
    const bool surface = has_surface(tile);
    for (int ly = 0; ly < kTileSize && ty * kTileSize + ly < fh; ++ly)
      for (int lx = 0; lx < kTileSize && tx * kTileSize + lx < fw; ++lx) {
        const int x = tx * kTileSize + lx, y = ty * kTileSize + ly;
        const int cell = ly * kTileSize + lx;
        const auto [to_index, to_cell] = coarse_cell(x, y);
        Tile& to = coarse.ensure_tile(to_index, slots);
        const auto at = static_cast<std::size_t>(cell), to_at = static_cast<std::size_t>(to_cell);
        to.dry_height_mm[to_at] += share * tile->dry_height_mm[at];
        to.wet_volume_mm[to_at] += share * tile->wet_volume_mm[at];
        for (int s = 0; s < std::min(slots, tile->slot_count()); ++s)
          to.pigment(s)[to_cell] += share * tile->pigment(s)[cell];
        if (surface && is_block_centre(x, y)) copy_cell_surface(tile, cell, to, to_cell);
      }
  }

  coarse.dry_layers().resize(fine.dry_layers().size());
  for (std::size_t l = 0; l < fine.dry_layers().size(); ++l) {
    std::map<int, DrySums> sums;  // by coarse tile index: the layer's tiles stay in order
    for (const DryTile& dry : fine.dry_layers()[l].tiles) {
      const int tx = dry.tile_index % fine.tiles_x(), ty = dry.tile_index / fine.tiles_x();
      for (int ly = 0; ly < kTileSize && ty * kTileSize + ly < fh; ++ly)
        for (int lx = 0; lx < kTileSize && tx * kTileSize + lx < fw; ++lx) {
          const int x = tx * kTileSize + lx, y = ty * kTileSize + ly;
          const auto cell = static_cast<std::size_t>(ly * kTileSize + lx);
          const auto [to_index, to_cell] = coarse_cell(x, y);
          DrySums& to = sums[to_index];
          if (to.volume_mm.empty()) {
            to.volume_mm.assign(kTileCells, 0.0f);
            to.pigment_mm.assign(static_cast<std::size_t>(slots) * kTileCells, 0.0f);
          }
          to.volume_mm[static_cast<std::size_t>(to_cell)] += share * dry.volume_mm[cell];
          for (std::size_t k = 0; k < dry.slots.size(); ++k) {
            const int s = dry.slots[k];
            if (s >= slots) continue;
            to.pigment_mm[static_cast<std::size_t>(s) * kTileCells +
                          static_cast<std::size_t>(to_cell)] +=
                share * dry.pigment_mm[k * kTileCells + cell];
          }
        }
    }
    for (auto& [index, sum] : sums) {
      DryTile dry;
      dry.tile_index = index;
      dry.volume_mm = std::move(sum.volume_mm);
      for (int s = 0; s < slots; ++s) {
        const float* plane = sum.pigment_mm.data() + static_cast<std::size_t>(s) * kTileCells;
        if (std::none_of(plane, plane + kTileCells, [](float v) { return v != 0.0f; })) continue;
        dry.slots.push_back(static_cast<std::uint8_t>(s));
        dry.pigment_mm.insert(dry.pigment_mm.end(), plane, plane + kTileCells);
      }
      coarse.dry_layers()[l].tiles.push_back(std::move(dry));
    }
  }
  for (int index = 0; index < coarse.tile_count(); ++index) coarse.mark_dirty(index);
  return Painting(std::move(coarse_impl));
}

}  // namespace impasto::paintcore
