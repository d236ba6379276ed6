// Flake paint in the tile renderer: sparkles where the top layer holds flake pigment and
// nowhere else, no flake work (and bit-identical images) where there is none, none under
// diffuse light, and the same sparkles for the same painting, light and view.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <numbers>

#include "impasto/data/lights.hpp"
#include "impasto/data/pigments.hpp"
#include "impasto/render/flake_shading.hpp"
#include "impasto/render/tile_renderer.hpp"

using namespace impasto;
using namespace impasto::render;
using paintcore::kTileCells;
using paintcore::kTileSize;

namespace {

constexpr int kWhite = 0, kBlue = 1, kAluminium = 2, kPearl = 3;

std::vector<data::Pigment> pigments_with_flakes() {
  const auto& db = data::PigmentDatabase::defaults();
  return {db.get("White"), db.get("Blue Red Shade"), db.get("Aluminium Metallic"),
          db.get("Mica Blue Pearl")};
}

// The same slots with plain pigments in place of the flake paints.
std::vector<data::Pigment> pigments_without_flakes() {
  const auto& db = data::PigmentDatabase::defaults();
  auto pigments = pigments_with_flakes();
  pigments[kAluminium] = db.get("Black");
  pigments[kPearl] = db.get("Red");
  return pigments;
}

SpectralPalette make_palette(const RenderSettings& settings,
                             const std::vector<data::Pigment>& pigments) {
  return SpectralPalette(settings, data::light_from_spec(settings.light), pigments,
                         hiding_reflectance(pigments[0]));
}

RenderSettings linear_settings() {
  RenderSettings settings;
  settings.display = DisplayEncoding::linear_srgb;
  settings.light_elevation_deg = 45.0;
  return settings;
}

// 0.5 mm of paint, `part` of it pigment `slot` and the rest white, over the cells of tile
// `tile_index` with x in [x0, x1); a weave makes the normals vary.
void paint_wet(paintcore::Canvas& canvas, int tile_index, int slot, float part, int x0, int x1) {
  paintcore::Tile& tile = canvas.ensure_tile(tile_index, 4);
  for (int y = 0; y < kTileSize; ++y) {
    for (int x = x0; x < x1; ++x) {
      const auto c = static_cast<std::size_t>(y * kTileSize + x);
      tile.wet_volume_mm[c] = 0.5f;
      tile.pigment(slot)[c] = 0.5f * part;
      tile.pigment(kWhite)[c] = 0.5f * (1.0f - part);
    }
  }
}

// A 3×2-tile canvas at 254 dpi (0.1 mm cells): blue in tile 0, aluminium on the left half of
// tile 1, nothing elsewhere.
paintcore::Canvas metallic_canvas() {
  paintcore::Canvas canvas({3 * kTileSize, 2 * kTileSize, 254.0, 7});
  paint_wet(canvas, 0, kBlue, 0.3f, 0, kTileSize);
  paint_wet(canvas, 1, kAluminium, 0.5f, 0, kTileSize / 2);
  return canvas;
}

paintcore::Canvas plain_canvas() {
  paintcore::Canvas canvas({3 * kTileSize, 2 * kTileSize, 254.0, 7});
  paint_wet(canvas, 0, kBlue, 0.3f, 0, kTileSize);
  paint_wet(canvas, 1, kBlue, 0.6f, 0, kTileSize / 2);
  return canvas;
}

std::unique_ptr<TileRenderer> rendered(const RenderSettings& settings,
                                       const std::vector<data::Pigment>& pigments,
                                       const paintcore::Canvas& canvas) {
  auto renderer = std::make_unique<TileRenderer>(settings, make_palette(settings, pigments));
  renderer->render_all(canvas);
  return renderer;
}

Image render_image(const RenderSettings& settings, const std::vector<data::Pigment>& pigments,
                   const paintcore::Canvas& canvas) {
  return rendered(settings, pigments, canvas)->image();
}

std::size_t differing_values(const Image& a, const Image& b) {
  std::size_t n = 0;
  for (std::size_t i = 0; i < a.rgb.size(); ++i) n += a.rgb[i] != b.rgb[i] ? 1 : 0;
  return n;
}

// Sum over the channels of a pixel.
float brightness(const Image& image, int x, int y) {
  const float* p = image.pixel(x, y);
  return p[0] + p[1] + p[2];
}

}  // namespace

