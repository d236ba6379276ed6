// Painting::coarsened: the coarser canvas a thumbnail renders.
#include <gtest/gtest.h>

#include <stdexcept>

#include "test_util.hpp"

namespace impasto::paintcore {
namespace {

TEST(Coarsened, KeepsThePaintAndTheSizeInMillimetres) {
  const Painting p = test::crossed_strokes(150, 1.0);
  for (int factor : {1, 2, 3, 8}) {
    const Painting c = p.coarsened(factor);
    // 150 and 70 cells: the last block of each row and column is partial when 3 or 8.
    EXPECT_EQ(c.canvas().width_cells(), (150 + factor - 1) / factor);
    EXPECT_EQ(c.canvas().height_cells(), (70 + factor - 1) / factor);
    EXPECT_DOUBLE_EQ(c.canvas().cell_mm(), p.canvas().cell_mm() * factor);
    EXPECT_EQ(c.pigment_slots(), p.pigment_slots());
    ASSERT_EQ(c.canvas().dry_layers().size(), p.canvas().dry_layers().size());
    EXPECT_EQ(c.nonfinite_count(), 0u);
    // A coarse cell is the mean of its block and covers its area: the totals (mm^3) stay,
    // also where the canvas's edge cuts a block (the strokes reach the bottom edge).
    EXPECT_NEAR(c.wet_totals().volume, p.wet_totals().volume, 1e-4 * p.wet_totals().volume);
    EXPECT_NEAR(c.dry_totals().volume, p.dry_totals().volume, 1e-4 * p.dry_totals().volume);
    for (int s = 0; s < p.slot_count(); ++s)
      EXPECT_NEAR(c.canvas_totals().pigment[static_cast<std::size_t>(s)],
                  p.canvas_totals().pigment[static_cast<std::size_t>(s)],
                  1e-4 * p.canvas_totals().volume);
  }
}

TEST(Coarsened, ACellIsTheMeanOfItsBlock) {
  const Painting p = test::crossed_strokes(150, 1.0);
  const Painting c = p.coarsened(4);
  for (int cy = 0; cy < c.canvas().height_cells(); ++cy)
    for (int cx = 0; cx < c.canvas().width_cells(); ++cx) {
      // 150 x 70 cells: the last row and column of blocks are cut by the edge, bare beyond it.
      double wet = 0.0, dry = 0.0;
      const int n = 16;
      for (int y = 4 * cy; y < std::min(4 * cy + 4, 70); ++y)
        for (int x = 4 * cx; x < std::min(4 * cx + 4, 150); ++x) {
          wet += p.canvas().wet_volume_mm(x, y);
          dry += p.canvas().dry_height_mm(x, y);
        }
      ASSERT_NEAR(c.canvas().wet_volume_mm(cx, cy), wet / n, 1e-5) << cx << "," << cy;
      ASSERT_NEAR(c.canvas().dry_height_mm(cx, cy), dry / n, 1e-5) << cx << "," << cy;
      // The cloth's mean is flat: a coarse cell would alias its threads into noise.
      ASSERT_EQ(c.canvas().base_height_mm(cx, cy), 0.0f);
    }
}

TEST(Coarsened, RefusesAFactorThatLeavesLessThanOneDpi) {
  const Painting p = test::crossed_strokes(150, 1.0);
  EXPECT_NO_THROW(p.coarsened(254));
  EXPECT_THROW(p.coarsened(255), std::runtime_error);
  EXPECT_THROW(p.coarsened(0), std::runtime_error);
}

}  // namespace
}  // namespace impasto::paintcore
