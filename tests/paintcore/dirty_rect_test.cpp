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
  Canvas canvas(CanvasSpec{100, 70, 300.0, 1});  // 2 x 2 tiles, the edge ones partial
  canvas.mark_dirty(0, {10, 20, 30, 25});
  canvas.mark_dirty(0, {50, 5, 90, 12});  // reaches into tile 1: clipped to tile 0
  canvas.mark_dirty(3);                   // a whole edge tile: only its cells on the canvas
  canvas.mark_dirty(2, {0, 0, 5, 5});     // outside tile 2: dirty, no cell changed
  const std::vector<DirtyTile> dirty = canvas.take_changes();
  ASSERT_EQ(dirty.size(), 3u);
  EXPECT_EQ(dirty[0].index, 0);
  EXPECT_EQ(dirty[0].cells, (CellRect{10, 5, 64, 25}));
  EXPECT_EQ(dirty[1].index, 2);
  EXPECT_TRUE(dirty[1].cells.empty());
  EXPECT_EQ(dirty[2].index, 3);
  EXPECT_EQ(dirty[2].cells, (CellRect{64, 64, 100, 70}));
  EXPECT_TRUE(canvas.take_changes().empty());
  canvas.mark_dirty(1, {70, 0, 71, 1});
  EXPECT_EQ(tile_indices(canvas.take_changes()), (std::vector<int>{1}));  // the boxes cleared
  EXPECT_TRUE(canvas.take_changes().empty());
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
  const Painting::ChangeSubscriber changes = p.subscribe_changes();
  (void)p.take_changes(changes);

  // A short move across the corner of four tiles (cell 64, 64), mid-stroke.
  std::vector<float> before = cell_values(canvas, slots);
  p.begin_stroke();
  for (int i = 0; i <= 6; ++i) p.stroke_to(pen(6.0 + 0.1 * i, 6.2 + 0.08 * i, 0.8f));
  const std::vector<float> after = cell_values(canvas, slots);
  const std::vector<DirtyTile> dirty = p.take_changes(changes);
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

// Two consumers of one painting (a window's view and a preview, say) each get every change,
// whatever the other took; a new subscriber, and one whose painting is replaced by another,
// sees the whole canvas.
TEST(DirtyRects, EachSubscriberTakesEveryChange) {
  Painting p(CanvasSpec{200, 130, 254.0, 1});  // 4 x 3 tiles
  const Painting::ChangeSubscriber view = p.subscribe_changes();
  EXPECT_EQ(p.take_changes(view).size(), 12u);  // new: all of it
  EXPECT_TRUE(p.take_changes(view).empty());
  p.set_brush(round_brush(2.0));
  p.load_brush({{"red", 1.0}}, 20.0);
  test::stroke_line(p, 2.0, 2.0, 4.0, 2.5, 0.8f);  // within tile 0
  const Painting::ChangeSubscriber preview = p.subscribe_changes();
  const std::vector<DirtyTile> seen_by_view = p.take_changes(view);
  ASSERT_FALSE(seen_by_view.empty());
  EXPECT_EQ(seen_by_view.front().index, 0);
  EXPECT_EQ(p.take_changes(preview).size(), 12u);  // what the view took is still its own

  test::stroke_line(p, 12.0, 9.0, 14.0, 9.5, 0.8f);  // tile 4 or so: both see it
  const std::vector<DirtyTile> second_view = p.take_changes(view);
  const std::vector<DirtyTile> second_preview = p.take_changes(preview);
  ASSERT_FALSE(second_view.empty());
  EXPECT_EQ(tile_indices(second_view), tile_indices(second_preview));
  for (std::size_t i = 0; i < second_view.size(); ++i)
    EXPECT_EQ(second_view[i].cells, second_preview[i].cells);
  EXPECT_TRUE(p.take_changes(view).empty());

  p = Painting(CanvasSpec{70, 70, 254.0, 1});  // 2 x 2 tiles: a new document in the slot
  EXPECT_EQ(p.take_changes(view).size(), 4u);
  EXPECT_EQ(p.take_changes(preview).size(), 4u);
  EXPECT_THROW((void)p.take_changes(Painting::ChangeSubscriber{7}), std::invalid_argument);
}

}  // namespace
}  // namespace impasto::paintcore
