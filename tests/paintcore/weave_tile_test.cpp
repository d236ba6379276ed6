// A tile's weave computed a row and a column at a time (canvas_weave_heights_mm, what
// Canvas::make_tile uses) gives the same floats as the weave cell by cell, at any DPI, origin
// and edge: paintings made before keep their bits.
#include <gtest/gtest.h>

#include <array>
#include <cstring>

#include "impasto/paintcore/canvas.hpp"
#include "impasto/paintcore/weave.hpp"

namespace impasto::paintcore {
namespace {

TEST(WeaveTile, EqualsTheWeaveCellByCellBitForBit) {
  const std::array<CanvasSpec, 5> specs{{
      {300, 200, 150.0, 1},
      {130, 70, 37.0, 0xdeadbeefull, -12345, 678},
      {200, 200, 1200.0, 42, 1ll << 39, -(1ll << 39)},
      {65, 129, 254.0, 7, -1, -1},
      {64, 64, 600.0, 0},  // flat
  }};
  for (const CanvasSpec& spec : specs) {
    const Canvas canvas(spec);
    std::array<float, kTileCells> tile{};
    for (int index = 0; index < canvas.tile_count(); ++index) {
      tile.fill(-1.0f);
      canvas.compute_base_heights(index, tile.data());
      const CellRect cells = canvas.tile_cells(index);
      int differing = 0;
      for (int y = 0; y < kTileSize; ++y)
        for (int x = 0; x < kTileSize; ++x) {
          const float got = tile[static_cast<std::size_t>(y * kTileSize + x)];
          float want = 0.0f;  // outside the canvas
          if (cells.x0 + x < cells.x1 && cells.y0 + y < cells.y1)
            want = canvas_weave_height_mm(
                spec.weave_seed,
                (static_cast<double>(spec.weave_origin_x_cells + cells.x0 + x) + 0.5) *
                    spec.cell_mm(),
                (static_cast<double>(spec.weave_origin_y_cells + cells.y0 + y) + 0.5) *
                    spec.cell_mm());
          differing += std::memcmp(&got, &want, sizeof got) != 0;
        }
      EXPECT_EQ(differing, 0) << "tile " << index << " of a " << spec.width_cells << "x"
                              << spec.height_cells << " canvas at " << spec.dpi << " dpi";
    }
  }
}

}  // namespace
}  // namespace impasto::paintcore
