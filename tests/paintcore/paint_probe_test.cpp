// The eyedropper's probe: the pigments, proportions and thickness of the paint at a point.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "impasto/paintcore/paint_probe.hpp"
#include "test_util.hpp"

namespace impasto::paintcore {
namespace {

using test::flat_spec;
using test::round_brush;

// A horizontal stroke of 2 parts "red" to 1 of "white" along y = 6 mm, and a stroke of "blue"
// alone along y = 9 mm (0.1 mm cells: rows 60 and 90).
Painting two_strokes() {
  Painting p(flat_spec());
  p.set_brush(round_brush());
  p.load_brush({{"red", 2.0}, {"white", 1.0}}, 5.0);
  test::stroke_line(p, 2.0, 6.0, 10.0, 6.0, 0.8f);
  p.wipe_brush();
  p.load_brush({{"blue", 1.0}}, 5.0);
  test::stroke_line(p, 2.0, 9.0, 10.0, 9.0, 0.8f);
  p.wipe_brush();
  return p;
}

TEST(PaintProbe, FindsThePigmentsAndTheirProportionsWhereAStrokeLies) {
  const Painting p = two_strokes();
  const PaintProbe probe = probe_paint(p, 60.5, 60.5, 2.0);
  ASSERT_EQ(p.pigment_slots().size(), 3u);  // red, white, blue
  EXPECT_EQ(probe.cells, 13u);              // a disc of radius 2 around a cell centre
  EXPECT_EQ(probe.wet_cells, probe.cells);
  EXPECT_EQ(probe.dry_cells, 0u);
  const std::vector<double> shares = probe.shares();
  EXPECT_NEAR(shares[0], 2.0 / 3.0, 1e-4);
  EXPECT_NEAR(shares[1], 1.0 / 3.0, 1e-4);
  EXPECT_EQ(shares[2], 0.0);
  // The mean wet height is the canvas's over the same cells.
  double sum = 0.0;
  for (int y = 58; y <= 62; ++y)
    for (int x = 58; x <= 62; ++x)
      if (std::hypot(x - 60, y - 60) <= 2.0) sum += p.canvas().wet_volume_mm(x, y);
  EXPECT_NEAR(probe.wet_mm, sum / 13.0, 1e-6);
  EXPECT_GT(probe.wet_mm, 0.01);
  EXPECT_EQ(probe.dry_mm, 0.0);

  const PaintProbe blue = probe_paint(p, 60.5, 90.5, 1.0);
  EXPECT_EQ(blue.shares()[2], 1.0);
}

TEST(PaintProbe, BareCanvasAndOutsideAreBare) {
  const Painting p = two_strokes();
  EXPECT_TRUE(probe_paint(p, 120.5, 20.5, 2.0).bare());
  const PaintProbe outside = probe_paint(p, -50.0, -50.0, 2.0);
  EXPECT_EQ(outside.cells, 0u);
  EXPECT_TRUE(outside.bare());
  const double nan = std::numeric_limits<double>::quiet_NaN();
  EXPECT_EQ(probe_paint(p, nan, 60.0, 2.0).cells, 0u);
  EXPECT_EQ(probe_paint(p, 60.0, 60.0, nan).cells, 0u);
  // Radius 0: the one cell the point lies in.
  EXPECT_EQ(probe_paint(p, 60.5, 60.5, 0.0).cells, 1u);
}

TEST(PaintProbe, WhereTheWetPaintIsGoneTheTopDryLayerIsSeen) {
  Painting p(flat_spec());
  p.set_brush(round_brush());
  p.load_brush({{"red", 1.0}}, 5.0);
  test::stroke_line(p, 2.0, 6.0, 10.0, 6.0, 0.8f);
  p.wipe_brush();
  p.dry(1.0);  // all of it
  const PaintProbe red = probe_paint(p, 60.5, 60.5, 1.0);
  EXPECT_EQ(red.wet_cells, 0u);
  EXPECT_EQ(red.dry_cells, red.cells);
  EXPECT_GT(red.dry_mm, 0.01);
  EXPECT_EQ(red.shares()[0], 1.0);
  // A second colour dried over the first: it is the one seen.
  p.load_brush({{"green", 1.0}}, 5.0);
  test::stroke_line(p, 2.0, 6.0, 10.0, 6.0, 0.8f);
  p.wipe_brush();
  const PaintProbe wet_green = probe_paint(p, 60.5, 60.5, 1.0);
  EXPECT_EQ(wet_green.wet_cells, wet_green.cells);
  EXPECT_GT(wet_green.shares()[1], 0.5);  // the stroke picks up a little red from below
  p.dry(1.0);
  const PaintProbe dry_green = probe_paint(p, 60.5, 60.5, 1.0);
  EXPECT_EQ(dry_green.dry_cells, dry_green.cells);
  EXPECT_NEAR(dry_green.shares()[1], wet_green.shares()[1], 1e-4);
}

// The probe reads the medium of the visible paint: wet, and after it has dried.
TEST(PaintProbe, ReadsTheMediumOfTheVisiblePaintWetAndDry) {
  Painting p(flat_spec());
  p.set_brush(round_brush());
  const Medium matte{Finish::matte, 0.4};
  p.load_brush({{"red", 1.0}}, 5.0, kDefaultPaintBody, matte);
  test::stroke_line(p, 2.0, 6.0, 10.0, 6.0, 0.8f);
  p.wipe_brush();
  p.load_brush({{"blue", 1.0}}, 5.0);  // no medium
  test::stroke_line(p, 2.0, 9.0, 10.0, 9.0, 0.8f);
  const PaintProbe wet = probe_paint(p, 60.5, 60.5, 2.0);
  EXPECT_FLOAT_EQ(wet.medium.share, 1.0f);
  EXPECT_NEAR(wet.medium.log_rms, medium_log_rms(matte), 1e-5);
  EXPECT_FLOAT_EQ(probe_paint(p, 60.5, 90.5, 1.0).medium.share, 0.0f);
  p.dry(1.0);
  const PaintProbe dry = probe_paint(p, 60.5, 60.5, 2.0);
  ASSERT_EQ(dry.dry_cells, dry.cells);
  EXPECT_NEAR(dry.medium.log_rms, medium_log_rms(matte), 1e-5);
  // What a brush loads to lay the same paint again.
  const std::optional<Medium> again = loadable_medium(dry.medium);
  ASSERT_TRUE(again.has_value());
  EXPECT_EQ(again->finish, Finish::matte);
  EXPECT_NEAR(again->amount, 0.4, 1e-4);
}

TEST(PaintProbe, LoadableMediumInvertsTheMediumsRoughnessAndNeedsHalfTheShare) {
  for (const Medium m : {Medium{Finish::gloss, 1.0}, Medium{Finish::gloss, 0.25},
                         Medium{Finish::matte, 0.7}, Medium{Finish::satin, 1.0}}) {
    const std::optional<Medium> back = loadable_medium(paint_medium(m));
    ASSERT_TRUE(back.has_value());
    EXPECT_EQ(back->finish, m.finish);
    EXPECT_NEAR(back->amount, m.amount, 1e-5);
  }
  EXPECT_FALSE(loadable_medium(PaintMedium{}).has_value());
  EXPECT_FALSE(loadable_medium(PaintMedium{0.4f, 0.0f}).has_value());
}

}  // namespace
}  // namespace impasto::paintcore
