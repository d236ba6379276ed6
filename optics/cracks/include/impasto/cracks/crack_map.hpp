#pragma once
// Where a painting is cracked: per canvas cell, the cavity's shape and size and the layer
// its walls expose. Stored sparsely in 64x64-cell tiles: only tiles that hold a crack exist,
// so a painting without cracks allocates nothing.
#include <array>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <vector>

#include "impasto/cracks/cavity.hpp"

namespace impasto::cracks {

// Layer exposed by a crack's walls: the canvas ground, or dry paint layer k (0 = lowest).
inline constexpr std::uint8_t kCanvasGround = 0xFF;

struct CrackCell {
  float depth_mm = 0.0f;       // L; 0 means no crack in this cell
  float half_width_mm = 0.0f;  // R
  CavityShape shape = CavityShape::VGroove;
  std::uint8_t exposed_layer = kCanvasGround;

  bool has_crack() const { return depth_mm > 0.0f; }
  CavityDims dims() const { return {depth_mm, half_width_mm}; }
};

class CrackMap {
 public:
  static constexpr int kTileSize = 64;
  static constexpr int kMaxSide = 1 << 17;  // cells; beyond this a size is taken as an error

  // Throws std::runtime_error for sizes outside [1, kMaxSide] or a cell size that is not
  // finite and positive.
  CrackMap(int width_cells, int height_cells, double cell_mm);

  int width() const { return width_; }
  int height() const { return height_; }
  double cell_mm() const { return cell_mm_; }
  int tiles_x() const { return tiles_x_; }
  int tiles_y() const { return tiles_y_; }

  // The cell at (x, y); an empty cell where there is no crack (or outside the map).
  CrackCell at(int x, int y) const;
  // Sets a cell. A crack cell allocates its tile on first use; an empty cell frees a tile
  // left without cracks. Throws std::out_of_range outside the map, std::runtime_error for
  // NaN, negative or infinite sizes.
  void set(int x, int y, const CrackCell& cell);

  bool tile_has_cracks(int tile_x, int tile_y) const;
  std::size_t allocated_tiles() const { return allocated_tiles_; }
  std::size_t crack_cells() const;
  // Heap bytes held by the tiles (0 for a painting without cracks).
  std::size_t memory_bytes() const;

  // Calls fn(x, y, cell) for every crack cell, tile by tile in row-major order.
  template <class Fn>
  void for_each_crack(Fn&& fn) const {
    for (int ty = 0; ty < tiles_y_ && allocated_tiles_ > 0; ++ty) {
      for (int tx = 0; tx < tiles_x_; ++tx) {
        const Tile* tile = tile_at(tx, ty);
        if (tile == nullptr) continue;
        for (int i = 0; i < kTileSize * kTileSize; ++i) {
          if (tile->cells[i].has_crack()) {
            fn(tx * kTileSize + i % kTileSize, ty * kTileSize + i / kTileSize, tile->cells[i]);
          }
        }
      }
    }
  }

 private:
  struct Tile {
    std::array<CrackCell, kTileSize * kTileSize> cells{};
    int crack_count = 0;
  };
  const Tile* tile_at(int tx, int ty) const {
    return tiles_.empty() ? nullptr : tiles_[static_cast<std::size_t>(ty) * tiles_x_ + tx].get();
  }

  int width_, height_;
  double cell_mm_;
  int tiles_x_, tiles_y_;
  std::vector<std::unique_ptr<Tile>> tiles_;  // empty until the first crack
  std::size_t allocated_tiles_ = 0;
};

// Number of 8-connected groups of crack cells (0 for a map without cracks).
std::size_t count_crack_networks(const CrackMap& map);

}  // namespace impasto::cracks
