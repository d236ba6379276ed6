// The dirty boxes a canvas reports: every cell a step changed lies in its tile's box, and a
// short move reports far fewer cells than the whole tiles it touches.
#include <gtest/gtest.h>

#include <map>
#include <vector>

#include "test_util.hpp"

namespace impasto::paintcore {
namespace {

using test::pen;
using test::round_brush;

TEST(DirtyRects, MarksAreClippedToTheTileAndUnited) {
  const Canvas canvas(CanvasSpec{100, 70, 300.0, 1});  // 2 x 2 tiles, the edge ones partial
  canvas.mark_dirty(0, {10, 20, 30, 25});
  canvas.mark_dirty(0, {50, 5, 90, 12});  // reaches into tile 1: clipped to tile 0
  canvas.mark_dirty(3);                   // a whole edge tile: only its cells on the canvas
  canvas.mark_dirty(2, {0, 0, 5, 5});     // outside tile 2: dirty, no cell changed
  const std::vector<DirtyTile> dirty = canvas.take_dirty_rects();
  ASSERT_EQ(dirty.size(), 3u);
  EXPECT_EQ(dirty[0].index, 0);
  EXPECT_EQ(dirty[0].cells, (CellRect{10, 5, 64, 25}));
  EXPECT_EQ(dirty[1].index, 2);
  EXPECT_TRUE(dirty[1].cells.empty());
  EXPECT_EQ(dirty[2].index, 3);
  EXPECT_EQ(dirty[2].cells, (CellRect{64, 64, 100, 70}));
  EXPECT_TRUE(canvas.take_dirty_rects().empty());
  canvas.mark_dirty(1, {70, 0, 71, 1});
  EXPECT_EQ(canvas.take_dirty_tiles(), (std::vector<int>{1}));  // and it clears the boxes
  EXPECT_TRUE(canvas.take_dirty_rects().empty());
}

// Every value a cell holds, by cell, for comparing before and after.
std::vector<float> cell_values(const Canvas& c, int slots) {
  std::vector<float> v;
  for (int y = 0; y < c.height_cells(); ++y)
    for (int x = 0; x < c.width_cells(); ++x) {
      v.push_back(c.wet_volume_mm(x, y));
      v.push_back(c.dry_height_mm(x, y));
      v.push_back(c.base_height_mm(x, y));
      for (int s = 0; s < slots; ++s) v.push_back(c.pigment_mm(x, y, s));
    }
  return v;
}

TEST(DirtyRects, CoverEveryCellAStrokeChanged) {
  Painting p(CanvasSpec{256, 256, 254.0, 7});  // 0.1 mm cells, a woven canvas, 4 x 4 tiles
  p.set_brush(round_brush(2.0));
  p.load_brush({{"red", 1.0}, {"white", 1.0}}, 20.0);
  test::stroke_line(p, 3.0, 6.0, 10.0, 7.0, 0.8f);  // paint to push around
  const int slots = p.slot_count();
  const Canvas& canvas = p.canvas();
  (void)canvas.take_dirty_rects();

  // A short move across the corner of four tiles (cell 64, 64), mid-stroke.
  std::vector<float> before = cell_values(canvas, slots);
  p.begin_stroke();
  for (int i = 0; i <= 6; ++i) p.stroke_to(pen(6.0 + 0.1 * i, 6.2 + 0.08 * i, 0.8f));
  const std::vector<float> after = cell_values(canvas, slots);
  const std::vector<DirtyTile> dirty = canvas.take_dirty_rects();
  ASSERT_GT(p.steps(), 0u);

  std::map<int, CellRect> box;
  long long boxed = 0;
  for (const DirtyTile& d : dirty) {
    box[d.index] = d.cells;
    boxed += static_cast<long long>(d.cells.x1 - d.cells.x0) * (d.cells.y1 - d.cells.y0);
  }
  const std::size_t per_cell = after.size() / (256u * 256u);
  int changed = 0;
  for (int y = 0; y < 256; ++y)
    for (int x = 0; x < 256; ++x) {
      const std::size_t first = (static_cast<std::size_t>(y) * 256 + x) * per_cell;
      bool differs = false;
      for (std::size_t k = 0; k < per_cell; ++k)
        differs = differs || after[first + k] != before[first + k];
      if (!differs) continue;
      ++changed;
      const auto it = box.find(canvas.tile_index(x / kTileSize, y / kTileSize));
      ASSERT_NE(it, box.end()) << "cell " << x << "," << y << " changed in a clean tile";
      const CellRect& r = it->second;
      EXPECT_TRUE(x >= r.x0 && x < r.x1 && y >= r.y0 && y < r.y1)
          << "cell " << x << "," << y << " outside its tile's box";
    }
  ASSERT_GT(changed, 0);
  // The boxes are tight: a fraction of the whole tiles the move touched.
  EXPECT_LT(boxed, static_cast<long long>(dirty.size()) * kTileCells / 2);
  p.end_stroke();
}

}  // namespace
}  // namespace impasto::paintcore
