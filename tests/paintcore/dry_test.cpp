#include <gtest/gtest.h>

#include <cmath>

#include "test_util.hpp"

namespace impasto::paintcore {
namespace {

using test::flat_spec;
using test::relative_error;
using test::round_brush;

Painting painted() {
  Painting p(flat_spec());
  p.set_brush(round_brush());
  p.load_brush({{"red", 2.0}, {"white", 1.0}}, 5.0);
  test::stroke_line(p, 2.0, 6.0, 10.0, 6.0, 0.8f);
  p.wipe_brush();
  return p;
}

TEST(Dry, BottomFractionMovesWithItsPigments) {
  Painting p = painted();
  const PaintTotals wet = p.wet_totals();
  const float cell_volume = p.canvas().wet_volume_mm(60, 60);
  const float cell_red = p.canvas().pigment_mm(60, 60, 0);
  ASSERT_GT(cell_volume, 0.0f);
  p.dry(0.25);
  ASSERT_EQ(p.canvas().dry_layers().size(), 1u);
  EXPECT_LT(relative_error(p.dry_totals().volume, 0.25 * wet.volume), 1e-6);
  EXPECT_LT(relative_error(p.wet_totals().volume, 0.75 * wet.volume), 1e-6);
  for (int s = 0; s < 2; ++s)
    EXPECT_LT(relative_error(p.dry_totals().pigment[s], 0.25 * wet.pigment[s]), 1e-6);
  // Per cell: the dry height grew by a quarter, the concentrations are those of the wet paint.
  EXPECT_FLOAT_EQ(p.canvas().dry_height_mm(60, 60), 0.25f * cell_volume);
  EXPECT_FLOAT_EQ(p.canvas().wet_volume_mm(60, 60), cell_volume - 0.25f * cell_volume);
  const DryTile* tile = p.canvas().dry_layers()[0].find(0);
  ASSERT_NE(tile, nullptr);
  const std::size_t c = 60 * kTileSize + 60;
  EXPECT_FLOAT_EQ(tile->volume_mm[c], 0.25f * cell_volume);
  ASSERT_NE(tile->pigment(0), nullptr);
  EXPECT_NEAR(tile->pigment(0)[c] / tile->volume_mm[c], cell_red / cell_volume, 1e-6);
  // Only tiles that had paint are stored.
  EXPECT_EQ(p.canvas().dry_layers()[0].tiles.size(), p.canvas().allocated_tiles());
}

TEST(Dry, FullDryEmptiesTheWetLayerAndStacksLayers) {
  Painting p = painted();
  const double total = p.canvas_totals().volume;
  p.dry(1.0);
  EXPECT_EQ(p.wet_totals().volume, 0.0);
  EXPECT_LT(relative_error(p.canvas_totals().volume, total), 1e-9);
  p.dry(1.0);  // nothing wet: an empty layer
  EXPECT_EQ(p.canvas().dry_layers().size(), 2u);
  EXPECT_TRUE(p.canvas().dry_layers()[1].tiles.empty());
}

TEST(Dry, ThousandsOfDryStepsStayFiniteAndConserved) {
  Painting p(flat_spec(64, 64));
  p.set_brush(round_brush());
  p.load_brush({{"red", 1.0}}, 3.0);
  test::stroke_line(p, 1.0, 3.0, 5.0, 3.0, 0.8f);
  p.wipe_brush();
  p.set_undo_budget_bytes(1 << 20);
  const double total = p.canvas_totals().volume;
  for (int k = 0; k < 2000; ++k) p.dry(0.5);
  EXPECT_EQ(p.canvas().dry_layers().size(), 2000u);
  EXPECT_EQ(p.nonfinite_count(), 0u);
  EXPECT_LT(relative_error(p.canvas_totals().volume, total), 1e-5);
  // Halved 2000 times: nothing left but the smallest float (half of it rounds to zero).
  EXPECT_LT(p.wet_totals().volume, 1e-30 * total);
}

TEST(Dry, RejectsBadFractions) {
  Painting p(flat_spec());
  EXPECT_THROW(p.dry(-0.1), std::runtime_error);
  EXPECT_THROW(p.dry(1.5), std::runtime_error);
  EXPECT_THROW(p.dry(std::nan("")), std::runtime_error);
}

}  // namespace
}  // namespace impasto::paintcore
