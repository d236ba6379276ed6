// Long steps (SimulationParams::long_step_share): a big brush moving several cells a step
// conserves paint, converges to the one-cell steps as the step shrinks, leaves no ridge every
// step, and changes nothing for brushes below the size where they begin.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "impasto/bench/simulation.hpp"
#include "impasto/paintcore/brush_head.hpp"
#include "stepper.hpp"
#include "test_util.hpp"

namespace impasto::paintcore {
namespace {

using namespace impasto::bench;  // the measures (bench/)

using test::expect_conserved;
using test::flat_spec;
using test::relative_error;
using test::round_brush;

SimulationParams with_share(double share) {
  SimulationParams params;
  params.long_step_share = share;
  return params;
}

// A loaded brush `cells` across (0.1 mm cells) strokes through a band of wet paint, with
// mouse-like samples a quarter of the brush apart.
Painting paint_through_band(int cells, const SimulationParams& params, int threads = 1) {
  const double size_mm = 0.1 * cells;
  Painting p(CanvasSpec{4 * cells, 2 * cells, 254.0, 3}, threads);
  p.set_params(params);
  p.set_brush(round_brush(size_mm, 0.5));
  p.load_brush({{"blue", 1.0}}, 0.4 * size_mm * size_mm);
  test::stroke_line(p, 0.3 * size_mm, 0.8 * size_mm, 3.7 * size_mm, 0.8 * size_mm, 0.8f, 14);
  p.wipe_brush();
  p.load_brush({{"white", 1.0}, {"red", 0.2}}, 0.4 * size_mm * size_mm);
  // Diagonally across the band and off the canvas's right edge.
  p.begin_stroke();
  for (int i = 0; i <= 16; ++i) {
    const double t = i / 16.0;
    PenSample s = test::pen((0.4 + 3.9 * t) * size_mm, (1.5 - 1.0 * t) * size_mm, 0.8f);
    s.time_s = 0.008 * i;
    p.stroke_to(s);
  }
  p.end_stroke();
  return p;
}

// Mean |height difference| of 4 x 4 cell blocks where either painting holds paint.
double block_difference(const Canvas& a, const Canvas& b) {
  double sum = 0;
  int blocks = 0;
  for (int by = 0; by + 4 <= a.height_cells(); by += 4)
    for (int bx = 0; bx + 4 <= a.width_cells(); bx += 4) {
      double ha = 0, hb = 0;
      for (int y = by; y < by + 4; ++y)
        for (int x = bx; x < bx + 4; ++x) {
          ha += a.wet_volume_mm(x, y);
          hb += b.wet_volume_mm(x, y);
        }
      if (ha <= 0.016 && hb <= 0.016) continue;
      sum += std::abs(ha - hb) / 16;
      ++blocks;
    }
  return blocks ? sum / blocks : 0.0;
}

TEST(LongSteps, StepLengthFollowsTheBrush) {
  SimulationParams params;
  params.long_step_share = 0.0625;
  params.long_step_from_cells = 64;
  EXPECT_EQ(max_step_cells(params, 63), 1.0);
  EXPECT_EQ(max_step_cells(params, 64), 4.0);
  EXPECT_EQ(max_step_cells(params, 128), 8.0);
  params.long_step_share = 0.0;
  EXPECT_EQ(max_step_cells(params, 512), 1.0);
}

TEST(LongSteps, APenEasingOffStepsByDepthWithinBounds) {
  // A step changes the tip's depth by at most half touch_mm, and by at most what moves the
  // splayed footprint's edge half a cell, but never by less than a 64th of the full depth: a
  // hair-thin fade or a huge brush cannot ask for millions of steps.
  const BrushHead head =
      load_named_brush_head("round", std::string(IMPASTO_SOURCE_DIR) + "/data/brushes");
  const Brush brush(head, round_brush(10.0, 0.5), 0.1, 1);  // 100 cells, splay 0.25
  const double full = brush.max_depth_mm();                 // 2.19 mm
  SimulationParams params;
  params.touch_mm = 0.3;  // half of it is more than the splay allows (0.088 mm)
  EXPECT_NEAR(Stepper::max_step_depth_mm(params, brush), 0.5 / (0.5 * 0.25 * 100) * full, 1e-12);
  params.touch_mm = 0.1;  // half of it is less
  EXPECT_NEAR(Stepper::max_step_depth_mm(params, brush), 0.05, 1e-12);
  params.touch_mm = 1e-9;
  EXPECT_EQ(Stepper::max_step_depth_mm(params, brush), full / 64);
  const Brush huge(head, round_brush(100.0, 0.5), 0.1, 1);  // 1000 cells
  EXPECT_EQ(Stepper::max_step_depth_mm(SimulationParams{}, huge), huge.max_depth_mm() / 64);
}

TEST(LongSteps, SmallBrushesAreUnchangedBitForBit) {
  // Below long_step_from_cells the default settings step exactly as one-cell steps do.
  const Painting reference = paint_through_band(40, with_share(0.0));
  const Painting by_default = paint_through_band(40, SimulationParams{});
  EXPECT_EQ(by_default.state_hash(), reference.state_hash());
  EXPECT_EQ(by_default.steps(), reference.steps());
  // And a big brush under a raised threshold too.
  SimulationParams high;
  high.long_step_from_cells = 1000;
  EXPECT_EQ(paint_through_band(72, high).state_hash(),
            paint_through_band(72, with_share(0.0)).state_hash());
}

TEST(LongSteps, PaintIsConserved) {
  for (const double share : {0.0625, 0.25, 0.5}) {
    SCOPED_TRACE("share " + std::to_string(share));
    const Painting p = paint_through_band(72, with_share(share));
    expect_conserved(p);
  }
}

TEST(LongSteps, TakeFewerStepsAndTheSameBitsOnAnyThreadCount) {
  const Painting one_cell = paint_through_band(72, with_share(0.0));
  const Painting long_steps = paint_through_band(72, with_share(0.125), 1);
  EXPECT_LT(long_steps.steps() * 4, one_cell.steps());
  EXPECT_EQ(paint_through_band(72, with_share(0.125), 2).state_hash(), long_steps.state_hash());
}

TEST(LongSteps, ConvergeToOneCellStepsAsTheyShrink) {
  const Painting reference = paint_through_band(72, with_share(0.0));
  std::vector<double> errors;
  for (const double share : {0.25, 0.0625, 1.0 / 72}) {
    const Painting p = paint_through_band(72, with_share(share));
    errors.push_back(block_difference(p.canvas(), reference.canvas()));
  }
  EXPECT_GT(errors[0], 0.0);
  EXPECT_LT(errors[1], errors[0]);
  // A share of one cell is the one-cell reference itself.
  EXPECT_EQ(errors[2], 0.0);
  EXPECT_EQ(paint_through_band(72, with_share(1.0 / 72)).state_hash(), reference.state_hash());
}

TEST(LongSteps, LeaveNoRidgeEveryStep) {
  // A straight stroke along x through fresh paint: the mean height of each column across
  // the stroke's middle varies along it no more with 12-cell steps than with one-cell ones
  // (a ridge or furrow where each step's contact ended would add a period of 12 cells).
  const auto column_spread = [](const SimulationParams& params) {
    Painting p(flat_spec(480, 160), 1);
    p.set_params(params);
    p.set_brush(round_brush(9.6, 0.5));
    p.load_brush({{"white", 1.0}}, 40.0);
    test::stroke_line(p, 6.0, 8.0, 42.0, 8.0, 0.8f, 13);
    std::vector<double> columns;
    for (int x = 200; x < 320; ++x) {
      double sum = 0;
      for (int y = 60; y < 100; ++y) sum += p.canvas().wet_volume_mm(x, y);
      columns.push_back(sum / 40);
    }
    // The variation from one column to the next (a slow trend along the stroke cancels).
    double spread = 0;
    for (std::size_t i = 1; i < columns.size(); ++i)
      spread += std::abs(columns[i] - columns[i - 1]);
    return spread / static_cast<double>(columns.size() - 1);
  };
  const double one_cell = column_spread(with_share(0.0));
  const double long_steps = column_spread(with_share(0.125));
  EXPECT_LT(long_steps, 2.0 * one_cell + 1e-4) << one_cell;
}

TEST(LongSteps, MarkAsOneCellStepsDo) {
  // The standard flat and round strokes in paste (8 mm: 80 cells at 254 dpi, long steps of
  // 5 cells by default): the ridges the squeeze ploughs along the edges, the furrows and the
  // film as one-cell steps leave them. Each long step's sub-steps split the film and squeeze
  // with the head where it was then; done once at the step's end, the squeeze saturated
  // (edge ridges 0.03 mm instead of 0.19) and printed the trailing edge every step.
  for (const char* head : {"flat", "round"}) {
    SCOPED_TRACE(head);
    MarkStroke one_cell;
    one_cell.params.long_step_share = 0.0;
    const MarkFigures reference = measure_mark(head, PaintBody::paste, one_cell);
    const MarkFigures f = measure_mark(head, PaintBody::paste, MarkStroke{});
    EXPECT_LT(f.steps * 3, reference.steps);
    EXPECT_NEAR(f.edge_ridge_mm, reference.edge_ridge_mm, 0.35 * reference.edge_ridge_mm + 0.01);
    EXPECT_NEAR(f.middle_mm, reference.middle_mm, 0.05 * reference.middle_mm);
    EXPECT_NEAR(f.furrow_rms_mm, reference.furrow_rms_mm, 0.25 * reference.furrow_rms_mm + 1e-3);
    // No ripple at the step's length (0.5 mm) above 0.1 % of the film (0.6 um): measured as
    // a sampling trace with samples that far apart.
    MarkStroke at_step;
    at_step.spacing_mm = 0.5;
    EXPECT_LT(measure_mark(head, PaintBody::paste, at_step).trace_peak_share, 1e-3);
  }
}

TEST(LongSteps, ABladeStepsACellAtATime) {
  // A blade pushes the paint at its leading edge ahead cell by cell (contact_rows, Stepper):
  // whatever its size it takes one-cell steps, a bristle head of the same size long ones.
  SimulationParams params;
  const Brush knife(load_named_brush_head("knife", default_brushes_dir()),
                    BrushSettings{"knife", 12.8, 0.9}, 0.1, 1);
  const Brush flat(load_named_brush_head("flat", default_brushes_dir()),
                   BrushSettings{"flat", 12.8, 0.5}, 0.1, 1);
  EXPECT_EQ(Stepper::max_step_cells(params, knife), 1.0);
  EXPECT_EQ(Stepper::max_step_cells(params, flat), 8.0);
}

TEST(LongSteps, SettingsHaveNamesAndBadValuesAreRefused) {
  SimulationParams params;
  set_param(params, "long_step_share=0.125");
  set_param(params, "long_step_from_cells=32");
  set_param(params, "long_step_drag_cells=3");
  EXPECT_EQ(params.long_step_share, 0.125);
  EXPECT_EQ(params.long_step_from_cells, 32.0);
  EXPECT_EQ(params.long_step_drag_cells, 3.0);
  EXPECT_NO_THROW(validate(params));
  const auto refused = [](const std::string& assignment, const std::string& field) {
    SimulationParams p;
    set_param(p, assignment);
    try {
      validate(p);
    } catch (const std::runtime_error& e) {
      EXPECT_NE(std::string(e.what()).find(field), std::string::npos) << e.what();
      return;
    }
    ADD_FAILURE() << assignment << " was accepted";
  };
  refused("long_step_share=-0.1", "'long_step_share'");
  refused("long_step_share=0.75", "'long_step_share'");
  refused("long_step_share=nan", "'long_step_share'");
  refused("long_step_from_cells=0", "'long_step_from_cells'");
  refused("long_step_drag_cells=0.5", "'long_step_drag_cells'");
  refused("long_step_drag_cells=inf", "'long_step_drag_cells'");
  SimulationParams p;
  EXPECT_THROW(set_param(p, "long_step_share=wide"), std::runtime_error);
  // Painting files hold these settings from version 7 (params_file_test.cpp): version 6's
  // list is the model's parameters alone, and every setting is in the full one.
  const auto file = simulation_param_fields(6);
  EXPECT_EQ(simulation_param_fields(7).size(), file.size() + 3);
  for (const NamedParam& named : file)
    EXPECT_NE(std::string(named.name).rfind("long_step", 0), 0u) << named.name;
}

TEST(LongSteps, BenchmarkMeasuresTheReferenceAsExact) {
  const auto results = run_long_step_benchmark(64, {0.125}, 1, 1);
  ASSERT_EQ(results.size(), 2u);
  EXPECT_EQ(results[0].mean_height_error_mm, 0.0);
  EXPECT_GT(results[0].mean_height_mm, 0.0);
  EXPECT_EQ(results[1].step_cells, 8.0);
  EXPECT_LT(results[1].steps, results[0].steps);
  EXPECT_GT(results[1].mean_block_error_mm, 0.0);
  EXPECT_LT(std::abs(results[1].volume_error_mm3), 1e-4 * results[1].volume_mm3);
}

TEST(Stepper, TheSqueezePerMillimetreIsTheSameOnEveryGrid) {
  // A cell travelled makes 0.1 mm / cell_mm full passes' worth of squeeze, in whole passes
  // each saturating at its share: one full pass at 254 dpi, a weaker one on coarser grids,
  // and more passes on finer ones.
  for (const double dpi : {75.0, 150.0, 254.0, 300.0, 600.0, 1200.0}) {
    SCOPED_TRACE(dpi);
    const double cell_mm = 25.4 / dpi;
    const Stepper::SqueezePasses plan = Stepper::squeeze_passes(cell_mm);
    EXPECT_GE(plan.passes, 1);
    EXPECT_GT(plan.reach, 0.0f);
    EXPECT_LE(plan.reach, 1.0f);
    EXPECT_NEAR(plan.passes * plan.reach, 0.1 / cell_mm, 1e-5);
    if (plan.passes > 1) {
      EXPECT_GT(plan.reach * plan.passes, plan.passes - 1);  // no pass to spare
    }
  }
  EXPECT_EQ(Stepper::squeeze_passes(0.1).passes, 1);
  EXPECT_FLOAT_EQ(Stepper::squeeze_passes(0.1).reach, 1.0f);
}

TEST(StepperBaseCache, AWindowOverMoreUnpaintedTilesThanTheCacheHoldsStaysValid) {
  // A brush window over 17 x 17 never painted tiles (more than the 256 the weave cache
  // keeps): the cache used to be emptied midway through the window's lookups, leaving the
  // first tiles' heights freed (AddressSanitizer: heap-use-after-free).
  Painting p(flat_spec(1088, 1088), 1);
  p.set_brush(round_brush(102.0, 0.5));
  test::stroke_line(p, 54.0, 54.0, 54.3, 54.0, 0.5f, 2);
  EXPECT_EQ(p.nonfinite_count(), 0u);
  EXPECT_EQ(p.canvas().allocated_tiles(), 0u);  // an empty brush on a bare canvas paints nothing
}

}  // namespace
}  // namespace impasto::paintcore
