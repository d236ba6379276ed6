#include "impasto/cracks/crack_map.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

namespace impasto::cracks {

CrackMap::CrackMap(int width_cells, int height_cells, double cell_mm)
    : width_(width_cells), height_(height_cells), cell_mm_(cell_mm) {
  if (width_cells < 1 || height_cells < 1 || width_cells > kMaxSide || height_cells > kMaxSide) {
    throw std::runtime_error("crack map size " + std::to_string(width_cells) + "x" +
                             std::to_string(height_cells) + " cells is outside [1, " +
                             std::to_string(kMaxSide) + "]");
  }
  if (!(cell_mm > 0.0) || !std::isfinite(cell_mm)) {
    throw std::runtime_error("crack map cell_mm must be finite and > 0, got " +
                             std::to_string(cell_mm));
  }
  tiles_x_ = (width_ + kTileSize - 1) / kTileSize;
  tiles_y_ = (height_ + kTileSize - 1) / kTileSize;
}

CrackCell CrackMap::at(int x, int y) const {
  if (x < 0 || y < 0 || x >= width_ || y >= height_) return {};
  const Tile* tile = tile_at(x / kTileSize, y / kTileSize);
  return tile ? tile->cells[(y % kTileSize) * kTileSize + x % kTileSize] : CrackCell{};
}

void CrackMap::set(int x, int y, const CrackCell& cell) {
  if (x < 0 || y < 0 || x >= width_ || y >= height_) {
    throw std::out_of_range("crack cell (" + std::to_string(x) + ", " + std::to_string(y) +
                            ") outside the " + std::to_string(width_) + "x" +
                            std::to_string(height_) + " map");
  }
  if (!(cell.depth_mm >= 0.0f) || !std::isfinite(cell.depth_mm) || !(cell.half_width_mm >= 0.0f) ||
      !std::isfinite(cell.half_width_mm) || (cell.has_crack() && !(cell.half_width_mm > 0.0f))) {
    throw std::runtime_error("crack cell (" + std::to_string(x) + ", " + std::to_string(y) +
                             "): depth_mm and half_width_mm must be finite, >= 0, and a crack "
                             "needs half_width_mm > 0");
  }
  if (!cell.has_crack() && tiles_.empty()) return;  // nothing to clear, nothing allocated
  if (tiles_.empty()) tiles_.resize(static_cast<std::size_t>(tiles_x_) * tiles_y_);
  auto& tile = tiles_[static_cast<std::size_t>(y / kTileSize) * tiles_x_ + x / kTileSize];
  if (!tile) {
    if (!cell.has_crack()) return;
    tile = std::make_unique<Tile>();
    ++allocated_tiles_;
  }
  CrackCell& slot = tile->cells[(y % kTileSize) * kTileSize + x % kTileSize];
  tile->crack_count += static_cast<int>(cell.has_crack()) - static_cast<int>(slot.has_crack());
  slot = cell.has_crack() ? cell : CrackCell{};
  if (tile->crack_count == 0) {
    tile.reset();
    if (--allocated_tiles_ == 0)
      std::vector<std::unique_ptr<Tile>>().swap(tiles_);  // holds nothing
  }
}

bool CrackMap::tile_has_cracks(int tile_x, int tile_y) const {
  if (tile_x < 0 || tile_y < 0 || tile_x >= tiles_x_ || tile_y >= tiles_y_) return false;
  return tile_at(tile_x, tile_y) != nullptr;
}

std::size_t CrackMap::crack_cells() const {
  std::size_t n = 0;
  for (const auto& tile : tiles_) n += tile ? static_cast<std::size_t>(tile->crack_count) : 0;
  return n;
}

std::size_t CrackMap::memory_bytes() const {
  return tiles_.capacity() * sizeof(std::unique_ptr<Tile>) + allocated_tiles_ * sizeof(Tile);
}

std::size_t count_crack_networks(const CrackMap& map) {
  if (map.allocated_tiles() == 0) return 0;
  const int w = map.width(), h = map.height();
  std::vector<std::uint8_t> seen(static_cast<std::size_t>(w) * h, 0);
  std::vector<std::pair<int, int>> stack;
  std::size_t networks = 0;
  map.for_each_crack([&](int x0, int y0, const CrackCell&) {
    if (seen[static_cast<std::size_t>(y0) * w + x0]) return;
    ++networks;
    seen[static_cast<std::size_t>(y0) * w + x0] = 1;
    stack.push_back({x0, y0});
    while (!stack.empty()) {
      const auto [x, y] = stack.back();
      stack.pop_back();
      for (int dy = -1; dy <= 1; ++dy) {
        for (int dx = -1; dx <= 1; ++dx) {
          const int nx = x + dx, ny = y + dy;
          if (nx < 0 || ny < 0 || nx >= w || ny >= h) continue;
          auto& s = seen[static_cast<std::size_t>(ny) * w + nx];
          if (s || !map.at(nx, ny).has_crack()) continue;
          s = 1;
          stack.push_back({nx, ny});
        }
      }
    }
  });
  return networks;
}

}  // namespace impasto::cracks
