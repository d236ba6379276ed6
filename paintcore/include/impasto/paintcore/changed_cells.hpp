#pragma once
// What changed on a canvas that one consumer has not yet taken: the tiles, each with the box
// of its cells that changed. The canvas keeps one for its painting; the painting hands what
// it gathers on to one per subscriber (Painting::take_changes), so consumers never take from
// one another.

#include <cstdint>
#include <span>
#include <vector>

namespace impasto::paintcore {

// Canvas cells [x0, x1) x [y0, y1).
struct CellRect {
  int x0 = 0, y0 = 0, x1 = 0, y1 = 0;
  bool empty() const { return x1 <= x0 || y1 <= y0; }
  bool operator==(const CellRect&) const = default;
};

// A tile changed since the last take, and the box of its cells that may have changed
// (inside the tile; empty when the tile was touched but no cell's value changed).
struct DirtyTile {
  int index = 0;
  CellRect cells;
};

class ChangedCells {
 public:
  // Tile `index` changed within `cells` (already inside the tile; empty when the tile was
  // touched but no cell's value changed): united with what it holds for that tile.
  void add(int index, const CellRect& cells);
  void add(std::span<const DirtyTile> tiles);
  // Every tile in [0, tile_count), each with the cells `tile_cells(index)` returns.
  template <typename TileCells>
  void add_all(int tile_count, TileCells tile_cells) {
    for (int index = 0; index < tile_count; ++index) add(index, tile_cells(index));
  }
  // The changed tiles in ascending order; leaves this empty.
  std::vector<DirtyTile> take();
  bool empty() const { return count_ == 0; }

 private:
  std::vector<std::uint8_t> changed_;  // by tile index, grown as tiles are added
  std::vector<CellRect> cells_;
  int count_ = 0;
};

// The tile indices of `tiles`, in their order.
std::vector<int> tile_indices(std::span<const DirtyTile> tiles);

}  // namespace impasto::paintcore
