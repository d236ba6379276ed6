// Media as part of the paint and varnish coats (paint_surface.hpp): carried by strokes into
// the cells, mixed, dried, undone and kept in the painting file.
#include <gtest/gtest.h>

#include <unistd.h>
#include <cmath>
#include <filesystem>

#include "impasto/paintcore/canvas_reframe.hpp"
#include "test_util.hpp"

namespace impasto::paintcore {
namespace {

// The surface of canvas cell (x, y).
CellSurface surface_at(const Painting& p, int x, int y) {
  const Canvas& c = p.canvas();
  const int index = c.tile_index(x / kTileSize, y / kTileSize);
  return cell_surface(c.tile(index), (y % kTileSize) * kTileSize + x % kTileSize);
}

bool any_surface(const Painting& p) {
  for (int index = 0; index < p.canvas().tile_count(); ++index)
    if (has_surface(p.canvas().tile(index))) return true;
  return false;
}

Painting brushed(int width = 128, int height = 64) {
  Painting p(test::flat_spec(width, height), 1);
  p.set_brush(test::round_brush(2.0));
  return p;
}

std::filesystem::path temp_file(const char* name) {
  return std::filesystem::temp_directory_path() /
         (std::string("impasto_surface_") + std::to_string(::getpid()) + "_" + name + ".impasto");
}

TEST(PaintMedium, AmountRunsFromTubePaintToTheFinishGeometrically) {
  const double satin = std::log10(film_roughness(Finish::satin).rms_um);
  const double matte = std::log10(film_roughness(Finish::matte).rms_um);
  EXPECT_DOUBLE_EQ(medium_log_rms({Finish::matte, 0.0}), satin);
  EXPECT_DOUBLE_EQ(medium_log_rms({Finish::matte, 1.0}), matte);
  EXPECT_NEAR(medium_log_rms({Finish::matte, 0.5}), 0.5 * (satin + matte), 1e-12);
  // The correlation length follows the finishes' curve and meets each finish.
  for (Finish f : {Finish::gloss, Finish::satin, Finish::matte}) {
    const FinishRoughness r = roughness_at_log_rms(finish_log_rms(f));
    EXPECT_NEAR(r.rms_um, film_roughness(f).rms_um, 1e-12);
    EXPECT_NEAR(r.correlation_um, film_roughness(f).correlation_um, 1e-12);
  }
  EXPECT_THROW(validate(Medium{Finish::gloss, 1.5}), std::runtime_error);
}

TEST(PaintMedium, MixesByVolumeAndMediumInLogSpace) {
  const PaintMedium gloss = paint_medium({Finish::gloss, 1.0});
  const PaintMedium matte = paint_medium({Finish::matte, 1.0});
  const PaintMedium half = mix(gloss, 1.0, matte, 1.0);
  EXPECT_FLOAT_EQ(half.share, 1.0f);
  EXPECT_NEAR(half.log_rms, 0.5 * (gloss.log_rms + matte.log_rms), 1e-6);
  // Paint without a medium dilutes the share but not the medium's roughness.
  const PaintMedium diluted = mix(matte, 1.0, PaintMedium{}, 3.0);
  EXPECT_FLOAT_EQ(diluted.share, 0.25f);
  EXPECT_FLOAT_EQ(diluted.log_rms, matte.log_rms);
  // One part in four of gloss: weighted by its volume of medium.
  const PaintMedium quarter = mix(gloss, 1.0, matte, 3.0);
  EXPECT_NEAR(quarter.log_rms, 0.25 * gloss.log_rms + 0.75 * matte.log_rms, 1e-6);
}

TEST(PaintSurface, PaintWithoutMediumOrVarnishMakesNoSurfaceData) {
  Painting p = brushed();
  p.load_brush({{"red", 1.0}}, 5.0);
  test::stroke_line(p, 1.0, 3.0, 10.0, 3.0, 0.8f);
  p.dry(0.5);
  EXPECT_FALSE(any_surface(p));
  EXPECT_EQ(p.brush().medium(), PaintMedium{});
}

TEST(PaintSurface, StrokeLaysTheBrushMediumWhereItLaysPaint) {
  Painting p = brushed();
  p.load_brush({{"red", 1.0}}, 5.0, kDefaultPaintBody, Medium{Finish::matte, 1.0});
  EXPECT_FLOAT_EQ(p.brush().medium().share, 1.0f);
  test::stroke_line(p, 1.0, 2.0, 5.0, 2.0, 0.8f);
  p.wipe_brush();
  p.load_brush({{"red", 1.0}}, 5.0);  // no medium: the brush's share drops to none
  EXPECT_FLOAT_EQ(p.brush().medium().share, 0.0f);
  test::stroke_line(p, 7.0, 4.5, 11.0, 4.5, 0.8f);
  const CellSurface matte = surface_at(p, 30, 20);
  ASSERT_GT(p.canvas().wet_volume_mm(30, 20), 0.01f);
  EXPECT_GT(matte.medium.share, 0.5f);
  EXPECT_NEAR(matte.medium.log_rms, finish_log_rms(Finish::matte), 1e-5);
  ASSERT_GT(p.canvas().wet_volume_mm(90, 45), 0.01f);
  EXPECT_FLOAT_EQ(surface_at(p, 90, 45).medium.share, 0.0f);
  EXPECT_FLOAT_EQ(surface_at(p, 100, 10).medium.share, 0.0f);  // no paint there
}

TEST(PaintSurface, UndoTakesTheMediumAwayWithThePaint) {
  Painting p = brushed();
  p.load_brush({{"red", 1.0}}, 5.0, kDefaultPaintBody, Medium{Finish::gloss, 1.0});
  const std::uint64_t before = p.state_hash();
  test::stroke_line(p, 1.0, 2.0, 5.0, 2.0, 0.8f);
  EXPECT_GT(surface_at(p, 30, 20).medium.share, 0.5f);
  ASSERT_TRUE(p.undo());
  EXPECT_EQ(p.state_hash(), before);
  EXPECT_FLOAT_EQ(surface_at(p, 30, 20).medium.share, 0.0f);
  ASSERT_TRUE(p.redo());
  EXPECT_GT(surface_at(p, 30, 20).medium.share, 0.5f);
}

TEST(PaintSurface, VarnishIsOneUndoableStepOverItsRegion) {
  Painting p = brushed();
  const std::uint64_t bare = p.state_hash();
  const std::size_t depth = p.undo_depth();
  p.apply_varnish(Finish::satin, 0.05, CellRect{60, 10, 100, 30});
  EXPECT_EQ(p.undo_depth(), depth + 1);
  const CellSurface in = surface_at(p, 70, 20);
  EXPECT_FLOAT_EQ(in.varnish_mm, 0.05f);
  EXPECT_FLOAT_EQ(in.varnish_wetness(), 1.0f);
  EXPECT_FLOAT_EQ(in.varnish_log_rms, static_cast<float>(finish_log_rms(Finish::satin)));
  EXPECT_FALSE(surface_at(p, 59, 20).varnished());
  EXPECT_FALSE(surface_at(p, 70, 30).varnished());
  EXPECT_NE(p.state_hash(), bare);
  ASSERT_TRUE(p.undo());
  EXPECT_EQ(p.state_hash(), bare);
  EXPECT_FALSE(any_surface(p));
  ASSERT_TRUE(p.redo());
  EXPECT_TRUE(surface_at(p, 70, 20).varnished());
  // A second coat: thicker, and its finish on top.
  p.apply_varnish(Finish::matte, 0.02);
  EXPECT_FLOAT_EQ(surface_at(p, 70, 20).varnish_mm, 0.07f);
  EXPECT_FLOAT_EQ(surface_at(p, 5, 5).varnish_mm, 0.02f);
  EXPECT_FLOAT_EQ(surface_at(p, 70, 20).varnish_log_rms,
                  static_cast<float>(finish_log_rms(Finish::matte)));
}

TEST(PaintSurface, VarnishRefusesBadThicknessAndRegionsOffTheCanvas) {
  Painting p = brushed();
  EXPECT_THROW(p.apply_varnish(Finish::gloss, 0.0), std::runtime_error);
  EXPECT_THROW(p.apply_varnish(Finish::gloss, std::nan("")), std::runtime_error);
  EXPECT_THROW(p.apply_varnish(Finish::gloss, 0.05, CellRect{200, 0, 300, 10}), std::runtime_error);
  EXPECT_EQ(p.undo_depth(), 1u);                                      // the brush only
  p.apply_varnish(Finish::gloss, 0.05, CellRect{120, 60, 200, 100});  // clipped
  EXPECT_TRUE(surface_at(p, 127, 63).varnished());
}

TEST(PaintSurface, VarnishDriesWithThePaintAndUndoWetsItAgain) {
  Painting p = brushed();
  p.apply_varnish(Finish::gloss, 0.04);
  p.dry(0.75);
  EXPECT_NEAR(surface_at(p, 10, 10).varnish_wetness(), 0.25f, 1e-6);
  EXPECT_FLOAT_EQ(surface_at(p, 10, 10).varnish_mm, 0.04f);
  ASSERT_TRUE(p.undo());
  EXPECT_FLOAT_EQ(surface_at(p, 10, 10).varnish_wetness(), 1.0f);
}

TEST(PaintSurface, PaintLaidOverAVarnishBuriesItThereAndUndoUncoversIt) {
  Painting p = brushed();
  p.apply_varnish(Finish::gloss, 0.03);
  p.dry(1.0);
  // A matte stroke across the middle (cells 10..50 along y = 20; 0.1 mm cells).
  p.load_brush({{"red", 1.0}}, 20.0, kDefaultPaintBody, Medium{Finish::matte, 1.0});
  const std::uint64_t varnished = p.state_hash();
  test::stroke_line(p, 1.0, 2.0, 5.0, 2.0, 0.9f);
  const CellSurface under_paint = surface_at(p, 30, 20);
  EXPECT_FALSE(under_paint.varnished()) << "the paint is on top";
  EXPECT_GT(under_paint.medium.share, 0.5f);
  EXPECT_TRUE(surface_at(p, 100, 50).varnished()) << "away from the stroke the varnish stays";
  ASSERT_TRUE(p.undo());
  EXPECT_EQ(p.state_hash(), varnished);
  EXPECT_TRUE(surface_at(p, 30, 20).varnished());
}

TEST(PaintSurface, MediumAndVarnishRoundTripThroughTheFile) {
  Painting p = brushed();
  p.load_brush({{"red", 1.0}}, 5.0, kDefaultPaintBody, Medium{Finish::matte, 0.6});
  test::stroke_line(p, 1.0, 2.0, 5.0, 2.0, 0.8f);
  p.apply_varnish(Finish::gloss, 0.03, CellRect{64, 0, 128, 64});
  p.dry(0.5);
  const auto file = temp_file("round_trip");
  p.save(file);
  const Painting back = Painting::load(file, 1);
  std::filesystem::remove(file);
  EXPECT_EQ(back.state_hash(), p.state_hash());
  EXPECT_EQ(back.brush().medium(), p.brush().medium());
  for (const auto& [x, y] : {std::pair{30, 20}, std::pair{70, 20}, std::pair{5, 60}}) {
    const CellSurface a = surface_at(p, x, y), b = surface_at(back, x, y);
    EXPECT_EQ(a.medium, b.medium) << x << "," << y;
    EXPECT_EQ(a.varnish_mm, b.varnish_mm);
    EXPECT_EQ(a.varnish_wet_mm, b.varnish_wet_mm);
    EXPECT_EQ(a.varnish_log_rms, b.varnish_log_rms);
  }
  EXPECT_TRUE(surface_at(back, 70, 20).varnished());
}

TEST(PaintSurface, UndoAfterReopeningStillTakesTheVarnishAway) {
  Painting p = brushed();
  p.load_brush({{"red", 1.0}}, 5.0, kDefaultPaintBody, Medium{Finish::satin, 1.0});
  test::stroke_line(p, 1.0, 2.0, 5.0, 2.0, 0.8f);
  p.apply_varnish(Finish::matte, 0.05);
  p.apply_varnish(Finish::gloss, 0.05, CellRect{0, 0, 64, 64});
  const auto file = temp_file("history");
  p.save(file);
  Painting back = Painting::load(file, 1);
  std::filesystem::remove(file);
  ASSERT_TRUE(back.undo());  // the gloss coat: the matte one is on top again
  EXPECT_FLOAT_EQ(surface_at(back, 10, 10).varnish_log_rms,
                  static_cast<float>(finish_log_rms(Finish::matte)));
  ASSERT_TRUE(back.undo());  // the matte coat
  EXPECT_FALSE(surface_at(back, 10, 10).varnished());
  EXPECT_GT(surface_at(back, 30, 20).medium.share, 0.5f);  // the stroke's medium stays
  ASSERT_TRUE(back.undo());
  EXPECT_FLOAT_EQ(surface_at(back, 30, 20).medium.share, 0.0f);
}

TEST(PaintSurface, UndoingALoadAfterReopeningGivesTheBrushItsMediumBack) {
  Painting p = brushed();
  p.load_brush({{"red", 1.0}}, 5.0, kDefaultPaintBody, Medium{Finish::matte, 0.5});
  const PaintMedium matte = p.brush().medium();
  p.load_brush({{"red", 1.0}}, 5.0);  // half the paint on the brush now has no medium
  ASSERT_FLOAT_EQ(p.brush().medium().share, 0.5f);
  const auto file = temp_file("brush_history");
  p.save(file);
  Painting back = Painting::load(file, 1);
  std::filesystem::remove(file);
  EXPECT_EQ(back.state_hash(), p.state_hash());
  ASSERT_TRUE(back.undo());
  EXPECT_EQ(back.brush().medium(), matte);
  ASSERT_TRUE(p.undo());
  EXPECT_EQ(back.state_hash(), p.state_hash());
}

TEST(PaintSurface, CropAndTheFinerCanvasKeepTheSurfaceWithThePaint) {
  Painting p = brushed();
  p.load_brush({{"red", 1.0}}, 5.0, kDefaultPaintBody, Medium{Finish::matte, 1.0});
  test::stroke_line(p, 1.0, 2.0, 5.0, 2.0, 0.8f);
  p.apply_varnish(Finish::satin, 0.05, CellRect{70, 10, 90, 30});
  const CellSurface painted = surface_at(p, 30, 20), varnished = surface_at(p, 80, 20);
  ASSERT_GT(painted.medium.share, 0.5f);
  const Painting fine = p.refined(2);
  EXPECT_EQ(surface_at(fine, 61, 41).medium, painted.medium);
  EXPECT_EQ(surface_at(fine, 161, 41).varnish_mm, varnished.varnish_mm);
  EXPECT_FALSE(surface_at(fine, 200, 41).varnished());
  p.reframe_canvas(crop_frame(20, 5, 80, 40));
  EXPECT_EQ(surface_at(p, 10, 15).medium, painted.medium);
  EXPECT_EQ(surface_at(p, 60, 15).varnish_mm, varnished.varnish_mm);
  ASSERT_TRUE(p.undo());
  EXPECT_EQ(surface_at(p, 80, 20).varnish_mm, varnished.varnish_mm);
}

// The brush picks up paint with its medium. An empty brush holds only what it picked up, so
// after dragging through paint of one medium it carries that medium. (Paint its drag moved
// onto a neighbour within the stroke counts as laid by the brush there: a trace of the
// brush's own medium, hence the tolerances.)
TEST(PaintSurface, AnEmptyBrushPicksUpTheMediumOfThePaintItDragsThrough) {
  Painting p = brushed();
  const Medium half_matte{Finish::matte, 0.5};
  p.load_brush({{"red", 1.0}}, 8.0, kDefaultPaintBody, half_matte);
  test::stroke_line(p, 1.0, 3.0, 11.0, 3.0, 0.8f);
  p.wipe_brush();
  p.load_brush({{"red", 1.0}}, 0.0, kDefaultPaintBody, Medium{Finish::gloss, 1.0});
  ASSERT_NEAR(p.brush().medium().log_rms, finish_log_rms(Finish::gloss), 1e-6);
  test::stroke_line(p, 3.0, 3.0, 9.0, 3.0, 0.9f);
  ASSERT_GT(p.brush_totals().volume, 0.01);  // it took paint
  EXPECT_NEAR(p.brush().medium().share, 1.0f, 1e-3);
  EXPECT_NEAR(p.brush().medium().log_rms, medium_log_rms(half_matte), 1e-3);
}

// By volume: a brush half gloss paint, half paint without a medium, has half the share.
// Picking up paint without a medium dilutes a gloss brush's share by the volume taken.
TEST(PaintSurface, PickingUpPaintWithoutAMediumDilutesTheBrushsShareByVolume) {
  Painting p = brushed();
  p.load_brush({{"red", 1.0}}, 8.0);  // no medium
  test::stroke_line(p, 1.0, 3.0, 11.0, 3.0, 0.8f);
  p.wipe_brush();
  p.load_brush({{"red", 1.0}}, 0.0, kDefaultPaintBody, Medium{Finish::gloss, 1.0});
  test::stroke_line(p, 3.0, 3.0, 9.0, 3.0, 0.9f);
  ASSERT_GT(p.brush_totals().volume, 0.01);
  EXPECT_NEAR(p.brush().medium().share, 0.0f, 1e-3);  // all it holds came from the canvas
  // Now gloss paint on the brush as well: share = its volume / all the brush holds.
  const double picked = p.brush_totals().volume;
  p.load_brush({{"red", 1.0}}, picked, kDefaultPaintBody, Medium{Finish::gloss, 1.0});
  EXPECT_NEAR(p.brush().medium().share, picked / p.brush_totals().volume, 1e-3);
  EXPECT_NEAR(p.brush().medium().share, 0.5, 1e-3);
}

// Dragging a gloss brush through matte paint and on over clean canvas lays down a mix there,
// and its own gloss before it reached the matte paint.
TEST(PaintSurface, AGlossBrushDraggedThroughMattePaintLaysAMixBeyondIt) {
  const auto lay = [](bool matte_first) {
    Painting p = brushed();
    if (matte_first) {
      p.load_brush({{"red", 1.0}}, 8.0, kDefaultPaintBody, Medium{Finish::matte, 1.0});
      test::stroke_line(p, 3.0, 3.0, 6.0, 3.0, 0.8f);
      p.wipe_brush();
    }
    p.load_brush({{"red", 1.0}}, 5.0, kDefaultPaintBody, Medium{Finish::gloss, 1.0});
    test::stroke_line(p, 1.0, 3.0, 11.0, 3.0, 0.8f);
    EXPECT_GT(p.canvas().wet_volume_mm(100, 30), 0.01f);
    // Before the brush reached the matte paint it laid its own gloss (its trailing edge was
    // still laying there when its front took up the first matte paint: a trace).
    EXPECT_GT(p.canvas().wet_volume_mm(14, 30), 0.01f);
    const double gloss = finish_log_rms(Finish::gloss), matte = finish_log_rms(Finish::matte);
    EXPECT_LT(surface_at(p, 14, 30).medium.log_rms, gloss + 0.01 * (matte - gloss));
    return surface_at(p, 100, 30).medium;
  };
  const double gloss = finish_log_rms(Finish::gloss), matte = finish_log_rms(Finish::matte);
  const PaintMedium clean = lay(false);
  EXPECT_NEAR(clean.log_rms, gloss, 1e-5);
  const PaintMedium mixed = lay(true);
  EXPECT_NEAR(mixed.share, 1.0f, 1e-3);
  EXPECT_GT(mixed.log_rms, gloss + 0.05 * (matte - gloss));
  EXPECT_LT(mixed.log_rms, matte - 0.05 * (matte - gloss));
}

// The relief under a varnish: the coat's top is what the light meets (surface_height_mm).
double box_roughness(const Painting& p, int x0, int y0, int x1, int y1) {
  // RMS of the surface about its 5x5 mean: the fine relief (bristle furrows, the weave).
  double sum = 0.0;
  int count = 0;
  for (int y = y0; y < y1; ++y)
    for (int x = x0; x < x1; ++x) {
      double mean = 0.0;
      for (int dy = -2; dy <= 2; ++dy)
        for (int dx = -2; dx <= 2; ++dx) mean += surface_height_mm(p.canvas(), x + dx, y + dy);
      const double d = surface_height_mm(p.canvas(), x, y) - mean / 25.0;
      sum += d * d;
      ++count;
    }
  return std::sqrt(sum / count);
}

TEST(PaintSurface, AnEvenVarnishOverAFlatCanvasChangesNoSlope) {
  Painting p = brushed();
  const float before = surface_height_mm(p.canvas(), 10, 10);
  p.apply_varnish(Finish::gloss, 0.2, std::nullopt);
  for (int y = 0; y < 64; ++y)
    for (int x = 0; x < 128; ++x) {
      ASSERT_FLOAT_EQ(surface_at(p, x, y).varnish_mm, 0.2f) << x << "," << y;
      ASSERT_NEAR(surface_height_mm(p.canvas(), x, y), before + 0.2f, 1e-6) << x << "," << y;
    }
}

TEST(PaintSurface, AThickVarnishLevelsTheFineReliefPartlyAndKeepsItsVolume) {
  const auto varnished = [](double thickness_mm) {
    Painting p(test::flat_spec(96, 96), 1);
    p.set_brush(test::round_brush(3.0));
    p.load_brush({{"red", 1.0}}, 10.0);
    for (int k = 0; k < 3; ++k) test::stroke_line(p, 1.0, 2.5 + 2.0 * k, 8.5, 2.5 + 2.0 * k, 0.9f);
    const double rough = box_roughness(p, 20, 20, 76, 76);
    p.apply_varnish(Finish::satin, thickness_mm, CellRect{10, 10, 86, 86});
    double volume = 0.0;
    for (int y = 10; y < 86; ++y)
      for (int x = 10; x < 86; ++x) volume += surface_at(p, x, y).varnish_mm;
    EXPECT_NEAR(volume / (76.0 * 76.0), thickness_mm, 1e-4 * thickness_mm);
    return box_roughness(p, 20, 20, 76, 76) / rough;
  };
  EXPECT_GT(varnish_levelled_share(0.1), 0.8);
  EXPECT_LT(varnish_levelled_share(0.01), 0.01);
  const double thin = varnished(0.01), thick = varnished(0.1);
  EXPECT_GT(thin, 0.97);   // a thin coat follows the brushwork
  EXPECT_LT(thick, 0.6);   // a thick one levels the furrows...
  EXPECT_GT(thick, 0.05);  // ... partly
}

}  // namespace
}  // namespace impasto::paintcore
