#include "impasto/paintcore/canvas.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "impasto/paintcore/weave.hpp"

namespace impasto::paintcore {

void validate(const CanvasSpec& spec) {
  const auto fail = [](const std::string& field, const std::string& why) {
    throw std::runtime_error("canvas spec: field '" + field + "' " + why);
  };
  if (spec.width_cells <= 0 || spec.width_cells > kMaxCanvasCells)
    fail("width_cells", "must be in 1.." + std::to_string(kMaxCanvasCells) + ", got " +
                            std::to_string(spec.width_cells));
  if (spec.height_cells <= 0 || spec.height_cells > kMaxCanvasCells)
    fail("height_cells", "must be in 1.." + std::to_string(kMaxCanvasCells) + ", got " +
                             std::to_string(spec.height_cells));
  // 1 dpi is a 25 mm cell; 100000 dpi is a 0.25 um cell: beyond either nothing makes sense.
  if (!std::isfinite(spec.dpi) || spec.dpi < 1.0 || spec.dpi > 100000.0)
    fail("dpi", "must be a finite number in 1..100000, got " + std::to_string(spec.dpi));
  // Each crop or resize moves the cloth by less than the canvas: far beyond any real history.
  constexpr std::int64_t kMaxWeaveOrigin = std::int64_t{1} << 40;
  if (spec.weave_origin_x_cells > kMaxWeaveOrigin || spec.weave_origin_x_cells < -kMaxWeaveOrigin)
    fail("weave_origin_x_cells",
         "must be within +-2^40, got " + std::to_string(spec.weave_origin_x_cells));
  if (spec.weave_origin_y_cells > kMaxWeaveOrigin || spec.weave_origin_y_cells < -kMaxWeaveOrigin)
    fail("weave_origin_y_cells",
         "must be within +-2^40, got " + std::to_string(spec.weave_origin_y_cells));
}

const float* DryTile::pigment(int slot) const {
  const auto it = std::lower_bound(slots.begin(), slots.end(), static_cast<std::uint8_t>(slot));
  if (slot < 0 || slot > 255 || it == slots.end() || *it != slot) return nullptr;
  return pigment_mm.data() + static_cast<std::size_t>(it - slots.begin()) * kTileCells;
}

const DryTile* DryLayer::find(int tile_index) const {
  const auto it =
      std::lower_bound(tiles.begin(), tiles.end(), tile_index,
                       [](const DryTile& t, int index) { return t.tile_index < index; });
  return it != tiles.end() && it->tile_index == tile_index ? &*it : nullptr;
}

Canvas::Canvas(CanvasSpec spec) : spec_(spec) {
  validate(spec_);
  tiles_x_ = (spec_.width_cells + kTileSize - 1) / kTileSize;
  tiles_y_ = (spec_.height_cells + kTileSize - 1) / kTileSize;
  tiles_.resize(static_cast<std::size_t>(tile_count()));
}

std::size_t Canvas::allocated_tiles() const {
  return static_cast<std::size_t>(
      std::count_if(tiles_.begin(), tiles_.end(), [](const auto& t) { return t != nullptr; }));
}

std::unique_ptr<Tile> Canvas::make_tile(int index, int slot_count) const {
  auto tile = std::make_unique<Tile>();
  tile->pigment_mm.assign(static_cast<std::size_t>(slot_count) * kTileCells, 0.0f);
  compute_base_heights(index, tile->base_height_mm.data());
  return tile;
}

void Canvas::compute_base_heights(int index, float* out) const {
  std::fill(out, out + kTileCells, 0.0f);
  const int x0 = (index % tiles_x_) * kTileSize;
  const int y0 = (index / tiles_x_) * kTileSize;
  const int nx = std::min(kTileSize, spec_.width_cells - x0);
  const int ny = std::min(kTileSize, spec_.height_cells - y0);
  const double cell = spec_.cell_mm();
  std::array<double, kTileSize> x_mm{}, y_mm{};
  for (int x = 0; x < nx; ++x)
    x_mm[static_cast<std::size_t>(x)] =
        (static_cast<double>(spec_.weave_origin_x_cells + x0 + x) + 0.5) * cell;
  for (int y = 0; y < ny; ++y)
    y_mm[static_cast<std::size_t>(y)] =
        (static_cast<double>(spec_.weave_origin_y_cells + y0 + y) + 0.5) * cell;
  canvas_weave_heights_mm(spec_.weave_seed, x_mm.data(), nx, y_mm.data(), ny, out, kTileSize);
}

Tile& Canvas::ensure_tile(int index, int slot_count) {
  auto& slot = tiles_[static_cast<std::size_t>(index)];
  if (!slot) slot = make_tile(index, slot_count);
  if (slot->slot_count() < slot_count)
    slot->pigment_mm.resize(static_cast<std::size_t>(slot_count) * kTileCells, 0.0f);
  return *slot;
}

namespace {
std::size_t local_index(int x, int y) {
  return static_cast<std::size_t>((y % kTileSize) * kTileSize + x % kTileSize);
}
}  // namespace

float Canvas::base_height_mm(int x, int y) const {
  if (const Tile* t = tile(x / kTileSize, y / kTileSize))
    return t->base_height_mm[local_index(x, y)];
  return canvas_weave_height_mm(
      spec_.weave_seed, (static_cast<double>(spec_.weave_origin_x_cells + x) + 0.5) * cell_mm(),
      (static_cast<double>(spec_.weave_origin_y_cells + y) + 0.5) * cell_mm());
}

float Canvas::dry_height_mm(int x, int y) const {
  const Tile* t = tile(x / kTileSize, y / kTileSize);
  return t ? t->dry_height_mm[local_index(x, y)] : 0.0f;
}

float Canvas::wet_volume_mm(int x, int y) const {
  const Tile* t = tile(x / kTileSize, y / kTileSize);
  return t ? t->wet_volume_mm[local_index(x, y)] : 0.0f;
}

float Canvas::pigment_mm(int x, int y, int slot) const {
  const Tile* t = tile(x / kTileSize, y / kTileSize);
  const float* p = t ? t->pigment(slot) : nullptr;
  return p ? p[local_index(x, y)] : 0.0f;
}

CellRect Canvas::tile_cells(int index) const {
  const int x0 = index % tiles_x_ * kTileSize, y0 = index / tiles_x_ * kTileSize;
  return {x0, y0, std::min(x0 + kTileSize, width_cells()),
          std::min(y0 + kTileSize, height_cells())};
}

void Canvas::mark_dirty(int index) {
  mark_dirty(index, tile_cells(index));
}

void Canvas::mark_dirty(int index, const CellRect& cells) {
  const CellRect tile = tile_cells(index);
  changes_.add(index, {std::max(cells.x0, tile.x0), std::max(cells.y0, tile.y0),
                       std::min(cells.x1, tile.x1), std::min(cells.y1, tile.y1)});
}

}  // namespace impasto::paintcore
