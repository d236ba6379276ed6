// The tile renderer over a canvas: colours against the per-cell maths, incremental updates,
// dry-layer baking, thread-count independence.
#include "impasto/render/tile_renderer.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

#include "image_checks.hpp"
#include "impasto/data/lights.hpp"
#include "impasto/data/pigments.hpp"
#include "impasto/render/kubelka_munk_cell.hpp"
#include "impasto/render/paint_layer.hpp"
#include "three_pigment_palette.hpp"

using namespace impasto;
using namespace impasto::render;
using paintcore::kTileCells;
using paintcore::kTileSize;

namespace {

// Matte, flat lighting: the image is the K-M colour itself.
RenderSettings matte_settings() {
  RenderSettings settings;
  settings.dry_material = {0.0f, 10.0f};
  settings.wet_material = {0.0f, 10.0f};
  return settings;
}

// A 3×2-tile canvas (flat unless weave_seed != 0) with 1 mm of blue over tile 1's left half.
paintcore::Canvas painted_canvas(std::uint64_t weave_seed = 0) {
  paintcore::Canvas canvas({3 * kTileSize, 2 * kTileSize - 10, 254.0, weave_seed});
  paintcore::Tile& tile = canvas.ensure_tile(1, 3);
  for (int y = 0; y < kTileSize; ++y) {
    for (int x = 0; x < kTileSize / 2; ++x) {
      const auto c = static_cast<std::size_t>(y * kTileSize + x);
      tile.wet_volume_mm[c] = 1.0f;
      tile.pigment(2)[c] = 0.2f;
      tile.pigment(0)[c] = 0.3f;
    }
  }
  return canvas;
}

void add_dry_black_glaze(paintcore::Canvas& canvas, int tile_index, float volume_mm) {
  paintcore::DryTile dry;
  dry.tile_index = tile_index;
  dry.volume_mm.assign(kTileCells, volume_mm);
  dry.slots = {1};
  dry.pigment_mm.assign(kTileCells, volume_mm * 0.5f);
  canvas.dry_layers().push_back({{dry}});
  canvas.ensure_tile(tile_index, 3).dry_height_mm.fill(volume_mm);
}

}  // namespace

TEST(TileRenderer, FlatPaintShowsItsKubelkaMunkColour) {
  const RenderSettings settings = matte_settings();
  const paintcore::Canvas canvas = painted_canvas();
  TileRenderer renderer(settings, make_palette(settings));
  renderer.render_all(canvas);
  const Image image = renderer.image();

  // The expected colours, straight from the per-cell functions, the paint's surface (on by
  // default: the body seen through it, and the ambient light's share of the sky reflected
  // by it, k1, as white) and the display transform.
  ASSERT_TRUE(settings.saunderson);
  const SpectralPalette& palette = renderer.palette();
  const DisplayTransform display(DisplayEncoding::srgb);
  const auto k1 = static_cast<float>(settings.saunderson_k1);
  const auto seen = [&](std::vector<float> reflectance, float* rgb) {
    for (float& v : reflectance) {
      v = km::saunderson(v, k1, static_cast<float>(settings.saunderson_k2));
    }
    node_reflectance_to_xyz(palette, reflectance.data(), rgb);
    for (int c = 0; c < 3; ++c) {
      rgb[c] += static_cast<float>(settings.ambient) * k1 * palette.white_xyz()[c];
    }
    display.apply(rgb, 1);
  };
  std::vector<float> r(palette.ground(), palette.ground() + palette.nodes());
  float ground_rgb[3];
  seen(r, ground_rgb);
  const PigmentShare shares[2] = {{2, 0.2f}, {0, 0.3f}};
  // The painted cells hold 1 mm of paint: 1 / thickness_scale_mm units of optical depth.
  composite_paint_layer(palette, shares, static_cast<float>(1.0 / settings.thickness_scale_mm),
                        r.data());
  float paint_rgb[3];
  seen(r, paint_rgb);

  const float* paint = image.pixel(kTileSize + 10, 20);  // inside the paint, flat there
  const float* bare = image.pixel(5, 5);
  for (int c = 0; c < 3; ++c) {
    EXPECT_NEAR(paint[c], paint_rgb[c], 1e-5f);
    EXPECT_NEAR(bare[c], ground_rgb[c], 1e-5f);
  }
  EXPECT_LT(paint[0], paint[2]);  // phthalo blue tint is blue
  for (float v : image.rgb) {
    ASSERT_TRUE(std::isfinite(v));
  }
}

TEST(TileRenderer, D65GroundOfPerfectWhiteIsDisplayWhite) {
  RenderSettings settings = matte_settings();
  // Under a uniform sky: what the paint's surface does not let into the body (k1) it
  // reflects, so a perfect white stays white (under a lamp that share goes to the highlight).
  settings.ambient = 1.0;
  const data::Spectrum white{"white", {300.0, 900.0}, {1.0, 1.0}};
  for (int nodes : {1, 8, 16, 0}) {  // 0: every nanometre
    settings.wavelengths = nodes;
    TileRenderer renderer(
        settings, SpectralPalette(settings, data::light_from_spec("A"), test_pigments(), white));
    renderer.render_all(paintcore::Canvas({70, 70, 100.0, 0}));
    const Image image = renderer.image();
    const float* pixel = image.pixel(30, 40);
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(pixel[c], 1.0f, 1e-3f) << "N=" << nodes;
  }
}

