// Media and varnish from the painting (paintcore/paint_surface.hpp) in the ghs surface model
// (surface_shading.hpp): two strokes of one paint, one mixed with a gloss medium and one with
// a matte medium, side by side in one painting under a raking light.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "image_checks.hpp"
#include "impasto/data/lights.hpp"
#include "impasto/data/pigments.hpp"
#include "impasto/paintcore/painting.hpp"
#include "impasto/render/paint_layer.hpp"
#include "impasto/render/surface_shading.hpp"
#include "impasto/render/tile_renderer.hpp"

using namespace impasto;
using namespace impasto::render;

namespace {

constexpr const char* kWhite = "White";
constexpr const char* kBlack = "Black";

// White (the ground) and Black, under D65.
SpectralPalette white_and_black_palette(const RenderSettings& settings) {
  const auto& db = data::PigmentDatabase::defaults();
  const std::vector<data::Pigment> pigments{db.get(kWhite), db.get(kBlack)};
  return SpectralPalette(settings, data::light_from_spec("D65"), pigments,
                         hiding_reflectance(pigments[0]));
}

Image shade_painting(const RenderSettings& settings, const paintcore::Painting& painting) {
  TileRenderer renderer(settings, white_and_black_palette(settings));
  renderer.render_all(painting.canvas());
  return renderer.image();
}

RenderSettings raking_ghs() {
  RenderSettings s;
  s.display = DisplayEncoding::linear_srgb;
  s.surface.model = SurfaceModel::ghs;
  s.light_elevation_deg = 35.0;
  s.light_azimuth_deg = 90.0;  // across the strokes, whose ridges run along x
  return s;
}

// 160 x 96 cells (16 x 9.6 mm): a dark grey stroke along y = 2.5 mm with `top`, one along
// y = 6.5 mm with `bottom` (nullopt: no medium), dried.
paintcore::Painting two_strokes(std::optional<paintcore::Medium> top,
                                std::optional<paintcore::Medium> bottom) {
  paintcore::Painting p(paintcore::CanvasSpec{160, 96, 254.0, 0}, 1);
  p.set_brush(paintcore::BrushSettings{"round", 2.5, 0.5});
  for (const auto& [y, medium] : {std::pair{2.5, top}, std::pair{6.5, bottom}}) {
    p.wipe_brush();
    p.load_brush({{kWhite, 1.0}, {kBlack, 3.0}}, 12.0, paintcore::kDefaultPaintBody, medium);
    p.begin_stroke();
    for (int i = 0; i <= 30; ++i) {
      paintcore::PenSample s;
      s.x_mm = 2.0 + 12.0 * i / 30.0;
      s.y_mm = y;
      s.pressure = 0.7f;
      s.buttons = paintcore::kPenTip;
      p.stroke_to(s);
    }
    p.end_stroke();
  }
  p.dry(1.0);
  return p;
}

// The brightest and the mean cell of the paint (thicker than 0.02 mm) in a band of rows, in
// the middle of the strokes' length (the bare white ground around them is left out).
struct Band {
  float peak = 0.0f, mean = 0.0f;
};
Band band(const Image& image, const paintcore::Painting& p, int y0, int y1) {
  Band b;
  double sum = 0.0;
  int cells = 0;
  for (int y = y0; y < y1; ++y) {
    for (int x = 50; x < 110; ++x) {
      if (p.canvas().dry_height_mm(x, y) + p.canvas().wet_volume_mm(x, y) < 0.02f) continue;
      const float l = luminance(image, x, y);
      b.peak = std::max(b.peak, l);
      sum += l;
      ++cells;
    }
  }
  b.mean = cells > 0 ? static_cast<float>(sum / cells) : 0.0f;
  return b;
}

constexpr int kTop0 = 10, kTop1 = 40, kBottom0 = 50, kBottom1 = 80;  // rows of each stroke

}  // namespace

