#pragma once
// The cracks of a canvas as plain per-cell records: where the dry paint or the ground is
// cracked, the cavity's shape code, depth, half-width and the layer its walls expose. Kept in
// the canvas's own 64x64 tiles, only where there is a crack, so an uncracked canvas holds
// nothing. paintcore stores and saves them; the cracks library gives them meaning (the shape
// codes are its CavityShape values) and the renderer shades them.
#include <array>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <vector>

namespace impasto::paintcore {

// Walls of a crack through the whole film expose the canvas ground.
inline constexpr std::uint8_t kCrackExposesGround = 0xFF;
// Shape codes 0 .. kCrackShapeCount - 1 (the cracks library's CavityShape).
inline constexpr std::uint8_t kCrackShapeCount = 6;
// Cells of a crack tile: the canvas's 64x64 tile (canvas.hpp checks that they agree).
inline constexpr int kCrackTileCells = 64 * 64;

struct CrackRecord {
  float depth_mm = 0.0f;       // L below the surface; 0: no crack in this cell
  float half_width_mm = 0.0f;  // R, half the width of the opening
  std::uint8_t shape = 0;      // CavityShape code
  std::uint8_t exposed_layer = kCrackExposesGround;  // or dry layer k (0 = lowest)

  bool has_crack() const { return depth_mm > 0.0f; }
  bool operator==(const CrackRecord&) const = default;
};

struct CrackTile {
  std::array<CrackRecord, kCrackTileCells> cells{};  // row-major, as the canvas tile
};

class CrackLayer {
 public:
  // The crack records of tile `index`, or nullptr where that tile has no crack.
  const CrackTile* tile(int index) const {
    return index >= 0 && static_cast<std::size_t>(index) < tiles_.size()
               ? tiles_[static_cast<std::size_t>(index)].get()
               : nullptr;
  }
  // The tile, allocated (without cracks) on first use. index >= 0.
  CrackTile& ensure_tile(int index);
  // Drops a tile (it no longer holds a crack).
  void erase_tile(int index);

  bool empty() const { return allocated_tiles() == 0; }
  std::size_t allocated_tiles() const;
  std::size_t crack_cells() const;
  std::size_t memory_bytes() const;  // heap bytes; 0 for an uncracked canvas
  // One past the highest tile index that may hold a crack (0 when empty).
  int tile_extent() const { return static_cast<int>(tiles_.size()); }

  bool operator==(const CrackLayer& other) const;

 private:
  std::vector<std::unique_ptr<CrackTile>> tiles_;  // by tile index; empty until the first crack
};

// Throws std::runtime_error naming the first bad record ("cracks: tile 3 cell 120: field
// 'depth_mm' ...") unless every crack lies inside a canvas of width x height cells, has a
// finite depth in (0, 1000] mm and half-width in (0, 1000] mm, a known shape code and exposes
// the ground or one of the dry_layers dry layers (a file may name any layer: an undo of a
// drying can leave a crack on a layer that is gone). A record without a crack must be all
// zero apart from its exposed layer.
void validate_cracks(const CrackLayer& cracks, int width_cells, int height_cells,
                     std::size_t dry_layers);

}  // namespace impasto::paintcore
