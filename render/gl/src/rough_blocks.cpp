#include "impasto/render_gl/rough_blocks.hpp"

#include <algorithm>

namespace impasto::render_gl {

void RoughBlocks::resize(int viewport_w, int viewport_h, int block) {
  width_ = std::max(0, viewport_w);
  height_ = std::max(0, viewport_h);
  block_ = std::max(1, block);
  columns_ = (width_ + block_ - 1) / block_;
  rows_ = (height_ + block_ - 1) / block_;
  rough_.assign(static_cast<std::size_t>(columns_) * rows_, 0);
  count_ = 0;
}

PixelRect RoughBlocks::block_rect(int column, int row) const {
  return {column * block_, row * block_, std::min(width_, (column + 1) * block_),
          std::min(height_, (row + 1) * block_)};
}

void RoughBlocks::set(int column, int row, bool rough) {
  std::uint8_t& flag = rough_[static_cast<std::size_t>(row) * columns_ + column];
  count_ += static_cast<int>(rough) - static_cast<int>(flag);
  flag = rough ? 1 : 0;
}

void RoughBlocks::mark(const PixelRect& rect) {
  const int x0 = std::max(0, rect.x0), y0 = std::max(0, rect.y0);
  const int x1 = std::min(width_, rect.x1), y1 = std::min(height_, rect.y1);
  if (x1 <= x0 || y1 <= y0) return;
  for (int row = y0 / block_; row <= (y1 - 1) / block_; ++row)
    for (int column = x0 / block_; column <= (x1 - 1) / block_; ++column) set(column, row, true);
}

void RoughBlocks::mark_all() {
  mark({0, 0, width_, height_});
}

void RoughBlocks::clear() {
  std::fill(rough_.begin(), rough_.end(), 0);
  count_ = 0;
}

void RoughBlocks::clear_covered(const PixelRect& rect) {
  if (count_ == 0) return;
  for (int row = 0; row < rows_; ++row) {
    for (int column = 0; column < columns_; ++column) {
      const PixelRect b = block_rect(column, row);
      if (b.x0 >= rect.x0 && b.y0 >= rect.y0 && b.x1 <= rect.x1 && b.y1 <= rect.y1)
        set(column, row, false);
    }
  }
}

void RoughBlocks::shift(int dx, int dy) {
  if (count_ == 0) return;
  std::vector<PixelRect> moved;
  for (int row = 0; row < rows_; ++row) {
    for (int column = 0; column < columns_; ++column) {
      if (!rough(column, row)) continue;
      const PixelRect b = block_rect(column, row);
      moved.push_back({b.x0 + dx, b.y0 + dy, b.x1 + dx, b.y1 + dy});
    }
  }
  clear();
  for (const PixelRect& r : moved) mark(r);
}

PixelRect RoughBlocks::take_run(int max_blocks) {
  for (int row = rows_ - 1; row >= 0; --row) {
    for (int column = 0; column < columns_; ++column) {
      if (!rough(column, row)) continue;
      int end = column;
      while (end < columns_ && end - column < std::max(1, max_blocks) && rough(end, row)) {
        set(end, row, false);
        ++end;
      }
      const PixelRect first = block_rect(column, row);
      return {first.x0, first.y0, block_rect(end - 1, row).x1, first.y1};
    }
  }
  return {};
}

}  // namespace impasto::render_gl
