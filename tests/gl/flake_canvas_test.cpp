// Flake sparkles through the GLSL shaders against the CPU reference (render::TileRenderer):
// the same sparkles in the same cells, within 2/255 of the displayable range, under a sun, a
// point light and a spot, in both depth models; and no sparkle where there is no flake paint.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <string>
#include <vector>

#include "gl_test_slots.hpp"
#include "impasto/paintcore/canvas.hpp"
#include "impasto/render/tile_renderer.hpp"
#include "impasto/render_gl/render_painting_gpu.hpp"

namespace impasto::render_gl {
namespace {

using paintcore::kTileCells;
using paintcore::kTileSize;

// 150x100 cells of 0.1 mm over a woven canvas: aluminium paint of varying thickness in tile
// 0, pearl over blue in tile 1, a dry aluminium layer (half of it under wet blue) in tile 4,
// tiles 2, 3 and 5 without flakes.
paintcore::Canvas flake_canvas() {
  paintcore::Canvas canvas({150, 100, 254.0, 5});
  const int slots = static_cast<int>(test::kWhiteAluminiumBluePearl.size());
  auto paint = [&](int index, int slot, float part, int other) {
    paintcore::Tile& tile = canvas.ensure_tile(index, slots);
    for (int cell = 0; cell < kTileCells; ++cell) {
      const int x = cell % kTileSize, y = cell / kTileSize;
      const float volume = 0.2f + 0.3f * static_cast<float>(x + y) / (2 * kTileSize);
      tile.wet_volume_mm[cell] = volume;
      tile.pigment(slot)[cell] = volume * part;
      tile.pigment(other)[cell] = volume * (1.0f - part);
    }
  };
  paint(0, 1, 0.6f, 0);
  paint(1, 3, 0.7f, 2);
  paint(2, 2, 0.5f, 0);
  paintcore::DryTile dry;
  dry.tile_index = 4;
  dry.volume_mm.assign(kTileCells, 0.3f);
  dry.slots = {1};
  dry.pigment_mm.assign(kTileCells, 0.15f);
  canvas.dry_layers().push_back({{dry}});
  paintcore::Tile& tile = canvas.ensure_tile(4, slots);
  tile.dry_height_mm.fill(0.3f);
  for (int cell = 0; cell < kTileCells; ++cell) {
    if (cell % kTileSize < kTileSize / 2) continue;
    tile.wet_volume_mm[cell] = 0.2f;
    tile.pigment(2)[cell] = 0.1f;
  }
  return canvas;
}

struct FlakeLightCase {
  std::string name;
  render::LightType light;
  double size_deg;
  bool masking;
};

void PrintTo(const FlakeLightCase& c, std::ostream* os) {
  *os << c.name;
}

class FlakeCanvas : public ::testing::TestWithParam<FlakeLightCase> {};

float displayed(float v) {
  return std::clamp(v, 0.0f, 1.0f);
}

TEST_P(FlakeCanvas, GpuSparklesMatchTheCpu) {
  const FlakeLightCase& c = GetParam();
  render::RenderSettings settings;
  settings.light_type = c.light;
  settings.light_size_deg = c.size_deg;
  settings.flake_masking = c.masking;
  settings.light_distance_mm = 150.0;
  settings.light_elevation_deg = 50.0;
  const paintcore::Canvas canvas = flake_canvas();

  render::TileRenderer cpu(settings, test::kWhiteAluminiumBluePearl);
  cpu.render_all(canvas);
  const render::Image expected = cpu.image();
  render::RenderSettings calm_settings = settings;
  calm_settings.flakes = false;
  render::TileRenderer calm(calm_settings, test::kWhiteAluminiumBluePearl);
  calm.render_all(canvas);
  const render::Image plain = calm.image();
  const render::Image actual =
      render_painting_gpu(canvas, test::kWhiteAluminiumBluePearl, settings);

  ASSERT_EQ(actual.width, expected.width);
  ASSERT_EQ(actual.height, expected.height);
  double worst = 0.0, brightest = 0.0;
  int worst_x = 0, worst_y = 0, sparkling = 0, same_cells = 0;
  for (int y = 0; y < expected.height; ++y) {
    for (int x = 0; x < expected.width; ++x) {
      bool sparkle = false, gpu_sparkle = false;
      for (int ch = 0; ch < 3; ++ch) {
        const double d =
            std::abs(displayed(actual.pixel(x, y)[ch]) - displayed(expected.pixel(x, y)[ch]));
        if (d > worst) {
          worst = d;
          worst_x = x;
          worst_y = y;
        }
        // A sparkle brighter than 1/255 over the image without flakes.
        const float calm = plain.pixel(x, y)[ch];
        sparkle = sparkle || expected.pixel(x, y)[ch] - calm > 1.0f / 255.0f;
        gpu_sparkle = gpu_sparkle || actual.pixel(x, y)[ch] - calm > 1.0f / 255.0f;
        brightest = std::max(brightest, double(expected.pixel(x, y)[ch]));
      }
      sparkling += sparkle ? 1 : 0;
      same_cells += sparkle == gpu_sparkle ? 1 : 0;
    }
  }
  std::cout << "[ " << c.name << " ] " << sparkling << " sparkling cells (brightest " << brightest
            << "); GPU vs CPU max " << worst * 255 << "/255 at (" << worst_x << "," << worst_y
            << ")\n";
  EXPECT_GT(sparkling, 10) << "the case shows sparkles";
  // The GPU sparkles in the very cells where the CPU does.
  EXPECT_EQ(same_cells, expected.width * expected.height);
  EXPECT_LE(worst, 2.0 / 255.0) << "worst pixel (" << worst_x << "," << worst_y << ")";
}

INSTANTIATE_TEST_SUITE_P(
    Lights, FlakeCanvas,
    ::testing::Values(FlakeLightCase{"sun_masking", render::LightType::directional, 0.53, true},
                      FlakeLightCase{"lamp_without_masking", render::LightType::directional, 3.0,
                                     false},
                      FlakeLightCase{"point", render::LightType::point, 2.0, true},
                      FlakeLightCase{"spot", render::LightType::spot, 2.0, true}),
    [](const ::testing::TestParamInfo<FlakeLightCase>& info) { return info.param.name; });

TEST(FlakeCanvasGpu, APaintingWithoutFlakePaintIsUnchanged) {
  // Flake pigments in the palette but not on the canvas: the GPU image equals the one with
  // flakes off, bit for bit.
  paintcore::Canvas canvas({100, 70, 254.0, 5});
  paintcore::Tile& tile = canvas.ensure_tile(0, 4);
  for (int cell = 0; cell < kTileCells; ++cell) {
    tile.wet_volume_mm[cell] = 0.3f;
    tile.pigment(2)[cell] = 0.15f;
  }
  render::RenderSettings on;
  render::RenderSettings off = on;
  off.flakes = false;
  const render::Image a = render_painting_gpu(canvas, test::kWhiteAluminiumBluePearl, on);
  const render::Image b = render_painting_gpu(canvas, test::kWhiteAluminiumBluePearl, off);
  EXPECT_EQ(a.rgb, b.rgb);
}

}  // namespace
}  // namespace impasto::render_gl
