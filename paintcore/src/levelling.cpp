#include "levelling.hpp"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <cstdint>

namespace impasto::paintcore {
namespace {

constexpr int kMaxIterations = 48;  // the flow is capped per iteration, so few suffice
// ... on a grid of kReferenceCellMm. The flow is a diffusion whose explicit iteration is
// stable only up to a step in proportion to the cell's square: a furrow a given width in mm
// spans more cells on a finer grid, and 48 capped iterations levelled less of it (fluid
// paint's furrows grew with the dpi, 0.007 mm RMS at 300 dpi, 0.027 at 1200). Finer grids
// take (kReferenceCellMm / cell)^2 times the iterations, at most kMaxFineIterations times:
// converged to 500 dpi; at 1200 dpi half the way, as the full count costs some 15 s a stroke.
constexpr double kMaxFineIterations = 4.0;

}  // namespace

double levelling_flow_mm(double h, double drop, double cell_mm, double seconds,
                         const PaintBodyInfo& body) {
  if (!(h > 0.0) || !(drop > 0.0)) return 0.0;
  const double slope = drop / cell_mm;
  const double weight = kPaintWeightPaPerMm * slope;     // shear stress per mm of depth
  const double h_yield = body.yield_stress_pa / weight;  // depth of the unyielded plug
  if (h_yield >= h) return 0.0;                          // the paint holds its slope
  const double flux_mm2_s =
      weight * (h - h_yield) * (h - h_yield) * (2.0 * h + h_yield) / (6.0 * body.viscosity_pa_s);
  // The drop the yield stress still holds at this depth; only the rest may level.
  const double held = body.yield_stress_pa / (kPaintWeightPaPerMm * h) * cell_mm;
  const double excess = std::max(drop - held, 0.0);
  // An eighth of the drop per face: a cell higher than all four neighbours by d loses at
  // most d / 2 and lands level with them (a quarter would flip a checkerboard for ever).
  return std::min({flux_mm2_s * seconds / cell_mm, 0.125 * excess, 0.25 * h});
}

LevellingReport settle_wet_paint(Canvas& canvas, const std::vector<int>& tiles, int slot_count,
                                 PaintBody body, const SimulationParams& params) {
  LevellingReport report;
  if (tiles.empty() || !(params.settle_time_s > 0.0)) return report;
  const PaintBodyInfo& info = body_info(body);
  const double cell_mm = canvas.cell_mm();
  // The working grid: the tiles' bounding box, cells outside the tiles are walls.
  int tx0 = canvas.tiles_x(), ty0 = canvas.tiles_y(), tx1 = -1, ty1 = -1;
  for (const int index : tiles) {
    const int tx = index % canvas.tiles_x(), ty = index / canvas.tiles_x();
    tx0 = std::min(tx0, tx), ty0 = std::min(ty0, ty), tx1 = std::max(tx1, tx),
    ty1 = std::max(ty1, ty);
  }
  const int w = (tx1 - tx0 + 1) * kTileSize, h = (ty1 - ty0 + 1) * kTileSize;
  const auto tiles_across = static_cast<std::size_t>(tx1 - tx0 + 1);
  std::vector<Tile*> tile_at(tiles_across * static_cast<std::size_t>(ty1 - ty0 + 1), nullptr);
  for (const int index : tiles) {
    const int tx = index % canvas.tiles_x() - tx0, ty = index / canvas.tiles_x() - ty0;
    tile_at[static_cast<std::size_t>(ty) * tiles_across + static_cast<std::size_t>(tx)] =
        canvas.tile_slot(index).get();
  }
  // Cells of edge tiles beyond the canvas are walls too.
  const int canvas_w = canvas.width_cells() - tx0 * kTileSize;
  const int canvas_h = canvas.height_cells() - ty0 * kTileSize;
  const auto locate = [&](int x, int y, Tile*& tile, int& c) {
    tile = x < w && y < h && x < canvas_w && y < canvas_h
               ? tile_at[static_cast<std::size_t>(y / kTileSize) * tiles_across +
                         static_cast<std::size_t>(x / kTileSize)]
               : nullptr;
    c = (y % kTileSize) * kTileSize + x % kTileSize;
  };
  // What crosses each east and south face of each listed tile's cells in one iteration. Only
  // the stroke's tiles are visited (not their bounding box: a long diagonal covers few of it).
  std::vector<float> east(tiles.size() * kTileCells), south(tiles.size() * kTileCells);
  // Calls body(face index, x, y) for every cell of listed tile k (bounding-box coordinates).
  const auto for_tile_cells = [&](std::size_t k, auto&& body) {
    const int x0 = (tiles[k] % canvas.tiles_x() - tx0) * kTileSize;
    const int y0 = (tiles[k] / canvas.tiles_x() - ty0) * kTileSize;
    for (int c = 0; c < kTileCells; ++c)
      body(k * kTileCells + static_cast<std::size_t>(c), x0 + c % kTileSize, y0 + c / kTileSize);
  };
  const double held_depth_drop = info.yield_stress_pa * cell_mm / kPaintWeightPaPerMm;
  const double finer = kReferenceCellMm / cell_mm;
  const int iterations = static_cast<int>(
      std::lround(kMaxIterations * std::clamp(finer * finer, 1.0, kMaxFineIterations)));
  const double seconds = params.settle_time_s / iterations;
  const auto surface = [](const Tile& t, int c) {
    return static_cast<double>(t.base_height_mm[static_cast<std::size_t>(c)]) +
           t.dry_height_mm[static_cast<std::size_t>(c)] +
           t.wet_volume_mm[static_cast<std::size_t>(c)];
  };
  // A tile's faces depend on its cells and its east and south neighbours' edges, which only
  // flows in the 3 x 3 tiles around it change: where none flowed last iteration its faces
  // are what they were, all 0, and it is not visited again.
  std::vector<int> listed_at(tile_at.size(), -1);
  for (std::size_t k = 0; k < tiles.size(); ++k) {
    const int tx = tiles[k] % canvas.tiles_x() - tx0, ty = tiles[k] / canvas.tiles_x() - ty0;
    listed_at[static_cast<std::size_t>(ty) * tiles_across + static_cast<std::size_t>(tx)] =
        static_cast<int>(k);
  }
  const int boxes_down = ty1 - ty0 + 1, boxes_across = tx1 - tx0 + 1;
  std::vector<std::uint8_t> tile_flows(tiles.size(), 1), active(tiles.size(), 1);
  for (int it = 0; it < iterations; ++it) {
    if (it > 0)
      for (std::size_t k = 0; k < tiles.size(); ++k) {
        const int tx = tiles[k] % canvas.tiles_x() - tx0, ty = tiles[k] / canvas.tiles_x() - ty0;
        std::uint8_t near = 0;
        for (int ny = std::max(ty - 1, 0); ny <= std::min(ty + 1, boxes_down - 1); ++ny)
          for (int nx = std::max(tx - 1, 0); nx <= std::min(tx + 1, boxes_across - 1); ++nx) {
            const int j = listed_at[static_cast<std::size_t>(ny) * tiles_across +
                                    static_cast<std::size_t>(nx)];
            if (j >= 0) near |= tile_flows[static_cast<std::size_t>(j)];
          }
        active[k] = near;
      }
    // 1. Fluxes from the current state (signed: > 0 flows east / south). Each face is
    // computed alone from the state: tiles in parallel, the same bits on any thread count.
    std::fill(tile_flows.begin(), tile_flows.end(), 0);
    tbb::parallel_for(std::size_t{0}, tiles.size(), [&](std::size_t k) {
      if (!active[k]) return;
      Tile* a = canvas.tile_slot(tiles[k]).get();
      const int x0 = (tiles[k] % canvas.tiles_x() - tx0) * kTileSize;
      const int y0 = (tiles[k] / canvas.tiles_x() - ty0) * kTileSize;
      float* tile_east = east.data() + k * kTileCells;
      float* tile_south = south.data() + k * kTileCells;
      for (int c = 0; c < kTileCells; ++c) {
        tile_east[c] = tile_south[c] = 0.0f;
        const int cx = c % kTileSize, cy = c / kTileSize;
        const int x = x0 + cx, y = y0 + cy;
        if (x >= canvas_w || y >= canvas_h) continue;  // beyond the canvas's edge: a wall
        const float h_a = a->wet_volume_mm[static_cast<std::size_t>(c)];
        for (int d = 0; d < 2; ++d) {
          // The neighbour east or south: in this tile but at its edge, else located.
          Tile* b;
          int cb;
          if (d == 0 ? cx + 1 < kTileSize : cy + 1 < kTileSize) {
            b = (d == 0 ? x + 1 < canvas_w : y + 1 < canvas_h) ? a : nullptr;
            cb = c + (d == 0 ? 1 : kTileSize);
          } else {
            locate(x + (d == 0), y + (d == 1), b, cb);
          }
          if (!b) continue;
          const float h_b = b->wet_volume_mm[static_cast<std::size_t>(cb)];
          if (h_a == 0.0f && h_b == 0.0f) continue;  // no wet paint on either side
          const double drop = surface(*a, c) - surface(*b, cb);
          // The yield stress holds a slope while depth x drop < yield x cell / weight
          // (levelling_flow_mm's first test); well inside that, skip the call. (The margin
          // keeps the answer exact: only cases the test itself decides are passed over.)
          if (std::abs(drop) * (drop > 0 ? h_a : h_b) < 0.999 * held_depth_drop) continue;
          const double flow = drop > 0 ? levelling_flow_mm(h_a, drop, cell_mm, seconds, info)
                                       : -levelling_flow_mm(h_b, -drop, cell_mm, seconds, info);
          (d == 0 ? tile_east : tile_south)[c] = static_cast<float>(flow);
          if (flow != 0.0) tile_flows[k] = 1;
        }
      }
    });
    if (std::none_of(tile_flows.begin(), tile_flows.end(), [](std::uint8_t f) { return f != 0; }))
      break;
    report.iterations = it + 1;
    // 2. Move paint and pigments face by face: what one cell loses, the other gains.
    for (std::size_t k = 0; k < tiles.size(); ++k) {
      if (!tile_flows[k]) continue;  // (all its faces are 0)
      for_tile_cells(k, [&](std::size_t i, int x, int y) {
        for (int d = 0; d < 2; ++d) {
          const float flow = (d == 0 ? east : south)[i];
          if (flow == 0.0f) continue;
          Tile *a, *b;
          int ca, cb;
          locate(x, y, a, ca);
          locate(x + (d == 0), y + (d == 1), b, cb);
          Tile& from = flow > 0 ? *a : *b;
          Tile& to = flow > 0 ? *b : *a;
          const auto cf = static_cast<std::size_t>(flow > 0 ? ca : cb);
          const auto ct = static_cast<std::size_t>(flow > 0 ? cb : ca);
          const float amount = std::min(std::abs(flow), from.wet_volume_mm[cf]);
          if (!(amount > 0.0f)) continue;
          const float share = amount / from.wet_volume_mm[cf];
          from.wet_volume_mm[cf] -= amount;
          to.wet_volume_mm[ct] += amount;
          for (int s = 0; s < std::min({slot_count, from.slot_count(), to.slot_count()}); ++s) {
            const float moved = from.pigment(s)[cf] * share;
            from.pigment(s)[cf] -= moved;
            to.pigment(s)[ct] += moved;
          }
          report.moved_mm3 += amount * canvas.spec().cell_area_mm2();
        }
      });
    }
  }
  if (report.iterations > 0)
    for (const int index : tiles) canvas.mark_dirty(index);
  return report;
}

}  // namespace impasto::paintcore
