// Totals, hash, counts and memory of a Painting: the checks tests and tools rely on.
#include <algorithm>
#include <cmath>

#include "hasher.hpp"
#include "painting_impl.hpp"

namespace impasto::paintcore {
namespace {

double sum(const float* values, std::size_t count) {
  double total = 0.0;
  for (std::size_t i = 0; i < count; ++i) total += values[i];
  return total;
}

std::size_t count_nonfinite(const float* values, std::size_t count) {
  std::size_t n = 0;
  for (std::size_t i = 0; i < count; ++i) n += !std::isfinite(values[i]);
  return n;
}

const std::array<float, kTileCells>& zero_tile_values() {
  static const std::array<float, kTileCells> zeros{};
  return zeros;
}

}  // namespace

PaintTotals Painting::wet_totals() const {
  const Canvas& canvas = impl_->canvas;
  PaintTotals totals{0.0, std::vector<double>(static_cast<std::size_t>(slot_count()), 0.0)};
  for (int index = 0; index < canvas.tile_count(); ++index) {
    const Tile* tile = canvas.tile(index);
    if (!tile) continue;
    totals.volume += sum(tile->wet_volume_mm.data(), kTileCells);
    for (int s = 0; s < slot_count(); ++s)
      if (const float* p = tile->pigment(s))
        totals.pigment[static_cast<std::size_t>(s)] += sum(p, kTileCells);
  }
  const double area = canvas.spec().cell_area_mm2();
  totals.volume *= area;
  for (double& v : totals.pigment) v *= area;
  return totals;
}

PaintTotals Painting::dry_totals() const {
  const Canvas& canvas = impl_->canvas;
  PaintTotals totals{0.0, std::vector<double>(static_cast<std::size_t>(slot_count()), 0.0)};
  for (const DryLayer& layer : canvas.dry_layers())
    for (const DryTile& tile : layer.tiles) {
      totals.volume += sum(tile.volume_mm.data(), tile.volume_mm.size());
      for (std::size_t k = 0; k < tile.slots.size(); ++k)
        totals.pigment[tile.slots[k]] += sum(tile.pigment_mm.data() + k * kTileCells, kTileCells);
    }
  const double area = canvas.spec().cell_area_mm2();
  totals.volume *= area;
  for (double& v : totals.pigment) v *= area;
  return totals;
}

PaintTotals Painting::canvas_totals() const {
  PaintTotals totals = wet_totals();
  accumulate(totals, dry_totals());
  return totals;
}

PaintThickness Painting::paint_thickness(double painted_above_mm) const {
  const Canvas& canvas = impl_->canvas;
  std::vector<float> thickness;
  for (int index = 0; index < canvas.tile_count(); ++index) {
    const Tile* tile = canvas.tile(index);
    if (!tile) continue;
    for (int c = 0; c < kTileCells; ++c) {
      const float t = tile->wet_volume_mm[c] + tile->dry_height_mm[c];
      if (t > painted_above_mm) thickness.push_back(t);
    }
  }
  PaintThickness result;
  result.painted_cells = thickness.size();
  if (thickness.empty()) return result;
  // The value below which share q of the cells lie (nearest rank).
  const auto quantile = [&](double q) {
    const auto rank =
        static_cast<std::size_t>(std::ceil(q * static_cast<double>(thickness.size()))) - 1;
    const auto at =
        thickness.begin() + static_cast<std::ptrdiff_t>(std::min(rank, thickness.size() - 1));
    std::nth_element(thickness.begin(), at, thickness.end());
    return static_cast<double>(*at);
  };
  result.median_mm = quantile(0.5);
  result.p90_mm = quantile(0.9);
  result.p99_mm = quantile(0.99);
  result.max_mm = *std::max_element(thickness.begin(), thickness.end());
  return result;
}

PaintTotals Painting::brush_totals() const {
  const Brush& brush = impl_->brush;
  PaintTotals totals{0.0, std::vector<double>(static_cast<std::size_t>(slot_count()), 0.0)};
  if (brush.empty()) return totals;
  const std::size_t cells = brush.cell_count();
  totals.volume = sum(brush.volume_mm().data(), cells);
  for (int s = 0; s < std::min(slot_count(), brush.slot_count()); ++s)
    totals.pigment[static_cast<std::size_t>(s)] =
        sum(brush.pigment_mm().data() + static_cast<std::size_t>(s) * cells, cells);
  const double area = impl_->canvas.spec().cell_area_mm2();
  totals.volume *= area;
  for (double& v : totals.pigment) v *= area;
  return totals;
}

PaintTotals Painting::loaded_totals() const {
  PaintTotals totals = impl_->ledger.loaded;
  totals.pigment.resize(static_cast<std::size_t>(slot_count()), 0.0);
  return totals;
}

PaintTotals Painting::wiped_totals() const {
  PaintTotals totals = impl_->ledger.wiped;
  totals.pigment.resize(static_cast<std::size_t>(slot_count()), 0.0);
  return totals;
}

std::uint64_t Painting::state_hash() const {
  const Impl& p = *impl_;
  const Canvas& canvas = p.canvas;
  Hasher h;
  h.value(canvas.spec().width_cells);
  h.value(canvas.spec().height_cells);
  h.value(canvas.spec().dpi);
  h.value(canvas.spec().weave_seed);
  // The cloth's origin only once a crop has moved it, so other paintings hash as they did.
  if (canvas.spec().weave_origin_x_cells != 0 || canvas.spec().weave_origin_y_cells != 0) {
    h.value(canvas.spec().weave_origin_x_cells);
    h.value(canvas.spec().weave_origin_y_cells);
  }
  h.value(p.slots.size());
  for (const std::string& name : p.slots) h.string(name);
  const int slots = slot_count();
  // The wet layer, tile by tile; a slot a tile lacks hashes as zeros.
  for (int index = 0; index < canvas.tile_count(); ++index) {
    const Tile* tile = canvas.tile(index);
    if (!tile) continue;
    h.value(index);
    h.bytes(tile->dry_height_mm.data(), sizeof(float) * kTileCells);
    h.bytes(tile->wet_volume_mm.data(), sizeof(float) * kTileCells);
    for (int s = 0; s < slots; ++s) {
      const float* values = tile->pigment(s);
      h.bytes(values ? values : zero_tile_values().data(), sizeof(float) * kTileCells);
    }
  }
  h.value(canvas.dry_layers().size());
  for (const DryLayer& layer : canvas.dry_layers()) {
    h.value(layer.tiles.size());
    for (const DryTile& tile : layer.tiles) {
      h.value(tile.tile_index);
      h.bytes(tile.volume_mm.data(), sizeof(float) * tile.volume_mm.size());
      h.bytes(tile.slots.data(), tile.slots.size());
      h.bytes(tile.pigment_mm.data(), sizeof(float) * tile.pigment_mm.size());
    }
  }
  const Brush& brush = p.brush;
  h.value(brush.cells_across());
  if (!brush.empty()) {
    h.string(brush.head().name);
    h.value(brush.settings().size_mm);
    h.value(brush.settings().stiffness);
    h.value(static_cast<int>(brush.body()));
    h.bytes(brush.volume_mm().data(), sizeof(float) * brush.cell_count());
    const std::vector<float> zeros(brush.cell_count(), 0.0f);
    for (int s = 0; s < slots; ++s)
      h.bytes(s < brush.slot_count()
                  ? brush.pigment_mm().data() + static_cast<std::size_t>(s) * brush.cell_count()
                  : zeros.data(),
              sizeof(float) * brush.cell_count());
  }
  for (const PaintTotals* t : {&p.ledger.loaded, &p.ledger.wiped}) {
    h.value(t->volume);
    for (int s = 0; s < slots; ++s)
      h.value(static_cast<std::size_t>(s) < t->pigment.size()
                  ? t->pigment[static_cast<std::size_t>(s)]
                  : 0.0);
  }
  // Cracks only where there are some, so an uncracked painting hashes as it always did.
  const CrackLayer& cracks = canvas.cracks();
  for (int index = 0; index < cracks.tile_extent(); ++index) {
    if (const CrackTile* tile = cracks.tile(index)) {
      h.value(index);
      for (const CrackRecord& c : tile->cells) {
        h.value(c.depth_mm);
        h.value(c.half_width_mm);
        h.value(c.shape);
        h.value(c.exposed_layer);
      }
    }
  }
  // Media and varnish only where there are some (paint_surface.hpp), likewise.
  for (int index = 0; index < canvas.tile_count(); ++index) {
    const Tile* tile = canvas.tile(index);
    if (!has_surface(tile)) continue;
    h.value(index);
    h.bytes(tile->medium.data(), sizeof(float) * tile->medium.size());
    h.bytes(tile->varnish.data(), sizeof(float) * tile->varnish.size());
  }
  if (brush.medium().share != 0.0f) {
    h.value(brush.medium().share);
    h.value(brush.medium().log_rms);
  }
  return h.digest();
}

std::size_t Painting::nonfinite_count() const {
  const Impl& p = *impl_;
  std::size_t n = 0;
  for (int index = 0; index < p.canvas.tile_count(); ++index)
    if (const Tile* tile = p.canvas.tile(index)) {
      n += count_nonfinite(tile->dry_height_mm.data(), kTileCells);
      n += count_nonfinite(tile->wet_volume_mm.data(), kTileCells);
      n += count_nonfinite(tile->pigment_mm.data(), tile->pigment_mm.size());
      n += count_nonfinite(tile->medium.data(), tile->medium.size());
      n += count_nonfinite(tile->varnish.data(), tile->varnish.size());
    }
  for (const DryLayer& layer : p.canvas.dry_layers())
    for (const DryTile& tile : layer.tiles) {
      n += count_nonfinite(tile.volume_mm.data(), tile.volume_mm.size());
      n += count_nonfinite(tile.pigment_mm.data(), tile.pigment_mm.size());
    }
  n += count_nonfinite(p.brush.volume_mm().data(), p.brush.volume_mm().size());
  n += count_nonfinite(p.brush.pigment_mm().data(), p.brush.pigment_mm().size());
  return n;
}

std::size_t Painting::memory_bytes() const {
  const Impl& p = *impl_;
  std::size_t bytes = sizeof(Impl) + p.canvas.tile_count() * sizeof(std::unique_ptr<Tile>);
  for (int index = 0; index < p.canvas.tile_count(); ++index)
    if (const Tile* tile = p.canvas.tile(index)) bytes += tile_bytes(*tile);
  for (const DryLayer& layer : p.canvas.dry_layers()) bytes += dry_layer_bytes(layer);
  return bytes + brush_bytes(p.brush) + p.history.bytes() + p.canvas.cracks().memory_bytes();
}

}  // namespace impasto::paintcore
