#include "impasto/paintcore/synthetic_painting.hpp"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <cmath>
#include <stdexcept>

#include "painting_file.hpp"
#include "painting_file_io.hpp"

namespace impasto::paintcore {

namespace {

// Ridges 0.05-0.6 mm high; every slot's share varies across the tile, summing to the paint.
void fill_wet(Tile& tile, const CellRect& inside, int slots) {
  for (int cell = 0; cell < kTileCells; ++cell) {
    const int x = inside.x0 + cell % kTileSize, y = inside.y0 + cell / kTileSize;
    if (x >= inside.x1 || y >= inside.y1) continue;  // outside the canvas: stays zero
    const float ridge = 0.5f + 0.5f * static_cast<float>(std::sin(0.21 * x + 0.05 * y));
    const float v = 0.05f + 0.55f * ridge * ridge;
    const auto k = static_cast<std::size_t>(cell);
    tile.wet_volume_mm[k] = v;
    tile.dry_height_mm[k] = 0.04f;
    float left = v;
    for (int s = 0; s + 1 < slots; ++s) {
      const float share =
          0.25f + 0.25f * static_cast<float>(std::cos(0.013 * x * (s + 1) - 0.017 * y));
      tile.pigment(s)[cell] = left * share;
      left -= left * share;
    }
    if (slots > 0) tile.pigment(slots - 1)[cell] = left;
  }
}

DryTile dry_tile(int index, const CellRect& inside, int slot) {
  DryTile dry;
  dry.tile_index = index;
  dry.volume_mm.resize(kTileCells);
  dry.slots = {static_cast<std::uint8_t>(slot)};
  dry.pigment_mm.resize(kTileCells);
  for (int cell = 0; cell < kTileCells; ++cell) {
    const int x = inside.x0 + cell % kTileSize, y = inside.y0 + cell / kTileSize;
    if (x >= inside.x1 || y >= inside.y1) continue;
    const float v = 0.02f + 0.02f * static_cast<float>(std::sin(0.07 * x - 0.11 * y) + 1.0);
    dry.volume_mm[static_cast<std::size_t>(cell)] = v;
    dry.pigment_mm[static_cast<std::size_t>(cell)] = 0.8f * v;
  }
  return dry;
}

}  // namespace

std::uint64_t painting_file_wet_tile_bytes(int slots) {
  return file_io::kMinWetTileBytes + static_cast<std::uint64_t>(slots) * kTileCells * 4;
}

std::uint64_t painting_file_dry_tile_bytes(int slots) {
  return file_io::kMinDryTileBytes + static_cast<std::uint64_t>(slots) * (1 + kTileCells * 4);
}

Painting synthetic_painting(const SyntheticPaintingSpec& spec, int threads) {
  const CanvasSpec canvas_spec{spec.width_cells, spec.height_cells, 150.0, 1};
  try {
    validate(canvas_spec);
  } catch (const std::runtime_error& e) {
    throw std::invalid_argument(std::string("synthetic painting: ") + e.what());
  }
  if (!(spec.painted_share >= 0.0 && spec.painted_share <= 1.0))
    throw std::invalid_argument("synthetic painting: painted_share must be in [0, 1]");
  if (spec.slots.size() > static_cast<std::size_t>(kMaxPigmentSlots))
    throw std::invalid_argument("synthetic painting: more than 16 slots");
  if (spec.dry_layers < 0 || spec.dry_layers > 64)
    throw std::invalid_argument("synthetic painting: dry_layers must be in 0..64");
  auto impl = PaintingFile::make_impl(canvas_spec, threads);
  impl->slots = spec.slots;
  Canvas& canvas = impl->canvas;
  const int slots = static_cast<int>(spec.slots.size());
  const int tiles = canvas.tile_count();
  const auto painted =
      static_cast<int>(std::llround(spec.painted_share * static_cast<double>(tiles)));
  // Painted tile k sits at k * tiles / painted: spread evenly, ascending.
  const auto index_of = [&](int k) {
    return static_cast<int>(static_cast<long long>(k) * tiles / painted);
  };
  for (int l = 0; l < spec.dry_layers; ++l)
    canvas.dry_layers().emplace_back().tiles.resize(static_cast<std::size_t>(painted));
  impl->arena.execute([&] {
    tbb::parallel_for(tbb::blocked_range<int>(0, painted), [&](const tbb::blocked_range<int>& r) {
      for (int k = r.begin(); k != r.end(); ++k) {
        const int index = index_of(k);
        const CellRect inside = canvas.tile_cells(index);
        auto tile = canvas.make_tile(index, slots);
        fill_wet(*tile, inside, slots);
        canvas.tile_slot(index) = std::move(tile);
        for (int l = 0; l < spec.dry_layers && slots > 0; ++l)
          canvas.dry_layers()[static_cast<std::size_t>(l)].tiles[static_cast<std::size_t>(k)] =
              dry_tile(index, inside, (k + l) % slots);
      }
    });
  });
  if (slots == 0) canvas.dry_layers().clear();
  for (int k = 0; k < painted; ++k) canvas.mark_dirty(index_of(k));
  return PaintingFile::adopt(std::move(impl));
}

}  // namespace impasto::paintcore
