// The edges of the input space: bad pen samples, huge and tiny sizes, strokes off the canvas.
#include <gtest/gtest.h>

#include <limits>

#include "test_util.hpp"

namespace impasto::paintcore {
namespace {

using test::flat_spec;
using test::relative_error;
using test::round_brush;

// The volume of paint is conserved (extremes leave the pigments out of the check).
void expect_volume_conserved(const Painting& p) {
  const double expected = test::expected_totals(p).volume;
  EXPECT_LT(relative_error(test::present_totals(p).volume, expected), 1e-5);
  EXPECT_EQ(p.nonfinite_count(), 0u);
}

TEST(Extremes, NonFinitePenInputIsRejectedAndChangesNothing) {
  Painting p(flat_spec());
  p.set_brush(round_brush());
  p.load_brush({{"red", 1.0}}, 5.0);
  p.begin_stroke();
  p.stroke_to(test::pen(3.0, 3.0, 0.5f));
  const std::uint64_t before = p.state_hash();
  PenSample bad = test::pen(3.5, 3.0, std::numeric_limits<float>::quiet_NaN());
  try {
    p.stroke_to(bad);
    FAIL();
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("pressure"), std::string::npos);
  }
  bad = test::pen(std::numeric_limits<double>::infinity(), 3.0, 0.5f);
  EXPECT_THROW(p.stroke_to(bad), std::runtime_error);
  bad = test::pen(3.0, 3.0, 0.5f, 0.0f, std::numeric_limits<float>::quiet_NaN());
  EXPECT_THROW(p.stroke_to(bad), std::runtime_error);
  EXPECT_EQ(p.state_hash(), before);
  p.stroke_to(test::pen(5.0, 3.0, 0.5f));  // the stroke goes on
  p.end_stroke();
  EXPECT_EQ(p.nonfinite_count(), 0u);
}

TEST(Extremes, PressureSpikesAreClamped) {
  Painting a(flat_spec()), b(flat_spec());
  for (Painting* p : {&a, &b}) {
    p->set_brush(round_brush());
    p->load_brush({{"red", 1.0}}, 5.0);
  }
  test::stroke_line(a, 2.0, 3.0, 8.0, 3.0, 1.0f);
  test::stroke_line(b, 2.0, 3.0, 8.0, 3.0, 1e6f);  // a spike far above 1 acts as 1
  EXPECT_EQ(a.state_hash(), b.state_hash());
  test::stroke_line(b, 2.0, 3.0, 8.0, 3.0, -5.0f);  // and below 0 as 0: no contact
  EXPECT_EQ(a.state_hash(), b.state_hash());
  expect_volume_conserved(b);
}

TEST(Extremes, FastStrokesAreSubStepped) {
  Painting p(flat_spec());
  p.set_brush(round_brush());
  p.load_brush({{"red", 1.0}}, 5.0);
  p.begin_stroke();
  p.stroke_to(test::pen(1.0, 6.0, 0.8f));
  p.stroke_to(test::pen(11.0, 6.0, 0.8f));  // 100 cells in one sample
  p.end_stroke();
  EXPECT_GE(p.steps(), 100u);
  // The whole path got paint, not just its ends.
  for (int x = 20; x <= 100; x += 10) EXPECT_GT(p.canvas().wet_volume_mm(x, 60), 0.0f) << x;
  expect_volume_conserved(p);
}

TEST(Extremes, StrokesLeavingTheCanvasLoseNoPaint) {
  Painting p(flat_spec(64, 64));
  SimulationParams params;
  p.set_params(params);
  p.set_brush(round_brush(2.0, 0.0));
  p.load_brush({{"red", 1.0}}, 20.0);
  test::stroke_line(p, 3.2, 3.2, 3.2, -5.0, 1.0f);    // off the top
  test::stroke_line(p, -2.0, 1.0, 9.0, 1.0, 1.0f);    // along the edge from outside
  test::stroke_line(p, 1e9, 1e9, 3.0, 3.0, 1.0f, 3);  // from absurdly far away
  test::stroke_line(p, 6.0, 6.0, 6.0, 1e12, 1.0f, 2);
  p.begin_stroke();  // positions whose cell coordinates overflow to infinity
  p.stroke_to(test::pen(-1.7e308, 3.0, 1.0f));
  p.stroke_to(test::pen(1.7e308, 3.0, 1.0f));
  p.end_stroke();
  EXPECT_GT(p.canvas_totals().volume, 0.0);
  expect_volume_conserved(p);
}

TEST(Extremes, BrushLargerThanTheCanvas) {
  Painting p(flat_spec(16, 16));  // 1.6 mm square
  SimulationParams params;
  p.set_params(params);
  p.set_brush(round_brush(5.0, 0.0));  // 50 cells across
  p.load_brush({{"red", 1.0}}, 20.0);
  test::stroke_line(p, 0.0, 0.8, 1.6, 0.8, 1.0f);
  EXPECT_GT(p.canvas_totals().volume, 0.0);
  expect_volume_conserved(p);
}

TEST(Extremes, TinyAndHugeDpi) {
  {
    Painting p(CanvasSpec{8, 8, 1.0, 1});  // 25.4 mm cells: the brush is a single cell
    p.set_brush(round_brush(4.0));
    EXPECT_EQ(p.brush().cells_across(), 1);
    p.load_brush({{"red", 1.0}}, 5.0);
    test::stroke_line(p, 10.0, 10.0, 150.0, 100.0, 1.0f);
    expect_volume_conserved(p);
  }
  {
    Painting p(CanvasSpec{256, 256, 20000.0, 1});  // 1.27 um cells
    p.set_brush(round_brush(0.05));                // 39 cells
    p.load_brush({{"red", 1.0}}, 1e-4);
    test::stroke_line(p, 0.002, 0.006, 0.01, 0.006, 1.0f);
    EXPECT_GT(p.steps(), 0u);
    expect_volume_conserved(p);
    EXPECT_THROW(p.set_brush(round_brush(100.0)), std::runtime_error);  // 78740 cells
  }
}

TEST(Extremes, ZeroPaintStaysZero) {
  Painting p(flat_spec());
  p.set_brush(round_brush());
  test::stroke_line(p, 2.0, 3.0, 8.0, 3.0, 1.0f);
  EXPECT_GT(p.steps(), 0u);  // the brush touched the bare canvas
  EXPECT_EQ(p.canvas_totals().volume, 0.0);
  EXPECT_EQ(p.canvas().allocated_tiles(), 0u);  // and made no tile for nothing
  p.load_brush({{"red", 1.0}}, 0.0);
  EXPECT_EQ(p.brush_totals().volume, 0.0);
}

TEST(Extremes, ThinHeadOnACoarseGridStillHoldsPaint) {
  Painting p(CanvasSpec{32, 32, 12.7, 1});  // 2 mm cells: a 4 mm flat head is 2 x 2 cells
  p.set_brush(BrushSettings{"flat", 4.0, 0.5});
  EXPECT_GT(p.brush().covered_cells(), 0u);
  p.load_brush({{"red", 1.0}}, 5.0);
  EXPECT_EQ(p.nonfinite_count(), 0u);
  EXPECT_NEAR(p.brush_totals().volume, 5.0, 1e-5);
}

TEST(Extremes, AtMostSixteenPigments) {
  Painting p(flat_spec());
  for (int s = 0; s < kMaxPigmentSlots; ++s) {
    std::string name = "p";  // (not "p" + ...: GCC 12 warns falsely on that)
    name += std::to_string(s);
    EXPECT_EQ(p.slot_for(name), s);
  }
  EXPECT_EQ(p.slot_for("p3"), 3);
  EXPECT_THROW(p.slot_for("one too many"), std::runtime_error);
}

}  // namespace
}  // namespace impasto::paintcore
