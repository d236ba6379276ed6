// Crop and resize (canvas_reframe.hpp): paint kept cell for cell, the weave moved with it,
// what is cut away booked, and undo/redo exact.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>

#include "impasto/paintcore/canvas_reframe.hpp"
#include "impasto/paintcore/weave.hpp"
#include "test_util.hpp"

namespace impasto::paintcore {
namespace {

using test::round_brush;
using test::stroke_line;

// Every quantity of one cell, to compare cells across frames.
struct CellState {
  float base, dry, wet;
  std::vector<float> pigment;
  bool operator==(const CellState&) const = default;
};

CellState cell(const Painting& p, int x, int y) {
  const Canvas& c = p.canvas();
  CellState s{c.base_height_mm(x, y), c.dry_height_mm(x, y), c.wet_volume_mm(x, y), {}};
  for (int k = 0; k < p.slot_count(); ++k) s.pigment.push_back(c.pigment_mm(x, y, k));
  return s;
}

// A woven 200x150 canvas with two pigments, wet paint over a dried layer, strokes that cross
// tile edges and reach every side.
Painting painted() {
  Painting p(CanvasSpec{200, 150, 254.0, 3}, 1);
  p.set_brush(round_brush(3.0));
  p.load_brush({{"red", 1.0}}, 40.0);
  stroke_line(p, 1.0, 1.0, 19.0, 14.0, 0.8f);
  p.dry(0.5);
  p.load_brush({{"blue", 1.0}}, 40.0);
  stroke_line(p, 19.0, 1.0, 1.0, 14.0, 0.9f);
  return p;
}

void expect_kept(const Painting& before, const Painting& after, const CanvasFrame& f) {
  int kept = 0;
  for (int y = 0; y < before.canvas().height_cells(); ++y)
    for (int x = 0; x < before.canvas().width_cells(); ++x) {
      const int nx = x + f.offset_x_cells, ny = y + f.offset_y_cells;
      if (nx < 0 || ny < 0 || nx >= f.width_cells || ny >= f.height_cells) continue;
      ASSERT_EQ(cell(before, x, y), cell(after, nx, ny)) << "cell " << x << "," << y;
      ++kept;
    }
  EXPECT_GT(kept, 0);
}

TEST(CanvasReframe, CropKeepsPaintCellForCellAndBooksWhatIsCut) {
  Painting p = painted();
  const Painting reference = painted();
  const PaintTotals total_before = p.canvas_totals();
  const std::uint64_t hash_before = p.state_hash();
  const CanvasFrame frame = crop_frame(37, 21, 100, 90);  // edges inside tiles
  const PaintTotals cut = p.reframe_canvas(frame);
  EXPECT_EQ(p.canvas().width_cells(), 100);
  EXPECT_EQ(p.canvas().height_cells(), 90);
  expect_kept(reference, p, frame);
  // Kept + cut = what there was; the ledger still balances.
  const PaintTotals after = p.canvas_totals();
  EXPECT_GT(cut.volume, 0.0);
  EXPECT_NEAR(after.volume + cut.volume, total_before.volume, 1e-9 * total_before.volume);
  for (std::size_t s = 0; s < after.pigment.size(); ++s)
    EXPECT_NEAR(after.pigment[s] + cut.pigment[s], total_before.pigment[s],
                1e-9 * total_before.volume);
  EXPECT_NEAR(test::present_totals(p).volume, test::expected_totals(p).volume,
              1e-6 * total_before.volume);
  EXPECT_EQ(p.nonfinite_count(), 0u);
  const std::uint64_t hash_cropped = p.state_hash();
  ASSERT_TRUE(p.undo());
  EXPECT_EQ(p.state_hash(), hash_before);
  EXPECT_EQ(p.canvas().width_cells(), 200);
  ASSERT_TRUE(p.redo());
  EXPECT_EQ(p.state_hash(), hash_cropped);
}

TEST(CanvasReframe, GrowAroundTheCentreAddsCleanCanvasWithItsWeave) {
  Painting p = painted();
  const Painting reference = painted();
  const CanvasFrame frame = anchored_frame(200, 150, 301, 260, CanvasAnchor::kCenter);
  EXPECT_EQ(frame.offset_x_cells, 50);
  EXPECT_EQ(frame.offset_y_cells, 55);
  const PaintTotals cut = p.reframe_canvas(frame);
  EXPECT_EQ(cut.volume, 0.0);
  expect_kept(reference, p, frame);
  const CanvasSpec& spec = p.canvas().spec();
  const double cell = spec.cell_mm();
  for (int y : {0, 10, 259})
    for (int x : {0, 49, 300}) {
      EXPECT_EQ(p.canvas().wet_volume_mm(x, y), 0.0f);
      EXPECT_EQ(p.canvas().dry_height_mm(x, y), 0.0f);
      // The cloth continues beyond the old edge: cell (x, y) is old cell (x - 50, y - 55).
      EXPECT_EQ(p.canvas().base_height_mm(x, y),
                canvas_weave_height_mm(3, (x - 50 + 0.5) * cell, (y - 55 + 0.5) * cell));
    }
  EXPECT_NEAR(p.canvas_totals().volume, reference.canvas_totals().volume,
              1e-9 * reference.canvas_totals().volume);
}

TEST(CanvasReframe, StrokesAfterAReframePaintAsOnTheReopenedPainting) {
  // The stepper caches the weave of tiles it reaches but has not painted, by tile index: a
  // reframe changes what an index means. A dab whose window reaches tile (1, 1) without
  // painting it, a crop that keeps the tile grid's indices, then a dab into that tile: it must
  // paint as it does on the cropped painting saved and reopened (a fresh stepper).
  const auto dab = [](Painting& p, double at_mm) {
    stroke_line(p, at_mm, at_mm, at_mm + 0.05, at_mm, 0.9f, 3);
  };
  Painting p(CanvasSpec{256, 256, 254.0, 5}, 1);
  p.set_brush(round_brush(3.0));
  p.load_brush({{"red", 1.0}}, 40.0);
  dab(p, 4.9);  // reaches tile (1, 1): its weave is cached, no paint arrives
  ASSERT_EQ(p.canvas().tile(1, 1), nullptr);
  p.reframe_canvas(crop_frame(29, 17, 200, 200));
  ASSERT_EQ(p.canvas().tiles_x(), 4);  // as before: index 5 is still tile (1, 1)
  ASSERT_EQ(p.canvas().tile(1, 1), nullptr);
  const auto file = std::filesystem::temp_directory_path() /
                    ("impasto_reframe_weave_" + std::to_string(::getpid()) + ".impasto");
  p.save(file);
  Painting reopened = Painting::load(file, 1);
  std::filesystem::remove(file);
  dab(p, 6.4);  // paints into tile (1, 1), on whatever weave the stepper takes for it
  dab(reopened, 6.4);
  EXPECT_EQ(p.state_hash(), reopened.state_hash());
  for (int index = 0; index < p.canvas().tile_count(); ++index) {
    const Tile* tile = p.canvas().tile(index);
    if (!tile) continue;
    std::array<float, kTileCells> expected;
    p.canvas().compute_base_heights(index, expected.data());
    ASSERT_EQ(tile->base_height_mm, expected) << "tile " << index;
  }
}

TEST(CanvasReframe, UndoThroughStrokesAfterAReframeIsExact) {
  Painting p = painted();
  const std::uint64_t h0 = p.state_hash();
  p.reframe_canvas(anchored_frame(200, 150, 120, 200, CanvasAnchor::kBottomRight));
  const std::uint64_t h1 = p.state_hash();
  stroke_line(p, 2.0, 2.0, 10.0, 15.0, 0.9f);
  const std::uint64_t h2 = p.state_hash();
  ASSERT_NE(h1, h2);
  ASSERT_TRUE(p.undo());
  EXPECT_EQ(p.state_hash(), h1);
  ASSERT_TRUE(p.undo());
  EXPECT_EQ(p.state_hash(), h0);
  ASSERT_TRUE(p.redo());
  ASSERT_TRUE(p.redo());
  EXPECT_EQ(p.state_hash(), h2);
}

TEST(CanvasReframe, AnInvalidFrameChangesNothing) {
  Painting p = painted();
  const std::uint64_t h = p.state_hash();
  EXPECT_THROW(p.reframe_canvas(crop_frame(0, 0, 0, 10)), std::runtime_error);
  EXPECT_THROW(p.reframe_canvas(crop_frame(200, 0, 10, 10)), std::runtime_error);  // beside it
  EXPECT_THROW(p.reframe_canvas(crop_frame(0, 0, kMaxCanvasCells + 1, 10)), std::runtime_error);
  EXPECT_EQ(p.state_hash(), h);
  EXPECT_EQ(p.undo_depth(), painted().undo_depth());
}

TEST(CanvasReframe, TheSameFrameIsNoStep) {
  Painting p = painted();
  const std::size_t depth = p.undo_depth();
  const std::uint64_t h = p.state_hash();
  EXPECT_EQ(p.reframe_canvas(anchored_frame(200, 150, 200, 150, CanvasAnchor::kCenter)).volume,
            0.0);
  EXPECT_EQ(p.undo_depth(), depth);
  EXPECT_EQ(p.state_hash(), h);
}

TEST(CanvasReframe, AnchorsByName) {
  EXPECT_EQ(parse_canvas_anchor("centre"), CanvasAnchor::kCenter);
  EXPECT_EQ(parse_canvas_anchor("bottom-left"), CanvasAnchor::kBottomLeft);
  EXPECT_THROW(parse_canvas_anchor("middle"), std::runtime_error);
  const CanvasFrame f = anchored_frame(100, 80, 60, 40, CanvasAnchor::kBottomRight);
  EXPECT_EQ(f.offset_x_cells, -40);
  EXPECT_EQ(f.offset_y_cells, -40);
  const CanvasFrame g = anchored_frame(100, 80, 160, 80, CanvasAnchor::kTopLeft);
  EXPECT_EQ(g.offset_x_cells, 0);
  EXPECT_EQ(g.offset_y_cells, 0);
}

}  // namespace
}  // namespace impasto::paintcore
