#include "impasto/paintcore/crack_layer.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace impasto::paintcore {

CrackTile& CrackLayer::ensure_tile(int index) {
  const auto i = static_cast<std::size_t>(index);
  if (i >= tiles_.size()) tiles_.resize(i + 1);
  if (!tiles_[i]) tiles_[i] = std::make_unique<CrackTile>();
  return *tiles_[i];
}

void CrackLayer::erase_tile(int index) {
  const auto i = static_cast<std::size_t>(index);
  if (i < tiles_.size()) tiles_[i].reset();
  while (!tiles_.empty() && !tiles_.back()) tiles_.pop_back();
  if (tiles_.empty()) tiles_.shrink_to_fit();  // an uncracked canvas holds nothing
}

std::size_t CrackLayer::allocated_tiles() const {
  return static_cast<std::size_t>(
      std::count_if(tiles_.begin(), tiles_.end(), [](const auto& t) { return t != nullptr; }));
}

std::size_t CrackLayer::crack_cells() const {
  std::size_t count = 0;
  for (const auto& tile : tiles_) {
    if (!tile) continue;
    count +=
        static_cast<std::size_t>(std::count_if(tile->cells.begin(), tile->cells.end(),
                                               [](const CrackRecord& r) { return r.has_crack(); }));
  }
  return count;
}

std::size_t CrackLayer::memory_bytes() const {
  return tiles_.capacity() * sizeof(std::unique_ptr<CrackTile>) +
         allocated_tiles() * sizeof(CrackTile);
}

bool CrackLayer::operator==(const CrackLayer& other) const {
  const int extent = std::max(tile_extent(), other.tile_extent());
  for (int index = 0; index < extent; ++index) {
    const CrackTile* a = tile(index);
    const CrackTile* b = other.tile(index);
    if ((a == nullptr) != (b == nullptr)) return false;
    if (a != nullptr && a->cells != b->cells) return false;
  }
  return true;
}

void validate_cracks(const CrackLayer& cracks, int width_cells, int height_cells,
                     std::size_t dry_layers) {
  constexpr int kSide = 64;
  constexpr float kMaxSizeMm = 1000.0f;
  const int tiles_x = (width_cells + kSide - 1) / kSide;
  const int tiles_y = (height_cells + kSide - 1) / kSide;
  for (int index = 0; index < cracks.tile_extent(); ++index) {
    const CrackTile* tile = cracks.tile(index);
    if (tile == nullptr) continue;
    const auto fail = [&](int cell, const std::string& field, const std::string& why) {
      throw std::runtime_error("cracks: tile " + std::to_string(index) + " cell " +
                               std::to_string(cell) + ": field '" + field + "' " + why);
    };
    if (index >= tiles_x * tiles_y) {
      fail(0, "tile", "is outside the canvas's " + std::to_string(tiles_x * tiles_y) + " tiles");
    }
    const int x0 = (index % tiles_x) * kSide;
    const int y0 = (index / tiles_x) * kSide;
    for (int cell = 0; cell < kCrackTileCells; ++cell) {
      const CrackRecord& r = tile->cells[static_cast<std::size_t>(cell)];
      const bool size_ok = std::isfinite(r.depth_mm) && r.depth_mm >= 0.0f &&
                           r.depth_mm <= kMaxSizeMm && std::isfinite(r.half_width_mm) &&
                           r.half_width_mm >= 0.0f && r.half_width_mm <= kMaxSizeMm;
      if (!size_ok) fail(cell, "depth_mm/half_width_mm", "must be finite and in [0, 1000] mm");
      if (!r.has_crack()) {
        if (r.half_width_mm != 0.0f || r.shape != 0) {
          fail(cell, "depth_mm", "is 0 (no crack) but the cell has a width or shape");
        }
        continue;
      }
      if (x0 + cell % kSide >= width_cells || y0 + cell / kSide >= height_cells) {
        fail(cell, "cell", "lies outside the canvas");
      }
      if (!(r.half_width_mm > 0.0f)) fail(cell, "half_width_mm", "must be > 0 for a crack");
      if (r.shape >= kCrackShapeCount) {
        fail(cell, "shape",
             "code " + std::to_string(r.shape) + " is unknown (0.." +
                 std::to_string(kCrackShapeCount - 1) + ")");
      }
      if (r.exposed_layer != kCrackExposesGround && r.exposed_layer >= dry_layers) {
        fail(cell, "exposed_layer",
             "dry layer " + std::to_string(r.exposed_layer) + " does not exist (the painting has " +
                 std::to_string(dry_layers) + ")");
      }
    }
  }
}

}  // namespace impasto::paintcore
