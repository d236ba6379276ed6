// The marks a stroke leaves, against the physics they model: how much paint lands, that it
// does not depend on how the stroke is sampled or on the canvas resolution, bristle furrows,
// bodies that hold or level, a head that trails the hand, a curve through the samples.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include "impasto/bench/marks.hpp"
#include "impasto/paintcore/painting.hpp"
#include "levelling.hpp"
#include "stroke_path.hpp"
#include "test_util.hpp"

namespace impasto::paintcore {
namespace {

using namespace impasto::bench;  // the measures (bench/)

// A canvas w_mm x h_mm at `dpi`, flat (no weave).
CanvasSpec canvas_mm(double w_mm, double h_mm, double dpi) {
  return CanvasSpec{static_cast<int>(std::lround(w_mm / 25.4 * dpi)),
                    static_cast<int>(std::lround(h_mm / 25.4 * dpi)), dpi, 0};
}

struct Mark {
  double deposited_share;  // canvas volume / loaded volume
  PaintThickness thickness;
};

struct StrokeSpec {
  double dpi = 254.0;
  double spacing_mm = 0.1;  // between pen samples
  double length_mm = 12.0;
  double seconds = 1.0;
  float pressure = 0.7f;
  BrushSettings brush{"round", 3.0, 0.5};
  double load_mm3 = 20.0;
  PaintBody body = kDefaultPaintBody;
};

// One straight stroke along +x through the canvas's middle, ended by a tip-up sample.
Painting paint_stroke(const StrokeSpec& spec) {
  Painting p(
      canvas_mm(spec.length_mm + 3.0 * spec.brush.size_mm, 2.5 * spec.brush.size_mm, spec.dpi));
  p.set_brush(spec.brush);
  p.load_brush({{"white", 1.0}}, spec.load_mm3, spec.body);
  const double x0 = 1.5 * spec.brush.size_mm, y = 1.25 * spec.brush.size_mm;
  const auto samples = std::max<long>(1, std::lround(spec.length_mm / spec.spacing_mm));
  p.begin_stroke();
  for (long i = 0; i <= samples; ++i) {
    const double t = static_cast<double>(i) / static_cast<double>(samples);
    PenSample s = test::pen(x0 + spec.length_mm * t, y, spec.pressure);
    s.time_s = spec.seconds * t;
    p.stroke_to(s);
  }
  p.end_stroke();
  return p;
}

Mark measure(const Painting& p) {
  return {p.canvas_totals().volume / p.loaded_totals().volume, p.paint_thickness()};
}

void expect_within(double value, double reference, double tolerance, const char* what) {
  EXPECT_NEAR(value / reference, 1.0, tolerance) << what << ": " << value << " vs " << reference;
}

void expect_same_mark(const Mark& a, const Mark& b, double tolerance) {
  expect_within(a.deposited_share, b.deposited_share, tolerance, "deposit");
  expect_within(a.thickness.median_mm, b.thickness.median_mm, tolerance, "median thickness");
  expect_within(a.thickness.p90_mm, b.thickness.p90_mm, tolerance, "p90 thickness");
  expect_within(a.thickness.p99_mm, b.thickness.p99_mm, tolerance, "p99 thickness");
}

TEST(Marks, ALoadedBrushLaysThickPaint) {
  const Mark mark = measure(paint_stroke({}));
  // Heavy-body impasto: most of the load lands, standing well above a canvas weave.
  EXPECT_GT(mark.deposited_share, 0.5);
  EXPECT_GT(mark.thickness.median_mm, 0.2);
  EXPECT_GT(mark.thickness.p99_mm, 0.5);
  EXPECT_LT(mark.thickness.max_mm, 5.0);
}

TEST(Marks, MoreLoadLaysMorePaint) {
  StrokeSpec light, heavy;
  light.load_mm3 = 3.0;
  heavy.load_mm3 = 24.0;
  const Mark a = measure(paint_stroke(light)), b = measure(paint_stroke(heavy));
  EXPECT_GT(b.thickness.median_mm, 2.0 * a.thickness.median_mm);
}

TEST(Marks, DepositDoesNotDependOnSampleSpacing) {
  StrokeSpec reference;
  reference.spacing_mm = 0.1;
  const Mark base = measure(paint_stroke(reference));
  for (const double spacing : {0.01, 0.03, 0.3, 1.0}) {
    SCOPED_TRACE(spacing);
    StrokeSpec spec;
    spec.spacing_mm = spacing;
    expect_same_mark(measure(paint_stroke(spec)), base, 0.10);
  }
}

TEST(Marks, DepositDoesNotDependOnCanvasResolution) {
  // A 5 mm head: 20 cells across at 100 dpi (a 3 mm head's 12 are too coarse to converge).
  StrokeSpec reference;
  reference.brush.size_mm = 5.0;
  reference.load_mm3 = 55.0;
  reference.length_mm = 20.0;
  reference.dpi = 300.0;
  const Mark base = measure(paint_stroke(reference));
  for (const double dpi : {100.0, 150.0, 600.0}) {
    SCOPED_TRACE(dpi);
    StrokeSpec spec = reference;
    spec.dpi = dpi;
    expect_same_mark(measure(paint_stroke(spec)), base, 0.10);
  }
}

// Cells holding paint farther than `radius_mm` from (x, y).
std::size_t painted_beyond(const Painting& p, double x_mm, double y_mm, double radius_mm) {
  const Canvas& c = p.canvas();
  std::size_t count = 0;
  for (int y = 0; y < c.height_cells(); ++y)
    for (int x = 0; x < c.width_cells(); ++x)
      if (c.wet_volume_mm(x, y) > 1e-3f &&
          std::hypot((x + 0.5) * c.cell_mm() - x_mm, (y + 0.5) * c.cell_mm() - y_mm) > radius_mm)
        ++count;
  return count;
}

TEST(Marks, AStillBrushPressedSqueezesPaintOut) {
  const auto hold = [](double seconds) {
    Painting p(test::flat_spec(80, 80));
    p.set_brush(test::round_brush(4.0, 0.3));
    p.load_brush({{"white", 1.0}}, 20.0);
    p.begin_stroke();
    for (int i = 0; i <= 100; ++i) {
      PenSample s = test::pen(4.0, 4.0, 1.0f);
      s.time_s = seconds * i / 100.0;
      p.stroke_to(s);
    }
    p.end_stroke();
    return std::pair{p.paint_thickness().painted_cells, painted_beyond(p, 4.0, 4.0, 1.6)};
  };
  const auto tap = hold(0.01), press = hold(2.0);
  EXPECT_GT(tap.first, 0u);             // a tap leaves paint: the film splits where the brush lifts
  EXPECT_GT(press.second, tap.second);  // held, paint is pressed out from under the head
}

TEST(Marks, FurrowsFollowTheBristleSpacing) {
  for (const double spacing : {0.6, 1.0}) {
    SCOPED_TRACE(spacing);
    BrushHead head = load_named_brush_head("round");
    head.bristles = {spacing, 0.15, 0.0};
    head.splay = 0.0;
    Painting p(canvas_mm(24.0, 12.0, 254.0));
    p.set_brush(BrushSettings{"round", 6.0, 0.5}, head);
    p.load_brush({{"white", 1.0}}, 40.0);
    p.begin_stroke();
    for (int i = 0; i <= 160; ++i) {
      PenSample s = test::pen(4.0 + 0.1 * i, 6.0, 0.7f);
      s.time_s = 0.01 * i;
      p.stroke_to(s);
    }
    p.end_stroke();
    const int width = p.canvas().width_cells();
    EXPECT_NEAR(furrow_period_mm(p.canvas(), width / 3, 2 * width / 3), spacing, 0.15 * spacing);
  }
}

TEST(Marks, HeavyPaintKeepsBristleFurrowsFluidPaintLevelsThem) {
  // A 6 mm round (hog bristles in columns 0.45 mm apart) in heavy paint ploughs furrows at
  // its splayed bristle spacing, a good fraction of the film deep; fluid paint levels them.
  MarkStroke stroke;
  stroke.size_mm = 6.0;
  stroke.length_mm = 20.0;
  const MarkFigures heavy = measure_mark("round", PaintBody::heavy, stroke);
  const MarkFigures fluid = measure_mark("round", PaintBody::fluid, stroke);
  EXPECT_NEAR(heavy.furrow_period_mm, heavy.bristle_spacing_mm, 0.15 * heavy.bristle_spacing_mm);
  EXPECT_GT(heavy.furrow_rms_mm, 0.05 * heavy.middle_mm);
  EXPECT_LT(fluid.furrow_rms_mm, 0.6 * heavy.furrow_rms_mm);
}

// A 16 mm standard stroke (bench/marks.hpp) of `head` in `body` on a grid of `dpi`.
MarkFigures short_mark(const std::string& head, PaintBody body, double dpi) {
  MarkStroke stroke;
  stroke.length_mm = 16.0;
  stroke.dpi = dpi;
  return measure_mark(head, body, stroke);
}

TEST(Marks, FurrowsAreSetInMillimetresNotByTheGrid) {
  // A heavy flat's furrows are as deep on a grid four times finer (the squeeze keeps its
  // strength per mm travelled, Stepper::squeeze_passes: with one pass a step it fell behind
  // on fine grids, 0.053 mm RMS at 300 dpi, 0.029 at 1200).
  const MarkFigures coarse = short_mark("flat", PaintBody::heavy, 300.0);
  const MarkFigures fine = short_mark("flat", PaintBody::heavy, 1200.0);
  EXPECT_GT(coarse.furrow_rms_mm, 0.02 * coarse.middle_mm);
  EXPECT_NEAR(fine.furrow_rms_mm, coarse.furrow_rms_mm, 0.3 * coarse.furrow_rms_mm);
}

TEST(Marks, FluidPaintLevelsItsFurrowsAsMuchOnAFinerGrid) {
  // Fluid paint levels a round's furrows; on a grid twice as fine the levelling's iterations
  // grow with the cell's inverse square (levelling.cpp), or they level less of them (0.007
  // mm RMS at 300 dpi, 0.014 at 600 with 48 iterations on both).
  const MarkFigures coarse = short_mark("round", PaintBody::fluid, 300.0);
  const MarkFigures fine = short_mark("round", PaintBody::fluid, 600.0);
  EXPECT_NEAR(fine.furrow_rms_mm, coarse.furrow_rms_mm, 0.3 * coarse.furrow_rms_mm);
}

TEST(Marks, ASplayedHeadLeavesNoStripesOfTheGrid) {
  // A fan splays a fifth wider under pressure 0.7: its grid of cells meets the canvas's at a
  // beat of about 5.8 cells, where some of its cell columns met two canvas cells and some
  // one. Evened out per column of cells, those ran dry first, in stripes 5.8 cells apart
  // that drowned the bristles' furrows (0.25 mm at 600 dpi). Paint in a bristle is shared
  // between its hairs: the furrows stand at the bristles' 1.09 mm.
  const MarkFigures fan = short_mark("fan", PaintBody::heavy, 600.0);
  EXPECT_NEAR(fan.furrow_period_mm, fan.bristle_spacing_mm, 0.15 * fan.bristle_spacing_mm);
}

TEST(Marks, HeavyPaintHoldsItsRidgesFluidPaintLevels) {
  // The standard flat's mark (bench/marks.hpp): ridges along its edges in stiff paint,
  // levelled away in fluid paint.
  const MarkStroke stroke;
  const MarkFigures fluid = measure_mark("flat", PaintBody::fluid, stroke);
  const MarkFigures heavy = measure_mark("flat", PaintBody::heavy, stroke);
  const MarkFigures paste = measure_mark("flat", PaintBody::paste, stroke);
  EXPECT_GT(heavy.edge_ridge_mm, 0.05);
  EXPECT_GE(paste.edge_ridge_mm, heavy.edge_ridge_mm);
  EXPECT_LT(fluid.edge_ridge_mm, 0.3 * heavy.edge_ridge_mm);
  // Levelling moves paint, never makes or loses it.
  EXPECT_NEAR(fluid.deposited_share, heavy.deposited_share, 0.02);
}

TEST(Marks, AKnifePlanesThePaintAndLeavesRidgesAtItsEnds) {
  const MarkStroke stroke;
  const MarkFigures paste = measure_mark("knife", PaintBody::paste, stroke);
  const MarkFigures fluid = measure_mark("knife", PaintBody::fluid, stroke);
  // A plane under the blade: most cells within a few percent of one height.
  EXPECT_LT(paste.thickness.p90_mm - paste.thickness.median_mm, 0.1 * paste.thickness.median_mm);
  // Sharp ridges where the blade's ends pass, kept by stiff paint, levelled by fluid paint.
  EXPECT_GT(paste.edge_ridge_mm, 0.2);
  EXPECT_LT(fluid.edge_ridge_mm, 0.2 * paste.edge_ridge_mm);
  EXPECT_EQ(paste.bristle_spacing_mm, 0.0);  // a smooth blade
}

TEST(Marks, AnEmptyKnifeScrapesWetPaintDownAndPushesItAhead) {
  // A band of heavy paint along x, then a clean 8 mm knife drawn flat across it along y,
  // pressed (0.9): where it passed, a film of less than a fifth of the band stays, and the
  // paint it took off is pushed ahead of the blade and piled past the band where the blade
  // left; paint is conserved and stays finite. Dragged by a fifth of its motion, the blade
  // planed the band into a raised slab 0.3 of its height.
  Painting p(CanvasSpec{300, 300, 254.0, 0}, 1);
  p.set_brush(BrushSettings{"flat", 10.0, 0.5});
  p.load_brush({{"white", 1.0}}, 300.0, PaintBody::heavy);
  test::stroke_line(p, 3.0, 10.0, 27.0, 10.0, 0.8f, 120);
  p.wipe_brush();
  p.set_brush(BrushSettings{"knife", 8.0, 0.9});
  const Canvas& c = p.canvas();
  const auto mean_over = [&c](int x0, int x1, int y0, int y1) {
    double sum = 0.0;
    for (int y = y0; y < y1; ++y)
      for (int x = x0; x < x1; ++x) sum += c.wet_volume_mm(x, y);
    return sum / ((x1 - x0) * (y1 - y0));
  };
  const double band = mean_over(140, 160, 80, 120);
  ASSERT_GT(band, 0.3);
  test::stroke_line(p, 15.0, 2.0, 15.0, 25.0, 0.9f, 100);
  EXPECT_LT(mean_over(145, 155, 85, 115), 0.2 * band);
  double ahead = 0.0;
  for (int y = 160; y < 300; ++y)
    for (int x = 110; x < 190; ++x) ahead = std::max(ahead, double(c.wet_volume_mm(x, y)));
  EXPECT_GT(ahead, 2.0 * band);
  for (int y = 0; y < c.height_cells(); ++y)
    for (int x = 0; x < c.width_cells(); ++x) {
      ASSERT_TRUE(std::isfinite(c.wet_volume_mm(x, y))) << x << "," << y;
      ASSERT_GE(c.wet_volume_mm(x, y), 0.0f) << x << "," << y;
    }
  test::expect_conserved(p);
}

TEST(Marks, LevellingFlowsOnlyPastTheYieldSlope) {
  const PaintBodyInfo& heavy = body_info(PaintBody::heavy);
  // 0.5 mm of heavy paint holds a slope of 60 / (14.7 * 0.5) ~ 8: a 0.5 mm drop over 0.1 mm.
  EXPECT_EQ(levelling_flow_mm(0.5, 0.5, 0.1, 1.0, heavy), 0.0);
  EXPECT_GT(levelling_flow_mm(0.5, 1.0, 0.1, 1.0, heavy), 0.0);
  // Fluid paint flows down the gentlest slope, never more than an eighth of the drop.
  const PaintBodyInfo& fluid = body_info(PaintBody::fluid);
  const double flow = levelling_flow_mm(0.5, 0.01, 0.1, 10.0, fluid);
  EXPECT_GT(flow, 0.0);
  EXPECT_LE(flow, 0.125 * 0.01);
  EXPECT_EQ(levelling_flow_mm(0.0, 1.0, 0.1, 1.0, fluid), 0.0);  // no paint, no flow
}

TEST(Marks, LevellingTreatsAPartialEdgeTileLikeAFullOne) {
  // Two equal blocks of fluid paint, one in a full tile and one in the canvas's last tile,
  // 36 of whose 64 columns lie on the canvas: both level alike.
  Canvas canvas(CanvasSpec{100, 64, 254.0, 0});
  for (const int index : {0, 1}) canvas.ensure_tile(index, 1);
  for (int y = 20; y < 30; ++y)
    for (const int x0 : {10, 74}) {
      Tile& tile = *canvas.tile_slot(x0 / kTileSize);
      for (int x = x0; x < x0 + 10; ++x) {
        const auto c = static_cast<std::size_t>(y * kTileSize + x % kTileSize);
        tile.wet_volume_mm[c] = 1.0f;
        tile.pigment(0)[c] = 1.0f;
      }
    }
  SimulationParams params;
  const LevellingReport report = settle_wet_paint(canvas, {0, 1}, 1, PaintBody::fluid, params);
  EXPECT_GT(report.iterations, 0);
  for (int y = 15; y < 35; ++y)
    for (int dx = -5; dx < 15; ++dx)
      EXPECT_EQ(canvas.wet_volume_mm(10 + dx, y), canvas.wet_volume_mm(74 + dx, y))
          << dx << "," << y;
  EXPECT_LT(canvas.wet_volume_mm(79, 25), 0.9f);  // it did level
}

TEST(Marks, ABrushLiftsWithoutLeavingAStamp) {
  // The standard round's stroke ends with the pen's tip up (pressure 0.7 to 0, as a mouse
  // releases): the bristles leave over a distance and the end tapers, with no ridge across
  // it where a footprint was pressed (the lift's rim, bench/marks.hpp) above a tenth of
  // the film. Lifted on the spot, the whole footprint split its film at once: a disc with a
  // rim 40-50 % of the film.
  MarkStroke stroke;
  for (const char* head : {"round", "filbert"}) {
    SCOPED_TRACE(head);
    const MarkFigures f = measure_mark(head, PaintBody::paste, stroke);
    EXPECT_LE(f.lift_rim_share, 0.10);
  }
  // The mark goes on past where the pen lifted, and thins there.
  const Painting p = paint_stroke({});
  const Canvas& c = p.canvas();
  const int y = c.height_cells() / 2;
  const double cell = c.cell_mm();
  const int end = static_cast<int>((1.5 * 3.0 + 12.0) / cell);
  const int width = static_cast<int>(3.0 / cell);
  double before = 0.0, past = 0.0;
  for (int x = end - 2 * width; x < end - width; ++x) before += c.wet_volume_mm(x, y) / width;
  for (int x = end + width / 2; x < end + width; ++x) past += c.wet_volume_mm(x, y);
  EXPECT_GT(past, 0.0);
  EXPECT_LT(past / (width / 2), before);
}

// How much a dab's paint ripples along its middle where the brush left it: the RMS of the
// height, less its 1 mm moving average, over the dab's 6 mm of travel, as a share of the
// film. A 10 mm round in paste, 6 mm at pressure 0.7 and then eased off over its last 2 mm
// (a pen) or released at once (a mouse).
double dab_ripple_share(bool eased) {
  Painting p(canvas_mm(30.0, 20.0, 254.0));
  p.set_brush(BrushSettings{"round", 10.0, 0.5});
  p.load_brush({{"white", 1.0}}, 250.0, PaintBody::paste);
  const double x0 = 8.0, y = 10.0;
  const int samples = 30;
  p.begin_stroke();
  for (int k = 0; k <= samples; ++k) {
    const double eased_off = std::min(1.0, (samples - k) / 10.0);
    const float pressure =
        eased ? static_cast<float>(0.7 * eased_off) : (k < samples ? 0.7f : 0.0f);
    PenSample s = test::pen(x0 + 6.0 * k / samples, y, pressure);
    s.time_s = 0.012 * k;
    if (pressure == 0.0f) s.buttons = kPenInRange;  // the tip lifts, as a mouse's release does
    p.stroke_to(s);
  }
  p.end_stroke();
  const Canvas& c = p.canvas();
  const double cell = c.cell_mm();
  const int y0 = static_cast<int>((y - 1.0) / cell), y1 = static_cast<int>((y + 1.0) / cell);
  std::vector<double> profile, film;
  for (int x = static_cast<int>((x0 + 0.5) / cell); x < static_cast<int>((x0 + 6.5) / cell); ++x) {
    double sum = 0.0;  // across the middle 2 mm: the furrows along the stroke average out
    for (int row = y0; row < y1; ++row) sum += c.wet_volume_mm(x, row);
    profile.push_back(sum / (y1 - y0));
  }
  const int window = static_cast<int>(std::lround(1.0 / cell));
  double squares = 0.0, mean_film = 0.0;
  int count = 0;
  for (std::size_t i = window; i + window < profile.size(); ++i) {
    double average = 0.0;
    for (std::size_t j = i - window / 2; j < i - window / 2 + window; ++j) average += profile[j];
    average /= window;
    squares += (profile[i] - average) * (profile[i] - average);
    mean_film += profile[i];
    ++count;
  }
  return std::sqrt(squares / count) / (mean_film / count);
}

TEST(Marks, AnEasedOffOrReleasedDabLeavesNoRings) {
  // A brush pressed less and less (or lifting) has a contact that shrinks a little every
  // step; where each step's edge stopped, the paint kept a step: concentric rings inside
  // every dab (a ripple of 1.3-1.6 % of the film here with touch_mm 0, 0.2-0.5 % with the
  // contact fading in from its edge and the depth changing a step no more than the fade
  // allows).
  // A mouse's release lifts the tip at once: the brush goes on along its travel as it rises
  // (Painting::stroke_to leaves the tip-up sample to the lift), instead of leaving on the spot
  // with an arc where the last footprint's trailing edge stood (0.48 % then, 0.18 % now).
  EXPECT_LT(dab_ripple_share(true), 0.006);
  EXPECT_LT(dab_ripple_share(false), 0.003);
}

TEST(Marks, NoTraceOfThePensSampling) {
  // The standard flat and knife strokes (bench/marks.hpp) sampled every 0.05 mm and every
  // 2 mm: the paint's variation along the stroke (what varies faster than 3 mm) is the same
  // within 30 %, with no peak at the samples' spacing. Stepping once a sample, the 2 mm
  // samples' ridges measured 2-4 times the 0.05 mm stroke's variation.
  for (const char* head : {"flat", "knife"}) {
    SCOPED_TRACE(head);
    MarkStroke fine, coarse;
    fine.spacing_mm = 0.05;
    coarse.spacing_mm = 2.0;
    const MarkFigures a = measure_mark(head, PaintBody::heavy, fine);
    const MarkFigures b = measure_mark(head, PaintBody::heavy, coarse);
    EXPECT_GT(a.trace_rms_share, 0.0);
    EXPECT_LT(b.trace_rms_share, 1.3 * a.trace_rms_share);
    EXPECT_LT(b.trace_peak, 5.0);
    EXPECT_NEAR(b.deposited_share, a.deposited_share, 0.005);
    EXPECT_NEAR(b.edge_ridge_mm, a.edge_ridge_mm, 0.1 * a.edge_ridge_mm + 1e-3);
  }
}

TEST(Marks, ATraceIsFoundWhereThereIsOne) {
  // sampling_trace itself: a ripple of 2 % of the film every 1 mm on a profile with a slow
  // slope reads as 2 % / sqrt(2) RMS with a peak far above the floor; 3 mm and slower is not
  // counted; a period shorter than three cells cannot be resolved.
  const double cell_mm = 0.1, film = 0.5;
  std::vector<double> rippled, sloped;
  for (int i = 0; i < 400; ++i) {
    const double x = i * cell_mm;
    sloped.push_back(film - 0.01 * x);
    rippled.push_back(sloped.back() + 0.02 * film * std::sin(2.0 * std::numbers::pi * x));
  }
  const SamplingTrace ripple = sampling_trace(rippled, cell_mm, 1.0, 3.0, film);
  EXPECT_NEAR(ripple.rms_share, 0.02 / std::sqrt(2.0), 0.004);
  EXPECT_NEAR(ripple.peak_share, 0.02, 0.004);
  EXPECT_GT(ripple.peak, 100.0);
  const SamplingTrace slope = sampling_trace(sloped, cell_mm, 1.0, 3.0, film);
  EXPECT_LT(slope.rms_share, 0.002);
  EXPECT_LT(slope.peak, 5.0);
  EXPECT_EQ(sampling_trace(rippled, cell_mm, 0.2, 3.0, film).peak, 0.0);
  // And a ridge's prominence: a crest on a plateau counts from the plateau.
  std::vector<double> end(60, 0.3);
  for (int i = 40; i < 60; ++i) end[static_cast<std::size_t>(i)] = 0.0;
  end[38] = 0.42;
  EXPECT_NEAR(ridge_prominence(end, 20, 60, 10), 0.12, 1e-12);
  end[38] = 0.3;
  EXPECT_NEAR(ridge_prominence(end, 20, 60, 10), 0.0, 1e-12);
}

// The widest run of painted cells along y (mm), over the stroke's middle third.
double mark_width_mm(const Painting& p) {
  const Canvas& c = p.canvas();
  int widest = 0;
  for (int x = c.width_cells() / 3; x < 2 * c.width_cells() / 3; ++x) {
    int painted = 0;
    for (int y = 0; y < c.height_cells(); ++y) painted += c.wet_volume_mm(x, y) > 1e-3f;
    widest = std::max(widest, painted);
  }
  return widest * c.cell_mm();
}

TEST(Marks, AFlatHeadTurnsToTheTravelWithoutTwistData) {
  // A 6 mm flat drawn along x and along y with a mouse (no twist): both marks are about as
  // wide as the head, not as thin as its edge.
  for (const bool along_x : {true, false}) {
    SCOPED_TRACE(along_x);
    Painting p(test::flat_spec(240, 240));
    p.set_brush(BrushSettings{"flat", 6.0, 0.5});
    p.load_brush({{"white", 1.0}}, 30.0);
    p.begin_stroke();
    for (int i = 0; i <= 120; ++i) {
      const double along = 4.0 + 0.13 * i;
      PenSample s = along_x ? test::pen(along, 12.0, 0.7f) : test::pen(12.0, along, 0.7f);
      s.time_s = 0.01 * i;
      p.stroke_to(s);
    }
    p.end_stroke();
    double width = 0.0;
    if (along_x) {
      width = mark_width_mm(p);
    } else {
      const Canvas& c = p.canvas();
      int widest = 0;
      for (int y = c.height_cells() / 3; y < 2 * c.height_cells() / 3; ++y) {
        int painted = 0;
        for (int x = 0; x < c.width_cells(); ++x) painted += c.wet_volume_mm(x, y) > 1e-3f;
        widest = std::max(widest, painted);
      }
      width = widest * c.cell_mm();
    }
    EXPECT_GT(width, 0.75 * 6.0);
  }
}

TEST(Marks, TheHeadTrailsTheHandWithALagSetByDistance) {
  // Heading for travel along +x puts the head's v axis along x.
  EXPECT_NEAR(heading_for_travel(0.0), -std::numbers::pi / 2, 1e-12);
  // After a right-angle turn it has turned 1 - 1/e of the way in one follow length.
  const double start = heading_for_travel(0.0);
  const double turned = follow_heading(start, std::numbers::pi / 2, 3.0, 3.0);
  EXPECT_NEAR(turned - start, (std::numbers::pi / 2) * (1 - std::exp(-1.0)), 1e-9);
  // A brush drawn straight back does not flip over: heads are symmetric under a half turn.
  EXPECT_NEAR(follow_heading(start, std::numbers::pi, 10.0, 1.0), start, 1e-9);
  // Cut into many small moves, the turn is the same: it depends on distance, not on steps.
  double many = start;
  for (int i = 0; i < 300; ++i) many = follow_heading(many, std::numbers::pi / 4, 0.01, 3.0);
  EXPECT_NEAR(many, follow_heading(start, std::numbers::pi / 4, 3.0, 3.0), 1e-9);
}

// A session with every kind of mark: a loaded curve with tilt, a reload without wiping, a
// crossing stroke that picks up and mixes, a still press, a fast flick.
// A circle, a dirty reload and a line, a brush held still, a fast flick: 16 x 16 mm at `dpi`.
Painting paint_session(const std::string& head, PaintBody body, int threads, double dpi = 254.0) {
  const int cells = static_cast<int>(std::lround(16.0 / 25.4 * dpi));
  Painting p(test::flat_spec(cells, cells, dpi), threads);
  p.set_brush(BrushSettings{head, 3.0, 0.5});
  p.load_brush({{"red", 2.0}, {"white", 1.0}}, 15.0, body);
  p.begin_stroke();
  for (int i = 0; i <= 80; ++i) {
    const double a = 0.05 * i;
    PenSample s = test::pen(8.0 + 5.0 * std::cos(a), 8.0 + 5.0 * std::sin(a), 0.6f, 20.0f, -10.0f);
    s.time_s = 0.01 * i;
    p.stroke_to(s);
  }
  p.end_stroke();
  p.load_brush({{"blue", 1.0}}, 10.0, body);  // onto the dirty brush
  test::stroke_line(p, 2.0, 8.0, 14.0, 9.0, 0.9f, 7);
  p.begin_stroke();
  for (int i = 0; i <= 20; ++i) {  // held still
    PenSample s = test::pen(8.0, 8.0, 1.0f);
    s.time_s = 0.02 * i;
    p.stroke_to(s);
  }
  p.end_stroke();
  test::stroke_line(p, 14.0, 2.0, 2.0, 14.0, 0.5f, 3);  // a fast flick: three samples
  return p;
}

TEST(Marks, EveryHeadAndBodyConservesPaint) {
  for (const char* head : {"round", "flat", "filbert", "fan", "rigger", "knife"})
    for (const PaintBodyInfo& body : kPaintBodies) {
      SCOPED_TRACE(std::string(head) + " " + std::string(body.name));
      const Painting p = paint_session(head, body.body, 0);
      const PaintTotals expected = test::expected_totals(p), present = test::present_totals(p);
      EXPECT_LT(test::relative_error(present.volume, expected.volume), 1e-5);
      for (std::size_t s = 0; s < expected.pigment.size(); ++s)
        EXPECT_LT(test::relative_error(present.pigment[s], expected.pigment[s]), 1e-5) << s;
      EXPECT_EQ(p.nonfinite_count(), 0u);
      EXPECT_GT(p.canvas_totals().volume, 0.0);
      // No cell anywhere holds negative paint (a painting file would refuse it).
      const auto& brush = p.brush().volume_mm();
      EXPECT_GE(*std::min_element(brush.begin(), brush.end()), 0.0f);
      const auto& pigments = p.brush().pigment_mm();
      EXPECT_GE(*std::min_element(pigments.begin(), pigments.end()), 0.0f);
      const Canvas& c = p.canvas();
      float lowest = 0.0f;
      for (int y = 0; y < c.height_cells(); ++y)
        for (int x = 0; x < c.width_cells(); ++x) lowest = std::min(lowest, c.wet_volume_mm(x, y));
      EXPECT_GE(lowest, 0.0f);
    }
}

TEST(Marks, PaintIsConservedOnFinerAndCoarserGrids) {
  // Finer grids squeeze in several passes a step, coarser ones in one weaker pass
  // (Stepper::squeeze_passes); a 3 mm head is 71 cells at 600 dpi and takes long steps.
  for (const double dpi : {150.0, 600.0})
    for (const char* head : {"round", "knife"}) {
      SCOPED_TRACE(std::string(head) + " " + std::to_string(dpi));
      test::expect_conserved(paint_session(head, PaintBody::heavy, 0, dpi));
    }
}

TEST(Marks, EveryHeadAndBodyPaintsTheSameOnAnyThreadCount) {
  for (const char* head : {"round", "flat", "knife"})
    for (const PaintBodyInfo& body : kPaintBodies) {
      SCOPED_TRACE(std::string(head) + " " + std::string(body.name));
      EXPECT_EQ(paint_session(head, body.body, 1).state_hash(),
                paint_session(head, body.body, 2).state_hash());
    }
}

TEST(Marks, AFastCircleStaysRound) {
  // A 10 mm circle from only 12 samples (a fast flick read at 60 Hz): the brush's path
  // through them stays within 0.5 % of the radius (the polygon's chords fall 3.4 % inside).
  constexpr int kSamples = 12;
  constexpr double kRadius = 10.0;
  const auto point = [](int k) {
    const double a = 2.0 * std::numbers::pi * k / kSamples;
    return std::array<double, 2>{kRadius * std::cos(a), kRadius * std::sin(a)};
  };
  double worst = 0.0;
  for (int k = 1; k <= kSamples; ++k) {
    const auto before = point(k - 1);
    const StrokeSegment segment(point(k), point(k + 1), &before);
    for (int i = 0; i <= 50; ++i) {
      const auto at = segment.at(i / 50.0);
      worst = std::max(worst, std::abs(std::hypot(at[0], at[1]) - kRadius));
    }
  }
  EXPECT_LT(worst, 0.005 * kRadius);
  // The first segment of a stroke has no sample before it: a straight chord.
  const StrokeSegment first({0, 0}, {2, 0}, nullptr);
  EXPECT_NEAR(first.at(0.5)[1], 0.0, 1e-12);
  EXPECT_NEAR(first.length(), 2.0, 1e-12);
}

TEST(Marks, TheBrushStepsByDistanceAlongItsPath) {
  // A coordinate the path does not change stays exactly what it was (a stroke along x at
  // y = 5.3 has no step up or down: the drag's direction would flip with its sign).
  const std::array<double, 2> before{-2.7, 5.3};
  const StrokeSegment along_x({0.3, 5.3}, {7.9, 5.3}, &before);
  for (int i = 0; i <= 100; ++i) EXPECT_EQ(along_x.at(i / 100.0)[1], 5.3) << i;
  EXPECT_NEAR(along_x.length(), 7.6, 1e-12);
  // On a curve, t_at_length_share finds the parameter where that share of the arc lies.
  const std::array<double, 2> behind{0.0, -4.0};
  const StrokeSegment curve({3.0, 0.0}, {0.0, 3.0}, &behind);
  double arc = 0.0, last_t = 0.0;
  std::array<double, 2> last = curve.at(0.0);
  for (int i = 1; i <= 2000; ++i) {
    const auto here = curve.at(i / 2000.0);
    arc += std::hypot(here[0] - last[0], here[1] - last[1]);
    last = here;
  }
  EXPECT_NEAR(curve.length(), arc, 1e-3 * arc);
  for (const double share : {0.1, 0.25, 0.5, 0.9}) {
    const double t = curve.t_at_length_share(share);
    EXPECT_GT(t, last_t);
    last_t = t;
    double part = 0.0;
    std::array<double, 2> from = curve.at(0.0);
    for (int i = 1; i <= 1000; ++i) {
      const auto here = curve.at(t * i / 1000.0);
      part += std::hypot(here[0] - from[0], here[1] - from[1]);
      from = here;
    }
    EXPECT_NEAR(part / arc, share, 2e-3) << share;
  }
  EXPECT_EQ(curve.t_at_length_share(0.0), 0.0);
  EXPECT_EQ(curve.t_at_length_share(1.0), 1.0);
}

}  // namespace
}  // namespace impasto::paintcore