TEST(FlakeRender, APaintingWithoutFlakePaintIsBitIdenticalWithFlakesOnOrOff) {
  RenderSettings on = linear_settings();
  // The palettes differ (with and without the flake pigments): a rule trained on the
  // palette would differ with them, the Gaussian rule does not.
  on.node_weights = NodeWeights::interpolatory;
  RenderSettings off = on;
  off.flakes = false;
  const paintcore::Canvas canvas = plain_canvas();
  // The palette holds flake pigments, so the hook is live, but no cell uses them.
  const auto renderer = rendered(on, pigments_with_flakes(), canvas);
  const Image with_hook = renderer->image();
  for (int t = 0; t < canvas.tile_count(); ++t) {
    EXPECT_EQ(renderer->flake_cell_count(t), 0u) << "tile " << t << " did flake work";
  }
  EXPECT_EQ(differing_values(with_hook, render_image(off, pigments_with_flakes(), canvas)), 0u);
  EXPECT_EQ(differing_values(with_hook, render_image(on, pigments_without_flakes(), canvas)), 0u);
}

TEST(FlakeRender, NoFlakeShadingIsMadeWithoutFlakePigmentsOrUnderDiffuseLight) {
  RenderSettings settings = linear_settings();
  EXPECT_EQ(FlakeShading::create(settings, make_palette(settings, pigments_without_flakes())),
            nullptr);
  EXPECT_NE(FlakeShading::create(settings, make_palette(settings, pigments_with_flakes())),
            nullptr);
  settings.light_type = LightType::diffuse;
  EXPECT_EQ(FlakeShading::create(settings, make_palette(settings, pigments_with_flakes())),
            nullptr);
  settings.light_type = LightType::directional;
  settings.flakes = false;
  EXPECT_EQ(FlakeShading::create(settings, make_palette(settings, pigments_with_flakes())),
            nullptr);
}

TEST(FlakeRender, SparklesAppearWhereFlakePaintIsAndNowhereElse) {
  const RenderSettings on = linear_settings();
  RenderSettings off = on;
  off.flakes = false;
  const paintcore::Canvas canvas = metallic_canvas();
  const auto renderer = rendered(on, pigments_with_flakes(), canvas);
  const Image sparkling = renderer->image();
  const Image calm = render_image(off, pigments_with_flakes(), canvas);

  // Only tile 1 holds flakes: it alone is looked at, every one of its cells once.
  for (int t = 0; t < canvas.tile_count(); ++t) {
    EXPECT_EQ(renderer->flake_cell_count(t), t == 1 ? std::uint64_t{kTileCells} : 0u) << t;
  }
  int sparkles = 0, elsewhere = 0, darker = 0;
  for (int y = 0; y < canvas.height_cells(); ++y) {
    for (int x = 0; x < canvas.width_cells(); ++x) {
      const float gain = brightness(sparkling, x, y) - brightness(calm, x, y);
      const bool flake_paint = x >= kTileSize && x < kTileSize + kTileSize / 2 && y < kTileSize;
      if (gain > 0.0f) (flake_paint ? sparkles : elsewhere) += 1;
      // A sparkle only adds light (aluminium is grey, so every channel grows).
      const float* a = sparkling.pixel(x, y);
      const float* b = calm.pixel(x, y);
      for (int c = 0; c < 3; ++c) darker += a[c] < b[c] ? 1 : 0;
    }
  }
  EXPECT_EQ(elsewhere, 0);
  EXPECT_EQ(darker, 0);
  // ⟨N⟩ is small per 0.1 mm cell for the sun: a sprinkling, not a sheet.
  EXPECT_GT(sparkles, 5);
  EXPECT_LT(sparkles, kTileCells / 4);
}

TEST(FlakeRender, DiffuseLightMakesNoSparkles) {
  RenderSettings overcast = linear_settings();
  overcast.light_type = LightType::diffuse;
  RenderSettings off = overcast;
  off.flakes = false;
  const paintcore::Canvas canvas = metallic_canvas();
  EXPECT_EQ(differing_values(render_image(overcast, pigments_with_flakes(), canvas),
                             render_image(off, pigments_with_flakes(), canvas)),
            0u);
}

TEST(FlakeRender, ABiggerLightLightsMoreFlakes) {
  // ⟨N⟩ ∝ Δ²: a light 4 times wider lights far more cells (each less brightly).
  RenderSettings sun = linear_settings();
  RenderSettings lamp = sun;
  lamp.light_size_deg = 4 * sun.light_size_deg;
  RenderSettings off = sun;
  off.flakes = false;
  const paintcore::Canvas canvas = metallic_canvas();
  const Image calm = render_image(off, pigments_with_flakes(), canvas);
  auto count = [&](const Image& image) {
    int n = 0;
    for (int y = 0; y < kTileSize; ++y) {
      for (int x = kTileSize; x < kTileSize + kTileSize / 2; ++x) {
        n += brightness(image, x, y) > brightness(calm, x, y) ? 1 : 0;
      }
    }
    return n;
  };
  const int small = count(render_image(sun, pigments_with_flakes(), canvas));
  const int large = count(render_image(lamp, pigments_with_flakes(), canvas));
  EXPECT_GT(large, 4 * small);
}

