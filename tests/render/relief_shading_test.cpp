// Cast shadows and ambient occlusion of the paint relief (relief_shading.hpp) on height
// fields whose answers follow from geometry, and in the tile renderer: flat canvas
// unchanged, shadows across tiles kept right by incremental updates, the switches.
#include "impasto/render/relief_shading.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <numbers>
#include <random>
#include <stdexcept>
#include <vector>

#include "image_checks.hpp"
#include "impasto/data/lights.hpp"
#include "impasto/data/pigments.hpp"
#include "impasto/render/render_settings.hpp"
#include "impasto/render/tile_renderer.hpp"
#include "white_and_blue_palette.hpp"

using namespace impasto;
using namespace impasto::render;
using paintcore::kTileSize;

namespace {

constexpr double kCellMm = 0.1;

struct Field {
  int width, height;
  std::vector<float> heights;
  Field(int w, int h, float value = 0.0f)
      : width(w), height(h), heights(static_cast<std::size_t>(w * h), value) {}
  float& at(int x, int y) { return heights[static_cast<std::size_t>(y * width + x)]; }
  relief::HeightField view() const { return {heights.data(), width, height}; }
  float highest() const { return *std::max_element(heights.begin(), heights.end()); }
};

RenderSettings light_at(double azimuth_deg, double elevation_deg, double diameter_deg = 3.0) {
  RenderSettings s;
  s.light_azimuth_deg = azimuth_deg;
  s.light_elevation_deg = elevation_deg;
  s.shadow_light_diameter_deg = diameter_deg;
  return s;
}

TEST(ReliefShading, FlatCanvasSeesTheWholeLightAndSky) {
  Field flat(40, 30, 0.37f);
  for (double azimuth : {0.0, 33.0, 90.0, 225.0, 300.0}) {
    for (double elevation : {1.0, 10.0, 30.0, 89.0, 90.0}) {
      const auto p = relief::relief_params(light_at(azimuth, elevation), kCellMm);
      for (int y = 0; y < flat.height; y += 7) {
        for (int x = 0; x < flat.width; x += 5) {
          EXPECT_EQ(relief::shadow(flat.view(), x, y, flat.highest(), p), 1.0f);
          EXPECT_EQ(relief::occlusion(flat.view(), x, y, p), 1.0f);
        }
      }
    }
  }
}

TEST(ReliefShading, VisibleDiscShareRunsFromWholeToNone) {
  const float elevation = 0.5f, r = 0.05f;
  EXPECT_EQ(relief::visible_disc_share(elevation - 2 * r, elevation, r), 1.0f);
  EXPECT_EQ(relief::visible_disc_share(elevation + 2 * r, elevation, r), 0.0f);
  EXPECT_NEAR(relief::visible_disc_share(elevation, elevation, r), 0.5f, 1e-6f);
  float last = 1.0f;
  for (int i = -10; i <= 10; ++i) {
    const float share = relief::visible_disc_share(elevation + 0.1f * i * r, elevation, r);
    EXPECT_LE(share, last);
    last = share;
  }
}

// A wall of height H along x = wall_x lit from +x at elevation e casts a shadow that ends,
// seen from the ground, where the wall's top stands at angle e: H / tan(e) behind it.
TEST(ReliefShading, AWallCastsAShadowOfGeometricLength) {
  const float wall_height = 1.0f;
  const int wall_x = 150;
  Field field(200, 8);
  for (int y = 0; y < field.height; ++y) field.at(wall_x, y) = wall_height;
  for (double elevation : {20.0, 30.0, 45.0}) {
    RenderSettings s = light_at(0.0, elevation, 2.0);
    s.shadow_reach_mm = 20.0;
    const auto p = relief::relief_params(s, kCellMm);
    // The last cell (walking away from the wall) with less than half the disc in view.
    int last_dark = wall_x;
    for (int x = wall_x - 1; x >= 0; --x) {
      if (relief::shadow(field.view(), x, 4, field.highest(), p) < 0.5f) last_dark = x;
    }
    const double expected_cells =
        wall_height / std::tan(elevation * std::numbers::pi / 180.0) / kCellMm;
    EXPECT_NEAR(wall_x - last_dark, expected_cells, 1.5) << elevation;
    // Far enough out, the whole disc shows; at the wall's foot none of it.
    EXPECT_EQ(relief::shadow(field.view(), 0, 4, field.highest(), p), 1.0f);
    EXPECT_EQ(relief::shadow(field.view(), wall_x - 1, 4, field.highest(), p), 0.0f);
    // The lit side of the wall is not shadowed.
    EXPECT_EQ(relief::shadow(field.view(), wall_x + 3, 4, field.highest(), p), 1.0f);
  }
}

TEST(ReliefShading, ALargerLightGivesAWiderPenumbra) {
  Field field(200, 4);
  for (int y = 0; y < field.height; ++y) field.at(150, y) = 3.0f;
  const auto penumbra_cells = [&](double diameter) {
    const auto p = relief::relief_params(light_at(0.0, 30.0, diameter), kCellMm);
    int partial = 0;
    for (int x = 0; x < 150; ++x) {
      const float share = relief::shadow(field.view(), x, 2, field.highest(), p);
      partial += share > 0.0f && share < 1.0f ? 1 : 0;
    }
    return partial;
  };
  // 3 mm / tan(30° ∓ r): about 2 cells at 1° across, 8 at 4°.
  EXPECT_GT(penumbra_cells(1.0), 0);
  EXPECT_GT(penumbra_cells(4.0), 2 * penumbra_cells(1.0));
}

TEST(ReliefShading, ShadowsFollowTheLightsAzimuth) {
  Field field(61, 61);
  field.at(30, 30) = 1.0f;  // a pin
  for (double azimuth : {0.0, 60.0, 135.0, 200.0, 290.0}) {
    const auto p = relief::relief_params(light_at(azimuth, 30.0), kCellMm);
    const double a = azimuth * std::numbers::pi / 180.0;
    // Three cells away from the light behind the pin: dark; toward the light: lit.
    const int bx = 30 - static_cast<int>(std::lround(3 * std::cos(a)));
    const int by = 30 - static_cast<int>(std::lround(3 * std::sin(a)));
    const int fx = 30 + static_cast<int>(std::lround(3 * std::cos(a)));
    const int fy = 30 + static_cast<int>(std::lround(3 * std::sin(a)));
    EXPECT_LT(relief::shadow(field.view(), bx, by, 1.0f, p), 0.5f) << azimuth;
    EXPECT_EQ(relief::shadow(field.view(), fx, fy, 1.0f, p), 1.0f) << azimuth;
  }
}

TEST(ReliefShading, TheMaxHeightCutDoesNotChangeTheShadow) {
  Field field(96, 96);
  std::mt19937 rng(5);
  std::uniform_real_distribution<float> height(0.0f, 2.0f);
  for (float& h : field.heights) h = height(rng);
  const auto p = relief::relief_params(light_at(200.0, 25.0), kCellMm);
  for (int y = 0; y < field.height; y += 3) {
    for (int x = 0; x < field.width; x += 3) {
      EXPECT_EQ(relief::shadow(field.view(), x, y, field.highest(), p),
                relief::shadow(field.view(), x, y, std::numeric_limits<float>::max(), p));
    }
  }
}

TEST(ReliefShading, MarchBoundedByTheHeightRangeGivesTheSameShadows) {
  Field field(120, 60);
  std::mt19937 rng(9);
  std::uniform_real_distribution<float> height(0.0f, 0.4f);
  for (float& h : field.heights) h = height(rng);
  for (double elevation : {8.0, 30.0, 60.0}) {
    const RenderSettings s = light_at(160.0, elevation);
    const auto capped = relief::relief_params(s, kCellMm);
    const auto bounded = relief::relief_params(s, kCellMm, field.highest());
    EXPECT_LT(bounded.shadow_steps, capped.shadow_steps) << elevation;  // thin paint: shorter
    for (int y = 0; y < field.height; y += 2) {
      for (int x = 0; x < field.width; x += 2) {
        ASSERT_EQ(relief::shadow(field.view(), x, y, field.highest(), bounded),
                  relief::shadow(field.view(), x, y, field.highest(), capped))
            << x << "," << y << " at " << elevation;
      }
    }
  }
}

TEST(ReliefShading, FurrowsAreOccludedDeeperOnesMore) {
  const auto furrow_occlusion = [](float depth) {
    Field field(41, 41, depth);
    for (int y = 0; y < field.height; ++y) field.at(20, y) = 0.0f;  // a groove one cell wide
    const auto p = relief::relief_params(RenderSettings{}, kCellMm);
    return relief::occlusion(field.view(), 20, 20, p);
  };
  EXPECT_EQ(furrow_occlusion(0.0f), 1.0f);
  EXPECT_LT(furrow_occlusion(0.2f), 1.0f);
  EXPECT_LT(furrow_occlusion(1.0f), furrow_occlusion(0.2f));
  // A ridge's crest sees the whole sky.
  Field ridge(41, 41);
  for (int y = 0; y < ridge.height; ++y) ridge.at(20, y) = 1.0f;
  EXPECT_EQ(
      relief::occlusion(ridge.view(), 20, 20, relief::relief_params(RenderSettings{}, kCellMm)),
      1.0f);
}

TEST(ReliefShading, ReachCoversTheCellsThatReadAChange) {
  // Light from the upper left (225°): shadows fall down and right of a change.
  RenderSettings s = light_at(225.0, 30.0);
  s.shadow_reach_mm = 3.0;
  s.occlusion_radius_mm = 0.5;
  const auto p = relief::relief_params(s, kCellMm);
  const relief::Reach r = relief::reach(p);
  EXPECT_GE(r.right, static_cast<int>(3.0 / kCellMm / std::numbers::sqrt2));
  EXPECT_GE(r.bottom, static_cast<int>(3.0 / kCellMm / std::numbers::sqrt2));
  EXPECT_EQ(r.left, 5);  // the occlusion radius
  EXPECT_EQ(r.top, 5);
  s.shadows = false;
  s.occlusion = false;
  const relief::Reach off = relief::reach(relief::relief_params(s, kCellMm));
  EXPECT_EQ(off.left + off.right + off.top + off.bottom, 4);  // the normals' rim alone
}

TEST(ReliefShading, SettingsOutOfRangeAreRefused) {
  for (auto set : {+[](RenderSettings& s) { s.shadow_light_diameter_deg = 0.0; },
                   +[](RenderSettings& s) { s.shadow_light_diameter_deg = std::nan(""); },
                   +[](RenderSettings& s) { s.shadow_reach_mm = -1.0; },
                   +[](RenderSettings& s) { s.occlusion_radius_mm = std::nan(""); }}) {
    RenderSettings s;
    set(s);
    EXPECT_THROW(validate(s), std::runtime_error);
  }
}

// --- in the tile renderer ---

// 3×3 tiles at 254 dpi (0.1 mm cells), a thick ridge of paint `height` mm across the
// middle tile's width and past its edges.
void paint_ridge(paintcore::Canvas& canvas, int tile_index, float height) {
  paintcore::Tile& tile = canvas.ensure_tile(tile_index, 2);
  for (int y = 20; y < 44; ++y) {
    for (int x = 0; x < kTileSize; ++x) {
      const auto c = static_cast<std::size_t>(y * kTileSize + x);
      const float v = height * static_cast<float>(std::sin((y - 20) * std::numbers::pi / 24.0));
      tile.wet_volume_mm[c] = v;
      tile.pigment(0)[c] = 0.8f * v;
      tile.pigment(1)[c] = 0.05f * v;
    }
  }
}

TEST(ReliefRender, IncrementalShadowsAcrossTilesEqualAFullRender) {
  for (double azimuth : {225.0, 90.0, 10.0}) {
    RenderSettings settings = light_at(azimuth, 20.0);
    paintcore::Canvas canvas({3 * kTileSize, 3 * kTileSize, 254.0, 3});
    TileRenderer renderer(settings, white_and_blue_palette(settings));
    renderer.update(canvas, {});
    paint_ridge(canvas, 4, 2.0f);  // the middle tile: its shadow falls into its neighbours
    const int changed[] = {4};
    const RenderStats stats = renderer.update(canvas, changed);
    EXPECT_GT(stats.border_cells, 2 * kTileSize) << azimuth;
    TileRenderer fresh(settings, white_and_blue_palette(settings));
    fresh.render_all(canvas);
    expect_identical(renderer.image(), fresh.image());
    // And back: the ridge removed, its shadow goes with it.
    paint_ridge(canvas, 4, 0.0f);
    renderer.update(canvas, changed);
    fresh.render_all(canvas);
    expect_identical(renderer.image(), fresh.image());
  }
}

float luminance_sum(const Image& image, int x0, int y0, int x1, int y1) {
  float sum = 0.0f;
  for (int y = y0; y < y1; ++y) {
    for (int x = x0; x < x1; ++x) {
      const float* p = image.rgb.data() + 3 * static_cast<std::size_t>(y * image.width + x);
      sum += p[0] + p[1] + p[2];
    }
  }
  return sum;
}

TEST(ReliefRender, TheRidgeShadowsTheSideAwayFromTheLight) {
  RenderSettings on = light_at(270.0, 30.0);  // light from the top (−y)
  RenderSettings off = on;
  off.shadows = false;
  off.occlusion = false;
  paintcore::Canvas canvas({3 * kTileSize, 3 * kTileSize, 254.0, 0});
  paint_ridge(canvas, 4, 2.0f);
  TileRenderer with(on, white_and_blue_palette(on));
  TileRenderer without(off, white_and_blue_palette(off));
  with.render_all(canvas);
  without.render_all(canvas);
  const Image a = with.image(), b = without.image();
  // Below the ridge (rows 108..118: within 2 mm / tan 30° = 35 cells): in shadow.
  EXPECT_LT(luminance_sum(a, 70, 108, 120, 118), 0.7f * luminance_sum(b, 70, 108, 120, 118));
  // Above it, on flat canvas toward the light and past the occlusion radius: unchanged.
  EXPECT_EQ(luminance_sum(a, 70, 40, 120, 60), luminance_sum(b, 70, 40, 120, 60));
}

}  // namespace
