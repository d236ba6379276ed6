#pragma once
// Which square blocks of a viewport's cached image still show a rough shading — a coarse
// frame's while the view moved, or a stroke's draft — so that they are refined a few at a
// time once the motion stops, and only they.
#include <cstdint>
#include <vector>

#include "impasto/render_gl/pixel_rect.hpp"

namespace impasto::render_gl {

class RoughBlocks {
 public:
  // A viewport_w × viewport_h viewport in `block`-square blocks, none rough.
  void resize(int viewport_w, int viewport_h, int block);
  void mark(const PixelRect& rect);  // every block the rectangle touches
  void mark_all();
  void clear();
  // The blocks the rectangle covers whole (the viewport's edge counts as covered): shaded
  // finely again.
  void clear_covered(const PixelRect& rect);
  // The image moved by (dx, dy) GL pixels: every block a rough block now touches is rough.
  void shift(int dx, int dy);
  // The first rough block in reading order from the top (GL rows count up) and the rough
  // blocks right after it in its row, at most max_blocks, no longer rough; empty if none.
  PixelRect take_run(int max_blocks);
  bool any() const { return count_ > 0; }
  int count() const { return count_; }
  int block() const { return block_; }

 private:
  PixelRect block_rect(int column, int row) const;
  bool rough(int column, int row) const {
    return rough_[static_cast<std::size_t>(row) * columns_ + column] != 0;
  }
  void set(int column, int row, bool rough);

  int width_ = 0, height_ = 0, block_ = 64;
  int columns_ = 0, rows_ = 0;
  std::vector<std::uint8_t> rough_;  // a flag a block, row by row from the bottom
  int count_ = 0;
};

}  // namespace impasto::render_gl
