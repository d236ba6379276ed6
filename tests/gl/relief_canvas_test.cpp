// Shadows and occlusion of the paint relief on the GPU (relief_lib.glsl) against the CPU
// reference (relief_shading.hpp through render::TileRenderer), pixel by pixel, on thick
// ridges whose shadows cross tile edges; and the cached window view re-shading the shadow
// a changed tile casts into its neighbours.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <numbers>
#include <string>
#include <vector>

#include "gl_test_slots.hpp"
#include "image_difference.hpp"
#include "impasto/paintcore/canvas.hpp"
#include "impasto/render/tile_renderer.hpp"
#include "impasto/render_gl/canvas_renderer.hpp"
#include "impasto/render_gl/framebuffer.hpp"
#include "impasto/render_gl/gl_context.hpp"
#include "impasto/render_gl/render_painting_gpu.hpp"
#include "impasto/render_gl/shaded_view_cache.hpp"

namespace impasto::render_gl {
namespace {

using test::max_difference;

using paintcore::kTileSize;

// Ridges up to `height` mm, diagonal and round, over tiles 0, 1, 3 and 4 of a 3x2-tile
// canvas at 150 dpi (0.17 mm cells), the right and bottom tiles partial.
void paint_ridges(paintcore::Canvas& canvas, float height, std::initializer_list<int> tiles) {
  for (int index : tiles) {
    paintcore::Tile& tile =
        canvas.ensure_tile(index, static_cast<int>(test::kWhiteBlueRedOxide.size()));
    const int x0 = (index % canvas.tiles_x()) * kTileSize;
    const int y0 = (index / canvas.tiles_x()) * kTileSize;
    for (int y = 0; y < kTileSize; ++y) {
      for (int x = 0; x < kTileSize; ++x) {
        const int gx = x0 + x, gy = y0 + y;
        const int cell = y * kTileSize + x;
        const double along = std::sin((gx + gy) * 0.09);  // diagonal furrows and ridges
        const double r = std::hypot(gx - 70.0, gy - 60.0);
        const double v =
            r < 45.0 ? height * (0.55 + 0.45 * along) * std::sqrt(1.0 - r / 45.0) : 0.0;
        const auto volume = static_cast<float>(v);
        tile.wet_volume_mm[cell] = volume;
        tile.pigment(0)[cell] = 0.6f * volume;
        tile.pigment(1)[cell] = gx < 70 ? 0.3f * volume : 0.0f;
        tile.pigment(2)[cell] = gx < 70 ? 0.0f : 0.3f * volume;
      }
    }
  }
}

paintcore::Canvas thick_canvas() {
  paintcore::Canvas canvas({170, 110, 150.0, 5});
  paint_ridges(canvas, 2.5f, {0, 1, 3, 4});
  return canvas;
}

struct Light {
  double azimuth, elevation;
};

class ReliefCanvas : public ::testing::TestWithParam<Light> {};

TEST_P(ReliefCanvas, GpuShadowsAndOcclusionMatchTheCpu) {
  const Light light = GetParam();
  render::RenderSettings settings;
  settings.light_azimuth_deg = light.azimuth;
  settings.light_elevation_deg = light.elevation;
  const paintcore::Canvas canvas = thick_canvas();

  render::TileRenderer cpu(settings, test::kWhiteBlueRedOxide);
  cpu.render_all(canvas);
  const render::Image expected = cpu.image();
  const render::Image actual = render_painting_gpu(canvas, test::kWhiteBlueRedOxide, settings);
  ASSERT_EQ(actual.rgb.size(), expected.rgb.size());
  const double worst = max_difference(actual, expected);
  double sum = 0.0;
  for (std::size_t i = 0; i < actual.rgb.size(); ++i) {
    sum += std::abs(double(actual.rgb[i]) - expected.rgb[i]);
  }
  std::cout << "[ relief " << light.azimuth << "/" << light.elevation << " ] GPU vs CPU: max "
            << worst * 255 << "/255, mean " << sum / actual.rgb.size() * 255 << "/255\n";
  RecordProperty("max_difference_255", std::to_string(worst * 255));
  EXPECT_LE(worst, 2.0 / 255.0);

  // The relief does show: without shadows and occlusion some cells are clearly lighter.
  render::RenderSettings bare = settings;
  bare.shadows = bare.occlusion = false;
  render::TileRenderer unshadowed(bare, test::kWhiteBlueRedOxide);
  unshadowed.render_all(canvas);
  EXPECT_GT(max_difference(unshadowed.image(), expected), 0.05);
}

INSTANTIATE_TEST_SUITE_P(Lights, ReliefCanvas,
                         ::testing::Values(Light{225.0, 30.0}, Light{10.0, 15.0},
                                           Light{100.0, 45.0}, Light{300.0, 70.0}));

// The window's cached view after a tile of thick paint changes: its shadow falls into
// unchanged tiles, which the cached frame must re-shade as a whole redraw does.
TEST(ReliefCachedView, ShadowsCastIntoUnchangedTilesAreReshaded) {
  auto context = create_headless_context();
  render::RenderSettings settings;
  settings.wavelengths = 4;
  settings.light_azimuth_deg = 200.0;  // from the left: shadows fall to the right
  settings.light_elevation_deg = 20.0;
  paintcore::Canvas canvas({170, 110, 150.0, 5});
  paint_ridges(canvas, 0.5f, {0, 1, 3, 4});
  CanvasRenderer renderer(canvas.width_cells(), canvas.height_cells(), settings,
                          render::SpectralPalette(settings, test::kWhiteBlueRedOxide));
  renderer.upload_all(canvas);
  const int w = 170, h = 110;
  const CanvasView view = one_pixel_per_cell(w, h);
  Framebuffer window(w, h, TexelFormat::kRGBA8);
  ShadedViewCache cache;
  cache.draw(renderer, view, w, h, window.id());

  paint_ridges(canvas, 2.5f, {0});  // tile 0 grows: its shadow reaches into tile 1
  const int changed[] = {0};
  renderer.upload_tiles(canvas, changed);
  cache.invalidate_tiles(changed);
  const CachedDrawStats stats = cache.draw(renderer, view, w, h, window.id());
  EXPECT_FALSE(stats.full);
  Framebuffer whole(w, h, TexelFormat::kRGBA8);
  whole.bind();
  renderer.draw(view, w, h);
  EXPECT_EQ(window.read_rgba8(), whole.read_rgba8());
}

}  // namespace
}  // namespace impasto::render_gl
