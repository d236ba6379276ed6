// Changing the brush's head or size keeps its paint: resampled onto the new grid, every
// total kept (the ledger books float rounding), only on covered cells, undone exactly.
#include <gtest/gtest.h>

#include <cmath>

#include "impasto/paintcore/brush_resample.hpp"
#include "test_util.hpp"

namespace impasto::paintcore {
namespace {

using test::flat_spec;
using test::relative_error;
using test::round_brush;
using test::stroke_line;

// A painting whose brush carries two pigments, unevenly after a stroke.
Painting dirty_brush_painting() {
  Painting p(flat_spec(160, 160, 254.0));
  p.set_brush(round_brush(2.0));
  p.load_brush({{"red", 1.0}, {"blue", 0.4}}, 6.0);
  stroke_line(p, 3.0, 4.0, 12.0, 6.0, 0.7f);
  return p;
}

// What the ledger says the brush holds: loaded - wiped - canvas.
PaintTotals ledger_brush(const Painting& p) {
  PaintTotals t = test::expected_totals(p);
  const PaintTotals canvas = p.canvas_totals();
  t.volume -= canvas.volume;
  for (std::size_t s = 0; s < t.pigment.size(); ++s) t.pigment[s] -= canvas.pigment[s];
  return t;
}

TEST(BrushResample, SizeAndHeadChangesKeepEveryTotal) {
  Painting p = dirty_brush_painting();
  const PaintTotals start = p.brush_totals();
  ASSERT_GT(start.volume, 0.0);
  ASSERT_EQ(start.pigment.size(), 2u);
  // The stroke left the ledger and the brush a float rounding apart; brush changes must not
  // widen that gap at all.
  const PaintTotals start_said = ledger_brush(p);
  const BrushSettings changes[] = {round_brush(3.7),      round_brush(1.1),      {"flat", 2.5, 0.5},
                                   {"filbert", 0.9, 0.3}, round_brush(6.0, 0.8), {"flat", 0.3, 0.5},
                                   round_brush(2.0)};
  for (const BrushSettings& settings : changes) {
    p.set_brush(settings);
    const PaintTotals now = p.brush_totals();
    const PaintTotals said = ledger_brush(p);
    SCOPED_TRACE(settings.head + " " + std::to_string(settings.size_mm) + " mm, " +
                 std::to_string(p.brush().cells_across()) + " cells across");
    EXPECT_LT(relative_error(now.volume, start.volume), 1e-6);
    EXPECT_NEAR(now.volume - said.volume, start.volume - start_said.volume, 1e-12 * start.volume);
    for (std::size_t s = 0; s < start.pigment.size(); ++s) {
      EXPECT_LT(relative_error(now.pigment[s], start.pigment[s]), 1e-6) << "slot " << s;
      EXPECT_NEAR(now.pigment[s] - said.pigment[s], start.pigment[s] - start_said.pigment[s],
                  1e-12 * start.volume)
          << "slot " << s;
    }
  }
  // The kept paint still paints, and the whole session stays conserved.
  stroke_line(p, 3.0, 10.0, 12.0, 10.0, 0.8f);
  const PaintTotals present = test::present_totals(p);
  const PaintTotals expected = test::expected_totals(p);
  EXPECT_LT(relative_error(present.volume, expected.volume), 1e-6);
  EXPECT_LT(p.brush_totals().volume, start.volume);
}

TEST(BrushResample, PaintStaysOnTheCoveredCells) {
  Painting p = dirty_brush_painting();
  for (const BrushSettings& settings :
       {BrushSettings{"flat", 2.0, 0.5}, BrushSettings{"filbert", 3.3, 0.5}, round_brush(1.3)}) {
    p.set_brush(settings);
    const Brush& brush = p.brush();
    double on_covered = 0.0;
    for (std::size_t c = 0; c < brush.cell_count(); ++c) {
      if (brush.covers()[c]) {
        on_covered += brush.volume_mm()[c];
        continue;
      }
      EXPECT_EQ(brush.volume_mm()[c], 0.0f) << settings.head << " cell " << c;
      for (int s = 0; s < brush.slot_count(); ++s)
        EXPECT_EQ(brush.pigment_mm()[static_cast<std::size_t>(s) * brush.cell_count() + c], 0.0f);
    }
    EXPECT_GT(on_covered, 0.0) << settings.head;
  }
}

TEST(BrushResample, UndoRestoresTheOldBrushAndRedoTheNew) {
  Painting p = dirty_brush_painting();
  const std::uint64_t before = p.state_hash();
  const std::vector<float> volume = p.brush().volume_mm();
  p.set_brush({"flat", 4.2, 0.5});
  const std::uint64_t after = p.state_hash();
  ASSERT_NE(after, before);
  ASSERT_TRUE(p.undo());
  EXPECT_EQ(p.state_hash(), before);
  EXPECT_EQ(p.brush().settings().head, "round");
  EXPECT_EQ(p.brush().volume_mm(), volume);
  ASSERT_TRUE(p.redo());
  EXPECT_EQ(p.state_hash(), after);
}

TEST(BrushResample, ThePaintKeepsItsBody) {
  Painting p(flat_spec());
  p.set_brush(round_brush(2.0));
  p.load_brush({{"red", 1.0}}, 4.0, PaintBody::paste);
  p.set_brush({"flat", 3.1, 0.5});
  EXPECT_EQ(p.brush().body(), PaintBody::paste);
}

TEST(BrushResample, SameGridSameHeadKeepsEveryCell) {
  Painting p = dirty_brush_painting();
  const std::vector<float> volume = p.brush().volume_mm();
  const std::vector<float> pigment = p.brush().pigment_mm();
  const double wiped = p.wiped_totals().volume;
  p.set_brush(round_brush(2.0, 0.9));  // only the stiffness changes
  EXPECT_EQ(p.brush().volume_mm(), volume);
  EXPECT_EQ(p.brush().pigment_mm(), pigment);
  EXPECT_EQ(p.wiped_totals().volume, wiped);
}

// The layout of the paint on the head is kept: paint on the left half of a brush lands on the
// left half of a larger one.
TEST(BrushResample, KeepsWhereThePaintSits) {
  const BrushHead head = load_named_brush_head("flat");
  Brush from(head, {"flat", 1.0, 0.5}, 0.1, 1);  // 10 cells across
  Brush to(head, {"flat", 2.3, 0.5}, 0.1, 0);    // 23 cells across
  const int n = from.cells_across();
  for (int y = 0; y < n; ++y)
    for (int x = 0; x < n / 2; ++x) {
      const auto c = static_cast<std::size_t>(y * n + x);
      if (!from.covers()[c]) continue;
      from.volume_mm()[c] = 0.3f;
      from.pigment_mm()[c] = 0.3f;
    }
  const PaintTotals lost = resample_brush_paint(from, to, 0.01);
  ASSERT_EQ(to.slot_count(), 1);
  double left = 0.0, right = 0.0, before = 0.0;
  for (float v : from.volume_mm()) before += v;
  const int m = to.cells_across();
  for (int y = 0; y < m; ++y)
    for (int x = 0; x < m; ++x) {
      const double v = to.volume_mm()[static_cast<std::size_t>(y * m + x)];
      // Cell 11 straddles the middle of an odd grid.
      (x < m / 2 ? left : x > m / 2 ? right : left) += v;
    }
  EXPECT_EQ(right, 0.0);
  EXPECT_LT(relative_error(left + lost.volume / 0.01, before), 1e-12);
  EXPECT_LT(std::abs(lost.volume / 0.01), 1e-6 * before);
}

}  // namespace
}  // namespace impasto::paintcore
