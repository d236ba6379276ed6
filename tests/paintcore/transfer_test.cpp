#include <gtest/gtest.h>

#include "impasto/paintcore/transfer.hpp"

namespace impasto::paintcore {
namespace {

SimulationParams unclamped() {
  SimulationParams p;
  p.max_xfer_mm = 1.0;  // so that the other factors show
  return p;
}

TEST(Transfer, DirectionFollowsWhichSideHasMorePaint) {
  const SimulationParams p = unclamped();
  const TransferAmounts deposit = compute_brush_transfer_amount(0.0, 0.5, 1.0, p);
  EXPECT_DOUBLE_EQ(deposit.brush_to_canvas, 0.05);  // XFER_FRACTION of a_b
  EXPECT_DOUBLE_EQ(deposit.canvas_to_brush, 0.0);
  const TransferAmounts pickup = compute_brush_transfer_amount(0.5, 0.1, 1.0, p);
  EXPECT_DOUBLE_EQ(pickup.brush_to_canvas, 0.0);
  EXPECT_DOUBLE_EQ(pickup.canvas_to_brush, 0.05);  // XFER_FRACTION of a_c
}

TEST(Transfer, EqualPaintCutoffFadesNearEquality) {
  const SimulationParams p = unclamped();
  EXPECT_DOUBLE_EQ(compute_brush_transfer_amount(0.2, 0.2, 1.0, p).brush_to_canvas, 0.0);
  EXPECT_DOUBLE_EQ(compute_brush_transfer_amount(0.2, 0.2, 1.0, p).canvas_to_brush, 0.0);
  // |a_b - a_c| = 1/60 is half the cut-off: half of 0.1 * a_b.
  const double a_b = 0.2, a_c = 0.2 - 1.0 / 60.0;
  EXPECT_NEAR(compute_brush_transfer_amount(a_c, a_b, 1.0, p).brush_to_canvas, 0.1 * a_b * 0.5,
              1e-12);
  // Beyond the cut-off the factor is 1.
  EXPECT_NEAR(compute_brush_transfer_amount(0.0, 0.04, 1.0, p).brush_to_canvas, 0.004, 1e-12);
}

TEST(Transfer, VelocityCutoffIsASmoothstep) {
  const SimulationParams p = unclamped();
  EXPECT_DOUBLE_EQ(compute_brush_transfer_amount(0.0, 0.5, 0.0, p).brush_to_canvas, 0.0);
  EXPECT_DOUBLE_EQ(compute_brush_transfer_amount(0.0, 0.5, 0.2, p).brush_to_canvas, 0.0);
  EXPECT_NEAR(compute_brush_transfer_amount(0.0, 0.5, 0.25, p).brush_to_canvas, 0.025, 1e-12);
  EXPECT_DOUBLE_EQ(compute_brush_transfer_amount(0.0, 0.5, 0.3, p).brush_to_canvas, 0.05);
  EXPECT_DOUBLE_EQ(smoothstep(0.0, 1.0, 0.25), 0.15625);
}

TEST(Transfer, ClampedToMaxTransfer) {
  const SimulationParams p;  // the paper's MAX_XFER_QUANTITY, 0.001
  EXPECT_DOUBLE_EQ(compute_brush_transfer_amount(0.0, 0.5, 1.0, p).brush_to_canvas, 0.001);
  EXPECT_DOUBLE_EQ(compute_brush_transfer_amount(0.9, 0.0, 1.0, p).canvas_to_brush, 0.001);
  // Small amounts pass unclamped (here also faded by the equal-paint cut-off, 0.005 * 30).
  EXPECT_NEAR(compute_brush_transfer_amount(0.0, 0.005, 1.0, p).brush_to_canvas, 0.1 * 0.005 * 0.15,
              1e-12);
}

TEST(Transfer, FloatKernelAgreesWithTheDoubleOne) {
  const SimulationParams p;
  const TransferConstants<float> k(p);
  EXPECT_NEAR(brush_transfer_amount(0.001f, 0.006f, 0.27f, k),
              compute_brush_transfer_amount(0.001, 0.006, 0.27, p).brush_to_canvas, 1e-7);
  EXPECT_LT(brush_transfer_amount(0.006f, 0.001f, 1.0f, k), 0.0f);
}

TEST(SimulationParams, ValidationNamesTheField) {
  SimulationParams p;
  p.min_film_mm = -1;
  try {
    validate(p);
    FAIL();
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("min_film_mm"), std::string::npos);
  }
}

}  // namespace
}  // namespace impasto::paintcore
