#include "impasto/paintcore/changed_cells.hpp"

#include <algorithm>

namespace impasto::paintcore {

void ChangedCells::add(int index, const CellRect& cells) {
  const auto i = static_cast<std::size_t>(index);
  if (i >= changed_.size()) {
    changed_.resize(i + 1, 0);
    cells_.resize(i + 1);
  }
  if (!changed_[i]) ++count_;
  changed_[i] = 1;
  if (cells.empty()) return;
  CellRect& box = cells_[i];
  box = box.empty() ? cells
                    : CellRect{std::min(box.x0, cells.x0), std::min(box.y0, cells.y0),
                               std::max(box.x1, cells.x1), std::max(box.y1, cells.y1)};
}

void ChangedCells::add(std::span<const DirtyTile> tiles) {
  for (const DirtyTile& tile : tiles) add(tile.index, tile.cells);
}

std::vector<DirtyTile> ChangedCells::take() {
  std::vector<DirtyTile> out;
  out.reserve(static_cast<std::size_t>(count_));
  for (std::size_t i = 0; i < changed_.size() && out.size() < static_cast<std::size_t>(count_); ++i)
    if (changed_[i]) {
      out.push_back({static_cast<int>(i), cells_[i]});
      changed_[i] = 0;
      cells_[i] = {};
    }
  count_ = 0;
  return out;
}

std::vector<int> tile_indices(std::span<const DirtyTile> tiles) {
  std::vector<int> out;
  out.reserve(tiles.size());
  for (const DirtyTile& tile : tiles) out.push_back(tile.index);
  return out;
}

}  // namespace impasto::paintcore
