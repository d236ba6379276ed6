// Painting::refined: the painting on a finer canvas for export at a larger scale. Heights and
// pigment amounts are interpolated between cell centres by Catmull-Rom (C1: the relief's
// slope, hence its shading, has no steps at the old cells' edges), clamped at zero.
#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <stdexcept>

#include "impasto/files/memory_budget.hpp"
#include "painting_impl.hpp"

namespace impasto::paintcore {
namespace {

// Catmull-Rom weights of samples i-1, i, i+1, i+2 at t in [0, 1) past sample i.
std::array<float, 4> catmull_rom(double t) {
  const double t2 = t * t, t3 = t2 * t;
  return {static_cast<float>(0.5 * (-t3 + 2 * t2 - t)),
          static_cast<float>(0.5 * (3 * t3 - 5 * t2 + 2)),
          static_cast<float>(0.5 * (-3 * t3 + 4 * t2 + t)), static_cast<float>(0.5 * (t3 - t2))};
}

// Along one axis of a fine tile: for each fine cell, its first coarse sample (i - 1, not yet
// clamped) and weights; and the coarse range [lo, hi) the tile reads, clamped to the canvas.
struct Axis {
  std::array<int, kTileSize> first{};
  std::array<std::array<float, 4>, kTileSize> weights{};
  int lo = 0, hi = 0;
};

Axis fine_axis(int fine_start, int fine_count, int scale, int coarse_size) {
  Axis a;
  a.lo = coarse_size;
  for (int k = 0; k < fine_count; ++k) {
    const double u = (fine_start + k + 0.5) / scale - 0.5;  // in coarse cell centres
    const int i = static_cast<int>(std::floor(u));
    a.first[static_cast<std::size_t>(k)] = i - 1;
    a.weights[static_cast<std::size_t>(k)] = catmull_rom(u - i);
    a.lo = std::min(a.lo, std::clamp(i - 1, 0, coarse_size - 1));
    a.hi = std::max(a.hi, std::clamp(i + 2, 0, coarse_size - 1) + 1);
  }
  return a;
}

using CellValue = std::function<float(int x, int y)>;

// One field over a fine tile (kTileCells values, row-major), interpolated from `value` at
// coarse cells (edges clamped), then clamped at zero.
void interpolate(const Axis& ax, const Axis& ay, int nx, int ny, int coarse_w, int coarse_h,
                 const CellValue& value, float* out) {
  const int ww = ax.hi - ax.lo, wh = ay.hi - ay.lo;
  std::vector<float> window(static_cast<std::size_t>(ww * wh));
  for (int y = 0; y < wh; ++y)
    for (int x = 0; x < ww; ++x)
      window[static_cast<std::size_t>(y * ww + x)] = value(ax.lo + x, ay.lo + y);
  const auto at = [&](int x, int y) {
    x = std::clamp(x, 0, coarse_w - 1) - ax.lo;
    y = std::clamp(y, 0, coarse_h - 1) - ay.lo;
    return window[static_cast<std::size_t>(y * ww + x)];
  };
  std::vector<float> rows(static_cast<std::size_t>(wh * nx));  // along x first
  for (int y = 0; y < wh; ++y)
    for (int k = 0; k < nx; ++k) {
      const auto& w = ax.weights[static_cast<std::size_t>(k)];
      const int i = ax.first[static_cast<std::size_t>(k)];
      float sum = 0.0f;
      for (int j = 0; j < 4; ++j) sum += w[static_cast<std::size_t>(j)] * at(i + j, ay.lo + y);
      rows[static_cast<std::size_t>(y * nx + k)] = sum;
    }
  std::fill(out, out + kTileCells, 0.0f);
  for (int m = 0; m < ny; ++m) {
    const auto& w = ay.weights[static_cast<std::size_t>(m)];
    const int i = ay.first[static_cast<std::size_t>(m)];
    for (int k = 0; k < nx; ++k) {
      float sum = 0.0f;
      for (int j = 0; j < 4; ++j) {
        const int row = std::clamp(i + j, 0, coarse_h - 1) - ay.lo;
        sum += w[static_cast<std::size_t>(j)] * rows[static_cast<std::size_t>(row * nx + k)];
      }
      out[m * kTileSize + k] = std::max(sum, 0.0f);
    }
  }
}

bool any_nonzero(const float* values, std::size_t count) {
  return std::any_of(values, values + count, [](float v) { return v != 0.0f; });
}

}  // namespace

Painting Painting::refined(int scale) const {
  const Impl& p = *impl_;
  if (scale < 1 || scale > 16)
    throw std::runtime_error("refined painting: field 'scale' must be in 1..16, got " +
                             std::to_string(scale));
  const Canvas& coarse = p.canvas;
  CanvasSpec spec = coarse.spec();
  spec.width_cells = static_cast<int>(std::min<long long>(
      static_cast<long long>(spec.width_cells) * scale, std::numeric_limits<int>::max()));
  spec.height_cells = static_cast<int>(std::min<long long>(
      static_cast<long long>(spec.height_cells) * scale, std::numeric_limits<int>::max()));
  spec.dpi *= scale;
  spec.weave_origin_x_cells *= scale;  // the same cloth, sampled finer
  spec.weave_origin_y_cells *= scale;
  validate(spec);
  // Each painted tile becomes up to (scale + 1)^2 fine ones (its paint reaches two cells out).
  files::check_allocation("refined painting", "the finer canvas's tiles",
                          static_cast<std::uint64_t>(coarse.allocated_tiles()) * (scale + 1) *
                              (scale + 1) * (3 + static_cast<std::uint64_t>(slot_count())) *
                              kTileCells * sizeof(float));
  std::unique_ptr<Impl> fine_impl = p.resampled(spec);
  Canvas& fine = fine_impl->canvas;
  const int cw = coarse.width_cells(), ch = coarse.height_cells();
  const int slots = slot_count();
  // Whether any coarse tile in the cell range holds something (here: per `held`).
  const auto any_tile = [&](const Axis& ax, const Axis& ay, const std::function<bool(int)>& held) {
    for (int ty = ay.lo / kTileSize; ty <= (ay.hi - 1) / kTileSize; ++ty)
      for (int tx = ax.lo / kTileSize; tx <= (ax.hi - 1) / kTileSize; ++tx)
        if (held(coarse.tile_index(tx, ty))) return true;
    return false;
  };
  std::vector<float> plane(kTileCells);
  fine.dry_layers().resize(coarse.dry_layers().size());
  for (int fty = 0; fty < fine.tiles_y(); ++fty)
    for (int ftx = 0; ftx < fine.tiles_x(); ++ftx) {
      const int nx = std::min(kTileSize, fine.width_cells() - ftx * kTileSize);
      const int ny = std::min(kTileSize, fine.height_cells() - fty * kTileSize);
      const Axis ax = fine_axis(ftx * kTileSize, nx, scale, cw);
      const Axis ay = fine_axis(fty * kTileSize, ny, scale, ch);
      const int index = fine.tile_index(ftx, fty);
      const auto run = [&](const CellValue& value, float* out) {
        interpolate(ax, ay, nx, ny, cw, ch, value, out);
      };
      if (any_tile(ax, ay, [&](int i) { return coarse.tile(i) != nullptr; })) {
        Tile& tile = fine.ensure_tile(index, slots);
        run([&](int x, int y) { return coarse.dry_height_mm(x, y); }, tile.dry_height_mm.data());
        run([&](int x, int y) { return coarse.wet_volume_mm(x, y); }, tile.wet_volume_mm.data());
        for (int s = 0; s < slots; ++s) {
          float* out = tile.pigment(s);
          run([&](int x, int y) { return coarse.pigment_mm(x, y, s); }, out);
          for (int c = 0; c < kTileCells; ++c)
            if (tile.wet_volume_mm[static_cast<std::size_t>(c)] == 0.0f) out[c] = 0.0f;
        }
      }
      // Media and varnish: each fine cell takes its coarse cell's (a finish, not a height).
      if (any_tile(ax, ay, [&](int i) { return has_surface(coarse.tile(i)); })) {
        Tile& tile = fine.ensure_tile(index, slots);
        for (int y = 0; y < ny; ++y)
          for (int x = 0; x < nx; ++x) {
            const int cx = (ftx * kTileSize + x) / scale, cy = (fty * kTileSize + y) / scale;
            copy_cell_surface(coarse.tile(coarse.tile_index(cx / kTileSize, cy / kTileSize)),
                              (cy % kTileSize) * kTileSize + cx % kTileSize, tile,
                              y * kTileSize + x);
          }
      }
      for (std::size_t l = 0; l < coarse.dry_layers().size(); ++l) {
        const DryLayer& layer = coarse.dry_layers()[l];
        if (!any_tile(ax, ay, [&](int i) { return layer.find(i) != nullptr; })) continue;
        const auto dry_at = [&](int x, int y, int slot) {
          const DryTile* t = layer.find(coarse.tile_index(x / kTileSize, y / kTileSize));
          if (!t) return 0.0f;
          const auto c = static_cast<std::size_t>((y % kTileSize) * kTileSize + x % kTileSize);
          if (slot < 0) return t->volume_mm[c];
          const float* amounts = t->pigment(slot);
          return amounts ? amounts[c] : 0.0f;
        };
        DryTile dry;
        dry.tile_index = index;
        dry.volume_mm.resize(kTileCells);
        run([&](int x, int y) { return dry_at(x, y, -1); }, dry.volume_mm.data());
        for (int s = 0; s < slots; ++s) {
          run([&](int x, int y) { return dry_at(x, y, s); }, plane.data());
          for (int c = 0; c < kTileCells; ++c)
            if (dry.volume_mm[static_cast<std::size_t>(c)] == 0.0f) plane[c] = 0.0f;
          if (!any_nonzero(plane.data(), kTileCells)) continue;
          dry.slots.push_back(static_cast<std::uint8_t>(s));
          dry.pigment_mm.insert(dry.pigment_mm.end(), plane.begin(), plane.end());
        }
        fine.dry_layers()[l].tiles.push_back(std::move(dry));  // tiles visited in index order
      }
    }
  for (int index = 0; index < fine.tile_count(); ++index) fine.mark_dirty(index);
  return Painting(std::move(fine_impl));
}

}  // namespace impasto::paintcore