TEST(SurfaceMedium, GlossStrokeHasAHighlightAndMatteStrokeNoneInOnePainting) {
  const paintcore::Painting p = two_strokes(paintcore::Medium{paintcore::Finish::gloss, 1.0},
                                            paintcore::Medium{paintcore::Finish::matte, 1.0});
  const Image image = shade_painting(raking_ghs(), p);
  const Band gloss = band(image, p, kTop0, kTop1), matte = band(image, p, kBottom0, kBottom1);
  std::printf("gloss stroke: peak %.4f mean %.4f; matte stroke: peak %.4f mean %.4f\n", gloss.peak,
              gloss.mean, matte.peak, matte.mean);
  // The gloss film throws a highlight off the ridges facing the light: far above its mean.
  EXPECT_GT(gloss.peak, 3.0f * gloss.mean);
  EXPECT_GT(gloss.peak, 2.0f * matte.peak);
  // The matte film spreads that light into a sheen: no peak far above its own mean.
  EXPECT_LT(matte.peak, 2.0f * matte.mean);
  // Blinn-Phong knows nothing of media: the two strokes render alike there.
  RenderSettings blinn = raking_ghs();
  blinn.surface.model = SurfaceModel::blinn;
  const Image flat = shade_painting(blinn, p);
  EXPECT_NEAR(band(flat, p, kTop0, kTop1).peak, band(flat, p, kBottom0, kBottom1).peak,
              0.05f * band(flat, p, kTop0, kTop1).peak);
}

TEST(SurfaceMedium, PaintWithoutAMediumTakesTheSettingsMedium) {
  // Cells without a medium shade on the settings' surface (as every painting did before media
  // were part of the paint); a gloss medium in the paint is the same surface to within the
  // quantisation of the levels (SurfaceShading::kLevelStep).
  const paintcore::Painting none = two_strokes(std::nullopt, std::nullopt);
  const paintcore::Painting gloss = two_strokes(paintcore::Medium{paintcore::Finish::gloss, 1.0},
                                                paintcore::Medium{paintcore::Finish::gloss, 1.0});
  RenderSettings s = raking_ghs();
  s.surface.medium = surface::Finish::gloss;
  const Image a = shade_painting(s, none), b = shade_painting(s, gloss);
  ASSERT_EQ(a.rgb.size(), b.rgb.size());
  float worst = 0.0f;
  for (std::size_t i = 0; i < a.rgb.size(); ++i)
    worst = std::max(worst, std::abs(a.rgb[i] - b.rgb[i]) / std::max(a.rgb[i], 1e-3f));
  EXPECT_LT(worst, 0.01f);
  // With the settings' medium matte, the unmixed paint turns matte and the gloss paint stays.
  s.surface.medium = surface::Finish::matte;
  const Image c = shade_painting(s, none), d = shade_painting(s, gloss);
  EXPECT_GT(band(d, gloss, kTop0, kTop1).peak, 2.0f * band(c, none, kTop0, kTop1).peak);
}

TEST(SurfaceMedium, MatteVarnishTakesTheHighlightAwayAndUndoGivesItBack) {
  paintcore::Painting p = two_strokes(paintcore::Medium{paintcore::Finish::gloss, 1.0},
                                      paintcore::Medium{paintcore::Finish::gloss, 1.0});
  const RenderSettings s = raking_ghs();
  const Image before = shade_painting(s, p);
  // Over the top stroke only.
  p.apply_varnish(paintcore::Finish::matte, 0.03, paintcore::CellRect{0, 0, 160, 45});
  const Image wet = shade_painting(s, p);  // a fresh varnish is a liquid: glossy
  const float highlight = band(before, p, kTop0, kTop1).peak;
  EXPECT_GT(band(wet, p, kTop0, kTop1).peak, 0.5f * highlight);
  p.dry(1.0);
  const Image varnished = shade_painting(s, p);
  EXPECT_LT(band(varnished, p, kTop0, kTop1).peak, 0.5f * highlight);
  // The other stroke keeps its surface; only the coat's raised relief reaches it, through the
  // relief's occlusion and shadows (a 0.03 mm step a few cells away): a trace.
  for (int y = kBottom0; y < kBottom1; ++y)
    for (int x = 50; x < 110; ++x)
      ASSERT_NEAR(luminance(varnished, x, y), luminance(before, x, y),
                  1e-3f * luminance(before, x, y));
  ASSERT_TRUE(p.undo());
  ASSERT_TRUE(p.undo());
  EXPECT_EQ(shade_painting(s, p).rgb, before.rgb);
}
