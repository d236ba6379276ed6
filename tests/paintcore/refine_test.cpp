// Painting::refined: the finer canvas that an export at 2x or 4x renders.
#include <gtest/gtest.h>

#include "test_util.hpp"

namespace impasto::paintcore {
namespace {

TEST(Refined, KeepsTheSizeInMillimetresTheWeaveAndThePaint) {
  const Painting p = test::crossed_strokes(100, 0.5);
  for (int scale : {1, 2, 4}) {
    const Painting f = p.refined(scale);
    EXPECT_EQ(f.canvas().width_cells(), 100 * scale);
    EXPECT_EQ(f.canvas().height_cells(), 70 * scale);
    EXPECT_DOUBLE_EQ(f.canvas().cell_mm() * scale, p.canvas().cell_mm());
    EXPECT_EQ(f.pigment_slots(), p.pigment_slots());
    EXPECT_EQ(f.canvas().dry_layers().size(), 1u);
    EXPECT_EQ(f.nonfinite_count(), 0u);
    // Interpolation keeps the volume of smooth paint (clamping adds a little at the edges).
    EXPECT_NEAR(f.wet_totals().volume, p.wet_totals().volume, 0.02 * p.wet_totals().volume);
    EXPECT_NEAR(f.dry_totals().volume, p.dry_totals().volume, 0.02 * p.dry_totals().volume);
    for (int s = 0; s < p.slot_count(); ++s)
      EXPECT_NEAR(f.canvas_totals().pigment[static_cast<std::size_t>(s)],
                  p.canvas_totals().pigment[static_cast<std::size_t>(s)],
                  0.02 * p.canvas_totals().volume);
  }
  // At scale 1 the interpolation passes through the cells: the same paint exactly.
  const Painting same = p.refined(1);
  for (int y = 0; y < 70; ++y)
    for (int x = 0; x < 100; ++x) {
      ASSERT_EQ(same.canvas().wet_volume_mm(x, y), p.canvas().wet_volume_mm(x, y));
      ASSERT_EQ(same.canvas().base_height_mm(x, y), p.canvas().base_height_mm(x, y));
    }
}

TEST(Refined, TheReliefHasNoStepsAtTheOldCellsEdges) {
  const Painting p = test::crossed_strokes(100, 0.5);
  const Painting f = p.refined(4);
  // Along a row through the paint: the fine surface's slope changes smoothly; a blocky copy
  // would be flat inside each old cell and jump at its edges.
  const int y = 4 * 35 + 1;
  double inside = 0.0, across = 0.0;
  for (int x = 8; x + 1 < f.canvas().width_cells() - 8; ++x) {
    const double step =
        std::abs(f.canvas().wet_volume_mm(x + 1, y) - f.canvas().wet_volume_mm(x, y));
    ((x + 1) % 4 == 0 ? across : inside) += step;
  }
  ASSERT_GT(across, 0.0);
  EXPECT_GT(inside / 3.0, 0.5 * across);  // three steps inside each old cell, one across
  EXPECT_THROW(p.refined(0), std::runtime_error);
  EXPECT_THROW(p.refined(17), std::runtime_error);
}

}  // namespace
}  // namespace impasto::paintcore