TEST(FlakeRender, SparklesAreStableAcrossThreadCountsAndRenders) {
  RenderSettings one = linear_settings();
  one.threads = 1;
  RenderSettings many = one;
  many.threads = 3;
  const paintcore::Canvas canvas = metallic_canvas();
  const Image a = render_image(one, pigments_with_flakes(), canvas);
  EXPECT_EQ(differing_values(a, render_image(many, pigments_with_flakes(), canvas)), 0u);
  EXPECT_EQ(differing_values(a, render_image(one, pigments_with_flakes(), canvas)), 0u);
}

TEST(FlakeRender, DryFlakePaintSparklesUnlessWetPaintCoversIt) {
  RenderSettings on = linear_settings();
  RenderSettings off = on;
  off.flakes = false;
  paintcore::Canvas canvas({kTileSize, kTileSize, 254.0, 7});
  paintcore::DryTile dry;
  dry.tile_index = 0;
  dry.volume_mm.assign(kTileCells, 0.5f);
  dry.slots = {static_cast<std::uint8_t>(kAluminium)};
  dry.pigment_mm.assign(kTileCells, 0.25f);
  canvas.dry_layers().push_back({{dry}});
  canvas.ensure_tile(0, 4).dry_height_mm.fill(0.5f);
  // Wet blue over the right half hides the flakes there.
  paint_wet(canvas, 0, kBlue, 0.3f, kTileSize / 2, kTileSize);
  const Image sparkling = render_image(on, pigments_with_flakes(), canvas);
  const Image calm = render_image(off, pigments_with_flakes(), canvas);
  int left = 0, right = 0;
  for (int y = 0; y < kTileSize; ++y) {
    for (int x = 0; x < kTileSize; ++x) {
      if (brightness(sparkling, x, y) > brightness(calm, x, y))
        (x < kTileSize / 2 ? left : right)++;
    }
  }
  EXPECT_GT(left, 0);
  EXPECT_EQ(right, 0);
}

TEST(FlakeRender, PearlSparklesAreBlue) {
  const RenderSettings on = linear_settings();
  RenderSettings off = on;
  off.flakes = false;
  paintcore::Canvas canvas({kTileSize, kTileSize, 254.0, 7});
  paint_wet(canvas, 0, kPearl, 0.8f, 0, kTileSize);
  const Image sparkling = render_image(on, pigments_with_flakes(), canvas);
  const Image calm = render_image(off, pigments_with_flakes(), canvas);
  double red = 0, blue = 0;
  for (int y = 0; y < kTileSize; ++y) {
    for (int x = 0; x < kTileSize; ++x) {
      red += sparkling.pixel(x, y)[0] - calm.pixel(x, y)[0];
      blue += sparkling.pixel(x, y)[2] - calm.pixel(x, y)[2];
    }
  }
  EXPECT_GT(blue, 0.0);
  EXPECT_GT(blue, 2.0 * red);
}

TEST(FlakeRender, PointAndSpotLightsSparkleAndValidateTheirSettings) {
  RenderSettings settings = linear_settings();
  const paintcore::Canvas canvas = metallic_canvas();
  RenderSettings off = settings;
  off.flakes = false;
  const Image calm = render_image(off, pigments_with_flakes(), canvas);
  for (LightType type : {LightType::point, LightType::spot}) {
    settings.light_type = type;
    settings.light_distance_mm = 300.0;
    EXPECT_GT(differing_values(render_image(settings, pigments_with_flakes(), canvas), calm), 0u);
  }
  settings.light_size_deg = 0.0;
  EXPECT_THROW(validate(settings), std::runtime_error);
  settings.light_size_deg = 1.0;
  settings.light_distance_mm = std::nan("");
  EXPECT_THROW(validate(settings), std::runtime_error);
  EXPECT_EQ(parse_light_type("spot"), LightType::spot);
  EXPECT_THROW(parse_light_type("laser"), std::runtime_error);
}

TEST(FlakeRender, SparkleLightMatchesTheRendererUnits) {
  // Directional: strength (1 − ambient)·π / sin(elevation) at every node; point lights the
  // same irradiance at the canvas centre.
  RenderSettings settings;
  settings.ambient = 0.25;
  settings.light_elevation_deg = 30.0;
  const flakes::Light sun = sparkle_light(settings, 100.0, 50.0, 3);
  ASSERT_EQ(sun.spectral.size(), 3u);
  EXPECT_NEAR(sun.spectral[1], 0.75 * std::numbers::pi / 0.5, 1e-5);
  EXPECT_NEAR(sun.direction.z, -0.5, 1e-6);
  settings.light_type = LightType::point;
  settings.light_distance_mm = 200.0;
  const flakes::Light bulb = sparkle_light(settings, 100.0, 50.0, 3);
  EXPECT_NEAR(bulb.position_mm.z, 100.0, 1e-4);
  EXPECT_NEAR(bulb.spectral[0] / (200.0 * 200.0), sun.spectral[0], 1e-9);
}
