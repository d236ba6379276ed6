// Whole simulation steps driven through a Painting: contact, deposit, pick-up, pushing.
#include <gtest/gtest.h>

#include "test_util.hpp"

namespace impasto::paintcore {
namespace {

using test::flat_spec;
using test::round_brush;
using test::stroke_line;

TEST(Stroke, HoveringTouchesNothing) {
  Painting p(flat_spec());
  p.set_brush(round_brush());
  p.load_brush({{"white", 1.0}}, 5.0);
  const std::uint64_t before = p.state_hash();
  stroke_line(p, 2.0, 6.0, 10.0, 6.0, 0.0f);  // pressure 0: the tip only grazes the surface
  EXPECT_EQ(p.steps(), 0u);
  EXPECT_EQ(p.state_hash(), before);
  EXPECT_EQ(p.canvas().allocated_tiles(), 0u);
  EXPECT_EQ(p.undo_depth(), 2u);  // set_brush and load; the hover left nothing to undo
}

TEST(Stroke, LoadedBrushDepositsPaintAlongThePath) {
  Painting p(flat_spec());
  const Painting::ChangeSubscriber changes = p.subscribe_changes();
  (void)p.take_changes(changes);
  p.set_brush(round_brush());
  p.load_brush({{"red", 1.0}}, 5.0);
  const double loaded = p.brush_totals().volume;
  stroke_line(p, 2.0, 6.0, 10.0, 6.0, 0.8f);
  EXPECT_GT(p.steps(), 80u);  // 8 mm at 0.1 mm cells: at least one step per cell
  const double on_canvas = p.canvas_totals().volume;
  EXPECT_GT(on_canvas, 0.0);
  EXPECT_NEAR(on_canvas + p.brush_totals().volume, loaded, 1e-5 * loaded);
  // Paint lies on the path and not far off it.
  EXPECT_GT(p.canvas().wet_volume_mm(60, 60), 0.0f);
  EXPECT_EQ(p.canvas().wet_volume_mm(60, 100), 0.0f);
  // All of it is red.
  EXPECT_NEAR(p.canvas().pigment_mm(60, 60, 0), p.canvas().wet_volume_mm(60, 60), 1e-7);
  EXPECT_FALSE(p.take_changes(changes).empty());
  EXPECT_TRUE(p.take_changes(changes).empty());
}

TEST(Stroke, CleanBrushPicksUpAndPushesPaintForward) {
  Painting p(flat_spec());
  SimulationParams params;
  p.set_params(params);
  p.set_brush(round_brush());
  p.load_brush({{"blue", 1.0}}, 20.0);
  stroke_line(p, 6.0, 2.0, 6.0, 10.0, 1.0f, 40);  // a vertical band at x = 6 mm
  p.wipe_brush();
  const auto centroid_x = [&p] {
    double sum = 0, weight = 0;
    for (int y = 0; y < 128; ++y)
      for (int x = 0; x < 128; ++x) {
        const double v = p.canvas().wet_volume_mm(x, y);
        sum += v * x;
        weight += v;
      }
    return sum / weight;
  };
  const double before = centroid_x();
  stroke_line(p, 3.0, 6.0, 9.0, 6.0, 1.0f, 30);  // drag the clean brush right across it
  EXPECT_GT(centroid_x(), before + 0.5);         // paint moved in the direction pushed
  EXPECT_GT(p.brush_totals().volume, 0.0);       // and the brush got dirty
  EXPECT_GT(p.brush_totals().pigment[0], 0.0);
}

TEST(Stroke, MixesPigmentsByVolume) {
  Painting p(flat_spec());
  p.set_brush(round_brush());
  p.load_brush({{"yellow", 3.0}, {"blue", 1.0}}, 5.0);
  EXPECT_EQ(p.pigment_slots(), (std::vector<std::string>{"yellow", "blue"}));
  stroke_line(p, 2.0, 6.0, 10.0, 6.0, 0.8f);
  const float v = p.canvas().wet_volume_mm(60, 60);
  ASSERT_GT(v, 0.0f);
  EXPECT_NEAR(p.canvas().pigment_mm(60, 60, 0) / v, 0.75, 1e-5);
  EXPECT_NEAR(p.canvas().pigment_mm(60, 60, 1) / v, 0.25, 1e-5);
}

TEST(Stroke, MoreLoadDepositsMore) {
  const auto deposit = [](double volume) {
    Painting p(flat_spec());
    SimulationParams params;
    p.set_params(params);
    p.set_brush(round_brush());
    p.load_brush({{"white", 1.0}}, volume);
    stroke_line(p, 2.0, 6.0, 10.0, 6.0, 0.8f);
    return p.canvas_totals().volume;
  };
  EXPECT_GT(deposit(4.0), 1.5 * deposit(1.0));
}

TEST(Stroke, PressurePushesPaintOutwards) {
  Painting p(flat_spec());
  SimulationParams params;
  params.min_film_mm = 0.0;
  p.set_params(params);
  p.set_brush(round_brush(2.0, 0.0));
  p.load_brush({{"white", 1.0}}, 30.0);
  stroke_line(p, 3.0, 6.0, 9.0, 6.0, 1.0f);
  p.wipe_brush();
  // Press the clean brush straight down in the band: paint under it spreads sideways.
  const float before_edge = p.canvas().wet_volume_mm(60, 69);
  p.begin_stroke();
  PenSample still = test::pen(6.0, 6.0, 1.0f);
  p.stroke_to(still);
  still.time_s = 0.5;  // held down for half a second
  p.stroke_to(still);
  p.end_stroke();
  EXPECT_GT(p.steps(), 0u);
  EXPECT_NE(p.canvas().wet_volume_mm(60, 69), before_edge);
}

TEST(Stroke, NeedsABrushAndABegunStroke) {
  Painting p(flat_spec());
  p.begin_stroke();
  EXPECT_THROW(p.stroke_to(test::pen(1, 1, 0.5f)), std::runtime_error);
  p.end_stroke();
  p.set_brush(round_brush());
  EXPECT_THROW(p.stroke_to(test::pen(1, 1, 0.5f)), std::runtime_error);
  EXPECT_THROW(p.load_brush({{"x", 0.0}}, 1.0), std::runtime_error);
  EXPECT_THROW(p.load_brush({{"x", 1.0}}, -1.0), std::runtime_error);
  EXPECT_THROW(p.load_brush({{"", 1.0}}, 1.0), std::runtime_error);
}

}  // namespace
}  // namespace impasto::paintcore