TEST(TileRenderer, OnlyChangedTilesAreReshaded) {
  const RenderSettings settings = matte_settings();
  paintcore::Canvas canvas = painted_canvas(7);
  TileRenderer renderer(settings, make_palette(settings));
  const RenderStats first = renderer.update(canvas, {});
  EXPECT_EQ(first.tiles_shaded, canvas.tile_count());

  canvas.ensure_tile(4, 3).wet_volume_mm[100] = 0.5f;
  canvas.ensure_tile(4, 3).pigment(1)[100] = 0.5f;
  const int changed[] = {4};
  const RenderStats second = renderer.update(canvas, changed);
  EXPECT_EQ(second.tiles_shaded, 1);
  EXPECT_EQ(second.tiles_baked, 0);  // no dry layer there: the dry stack did not change
  EXPECT_GT(second.border_cells, 0);
  for (int t = 0; t < canvas.tile_count(); ++t) {
    EXPECT_EQ(renderer.shade_count(t), t == 4 ? 2u : 1u) << "tile " << t;
  }

  // The incremental image equals a full render of the same canvas, rims included.
  TileRenderer fresh(settings, make_palette(settings));
  fresh.render_all(canvas);
  expect_identical(renderer.image(), fresh.image());
}

TEST(TileRenderer, DryStackIsBakedOnceAndRebakedForANewLight) {
  const RenderSettings settings = matte_settings();
  paintcore::Canvas canvas = painted_canvas();
  add_dry_black_glaze(canvas, 0, 0.01f);
  TileRenderer renderer(settings, make_palette(settings));
  renderer.render_all(canvas);
  const float darkened = renderer.image().pixel(10, 10)[1];
  const float bare = renderer.image().pixel(2 * kTileSize + 10, 10)[1];
  EXPECT_LT(darkened, bare - 0.05f);

  // A wet change elsewhere in the tile keeps the baked dry stack.
  canvas.ensure_tile(0, 3).wet_volume_mm[5] = 0.1f;
  const int changed[] = {0};
  EXPECT_EQ(renderer.update(canvas, changed).tiles_baked, 0);

  // A new light re-bakes every tile.
  RenderSettings warm = settings;
  warm.light = std::string("A");  // (a literal here trips GCC 12's -Wrestrict false positive)
  renderer.set_settings(warm, make_palette(warm, "A"));
  const RenderStats relit = renderer.update(canvas, {});
  EXPECT_EQ(relit.tiles_baked, canvas.tile_count());
  EXPECT_EQ(relit.tiles_shaded, canvas.tile_count());
}

TEST(TileRenderer, HalfStorageStaysCloseToFloat) {
  RenderSettings settings = matte_settings();
  paintcore::Canvas canvas = painted_canvas(3);
  add_dry_black_glaze(canvas, 0, 0.004f);
  add_dry_black_glaze(canvas, 1, 0.002f);
  TileRenderer exact(settings, make_palette(settings));
  exact.render_all(canvas);
  settings.storage = ReflectanceStorage::float16;
  TileRenderer half(settings, make_palette(settings));
  half.render_all(canvas);
  const Image a = exact.image(), b = half.image();
  float worst = 0.0f;
  for (std::size_t i = 0; i < a.rgb.size(); ++i)
    worst = std::max(worst, std::abs(a.rgb[i] - b.rgb[i]));
  EXPECT_LT(worst, 2e-3f);
  EXPECT_GT(worst, 0.0f);  // the dry tiles do go through half precision
}

TEST(TileRenderer, ThreadCountDoesNotChangeTheImage) {
  RenderSettings settings;  // glossy, lit from the side: every term in play
  settings.light_elevation_deg = 35.0;
  paintcore::Canvas canvas = painted_canvas(11);
  add_dry_black_glaze(canvas, 3, 0.003f);
  settings.threads = 1;
  TileRenderer one(settings, make_palette(settings));
  one.render_all(canvas);
  settings.threads = 2;
  TileRenderer two(settings, make_palette(settings));
  two.render_all(canvas);
  expect_identical(one.image(), two.image());
}

TEST(TileRenderer, RejectsSlotsBeyondThePalette) {
  const RenderSettings settings = matte_settings();
  paintcore::Canvas canvas({64, 64, 100.0, 0});
  canvas.ensure_tile(0, 5);
  TileRenderer renderer(settings, make_palette(settings));
  EXPECT_THROW(renderer.render_all(canvas), std::runtime_error);
  const int bad[] = {7};
  EXPECT_THROW(renderer.update(canvas, bad), std::runtime_error);
}
