// The subsurface spread on the GPU (subsurface_spread.hpp, subsurface_spread_frag.glsl)
// against the CPU reference render::render_canvas_with_subsurface, pixel by pixel: a glaze over
// a sharp black and white edge, running off two sides of the canvas (where the CPU keeps the
// light in the edge cells); the window's path (tiles changed after the first draw); a painting
// with nothing that spreads; and the map's debug view.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

#include "gl_test_slots.hpp"
#include "image_difference.hpp"
#include "impasto/paintcore/canvas.hpp"
#include "impasto/render/subsurface.hpp"
#include "impasto/render/tile_renderer.hpp"
#include "impasto/render_gl/canvas_renderer.hpp"
#include "impasto/render_gl/framebuffer.hpp"
#include "impasto/render_gl/gl_context.hpp"
#include "impasto/render_gl/render_painting_gpu.hpp"

namespace impasto::render_gl {
namespace {

using paintcore::kTileCells;
using paintcore::kTileSize;

constexpr int kWidth = 100, kHeight = 70;  // four tiles, two of them partial

// A thin dry layer (too thin to spread), black left of x = 50 and white right
// of it, over a gentle ridge.
paintcore::Canvas make_edge_canvas() {
  paintcore::Canvas canvas({kWidth, kHeight, 300.0, 7});
  const int slots = static_cast<int>(test::kWhiteBlueRedBlack.size());
  paintcore::DryLayer layer;
  for (int index = 0; index < canvas.tile_count(); ++index) {
    paintcore::Tile& tile = canvas.ensure_tile(index, slots);
    paintcore::DryTile dry;
    dry.tile_index = index;
    dry.volume_mm.assign(kTileCells, 0.0f);
    dry.slots = {0, 3};
    dry.pigment_mm.assign(2 * kTileCells, 0.0f);
    const int x0 = (index % canvas.tiles_x()) * kTileSize;
    const int y0 = (index / canvas.tiles_x()) * kTileSize;
    for (int cell = 0; cell < kTileCells; ++cell) {
      const int gx = x0 + cell % kTileSize, gy = y0 + cell / kTileSize;
      const float ridge = 0.12f + 0.03f * static_cast<float>(std::sin(gx * 0.3 + gy * 0.2));
      dry.volume_mm[static_cast<std::size_t>(cell)] = 0.015f;
      tile.dry_height_mm[static_cast<std::size_t>(cell)] = ridge;
      const bool black = gx < 50;
      dry.pigment_mm[static_cast<std::size_t>(black ? kTileCells + cell : cell)] = 0.01f;
    }
    layer.tiles.push_back(std::move(dry));
  }
  canvas.dry_layers().push_back(std::move(layer));
  return canvas;
}

// A thick wet glaze (little red, less white: it scatters little) over cells [x0, x1) x [y0, y1).
void glaze(paintcore::Canvas& canvas, int x0, int y0, int x1, int y1, float volume_mm) {
  for (int y = y0; y < y1; ++y) {
    for (int x = x0; x < x1; ++x) {
      const int index = (y / kTileSize) * canvas.tiles_x() + x / kTileSize;
      paintcore::Tile& tile =
          canvas.ensure_tile(index, static_cast<int>(test::kWhiteBlueRedBlack.size()));
      const auto c = static_cast<std::size_t>((y % kTileSize) * kTileSize + x % kTileSize);
      tile.wet_volume_mm[c] = volume_mm;
      tile.pigment(2)[c] = 0.1f * volume_mm;
      tile.pigment(0)[c] = 0.005f * volume_mm;
      tile.pigment(3)[c] = 0.0f;
    }
  }
}

render::RenderSettings ghs_settings() {
  render::RenderSettings settings;
  settings.surface.model = render::SurfaceModel::ghs;
  settings.surface.subsurface = true;
  settings.light_azimuth_deg = 200.0;
  return settings;
}

render::Image cpu_with_spread(const paintcore::Canvas& canvas,
                              const render::RenderSettings& settings,
                              render::SubsurfaceMap* map = nullptr) {
  return render::render_canvas_with_subsurface(
      canvas, render::SpectralPalette(settings, test::kWhiteBlueRedBlack), settings, map);
}

// Reads the renderer's one-pixel-a-cell image, rows top-down.
render::Image draw_cells(CanvasRenderer& renderer) {
  const int w = renderer.width_cells(), h = renderer.height_cells();
  Framebuffer target(w, h, TexelFormat::kRGBA32F);
  target.bind();
  renderer.draw(one_pixel_per_cell(w, h), w, h);
  const std::vector<float> rgba = target.read_rgba_float();
  render::Image image;
  image.width = w;
  image.height = h;
  image.rgb.resize(3 * static_cast<std::size_t>(w) * h);
  for (int y = 0; y < h; ++y) {
    for (int x = 0; x < w; ++x) {
      for (int c = 0; c < 3; ++c) {
        image.pixel(x, y)[c] = rgba[static_cast<std::size_t>(4 * ((h - 1 - y) * w + x) + c)];
      }
    }
  }
  return image;
}

double report(const char* name, const render::Image& gpu, const render::Image& cpu) {
  const auto [worst, mean, worst_x, worst_y] = test::compare_images(gpu, cpu);
  std::cout << "[ " << name << " ] GPU vs CPU: max " << worst * 255 << "/255 at (" << worst_x << ","
            << worst_y << "), mean " << mean * 255 << "/255\n";
  return worst;
}

// SPREAD_MAX_RADIUS and the map's full scale come from the C++ (render::kSubsurfaceMaxRadius,
// render::kSubsurfaceMapFullScaleCells), never by hand in the GLSL.
TEST(SubsurfaceGlsl, ConstantsAreInjectedFromTheCpp) {
  for (const char* name : {"subsurface_spread_frag.glsl", "subsurface_canvas_lib.glsl"}) {
    std::ifstream file(std::filesystem::path(IMPASTO_SOURCE_DIR) / "render/gl/shaders" / name);
    std::stringstream text;
    text << file.rdbuf();
    ASSERT_FALSE(text.str().empty()) << name;
    EXPECT_EQ(text.str().find("#define SPREAD_MAX_RADIUS"), std::string::npos) << name;
    EXPECT_EQ(text.str().find("#define SPREAD_MAP_FULL_SCALE"), std::string::npos) << name;
  }
  EXPECT_NE(GpuSubsurfaceSpread::canvas_glsl().find(
                "#define SPREAD_MAP_FULL_SCALE " +
                std::to_string(render::kSubsurfaceMapFullScaleCells) + "\n"),
            std::string::npos);
}

// Half a level of 255 in the display encoding, as the ghs surface's own test.
TEST(SubsurfaceSpreadGpu, GlazeOverAnEdgeMatchesTheCpuWithinHalfALevelOf255) {
  auto context = create_headless_context();
  paintcore::Canvas canvas = make_edge_canvas();
  glaze(canvas, 30, 12, kWidth, kHeight, 0.3f);  // off the right and bottom sides
  const render::RenderSettings settings = ghs_settings();
  render::SubsurfaceMap map;
  const render::Image expected = cpu_with_spread(canvas, settings, &map);
  ASSERT_GT(map.cells.size(), 1000u);
  const render::Image actual = render_painting_gpu(canvas, test::kWhiteBlueRedBlack, settings);
  const double worst = report("glaze over an edge", actual, expected);
  RecordProperty("max_difference_255", std::to_string(worst * 255));
  EXPECT_LE(worst, 0.5 / 255.0);

  // Linear, where the spread is added: the same.
  render::RenderSettings linear = settings;
  linear.display = render::DisplayEncoding::linear_srgb;
  EXPECT_LE(report("linear", render_painting_gpu(canvas, test::kWhiteBlueRedBlack, linear),
                   cpu_with_spread(canvas, linear)),
            0.5 / 255.0);

  // Not vacuous: without the spread the edge under the glaze is sharper by far.
  render::RenderSettings off = settings;
  off.surface.subsurface = false;
  const render::Image sharp = render_painting_gpu(canvas, test::kWhiteBlueRedBlack, off);
  EXPECT_GT(test::max_difference(sharp, actual), 10.0 / 255.0);
}

// The window's path: one renderer, tiles changed after its first draw (a glaze laid, then
// wiped off one tile), each draw equal to the CPU's render of the canvas as it is then.
TEST(SubsurfaceSpreadGpu, TilesChangedAfterTheFirstDrawFollowTheCpu) {
  auto context = create_headless_context();
  paintcore::Canvas canvas = make_edge_canvas();
  render::RenderSettings settings = ghs_settings();
  settings.display = render::DisplayEncoding::linear_srgb;
  CanvasRenderer gpu(kWidth, kHeight, settings,
                     render::SpectralPalette(settings, test::kWhiteBlueRedBlack));
  gpu.upload_all(canvas);
  EXPECT_EQ(gpu.subsurface_cells(), 0);
  EXPECT_LE(report("no glaze", draw_cells(gpu), cpu_with_spread(canvas, settings)), 0.5 / 255.0);

  glaze(canvas, 40, 20, 60, 40, 0.3f);  // tile 0 only
  const int first[] = {0};
  gpu.upload_tiles(canvas, first);
  EXPECT_GT(gpu.subsurface_cells(), 0);
  EXPECT_LE(report("glaze laid", draw_cells(gpu), cpu_with_spread(canvas, settings)), 0.5 / 255.0);

  glaze(canvas, 62, 20, 80, 40, 0.3f);  // across into tile 1
  glaze(canvas, 40, 20, 60, 40, 0.0f);  // and tile 0's wiped off
  const int both[] = {0, 1};
  gpu.upload_tiles(canvas, both);
  EXPECT_LE(report("glaze moved", draw_cells(gpu), cpu_with_spread(canvas, settings)), 0.5 / 255.0);

  // The light moved: the body's light changes everywhere.
  settings.light_azimuth_deg = 120.0;
  gpu.set_shading(settings);
  EXPECT_LE(report("light moved", draw_cells(gpu), cpu_with_spread(canvas, settings)), 0.5 / 255.0);
}

// Nothing that spreads: nothing is mapped and the image is the one without the spread, bit for
// bit.
TEST(SubsurfaceSpreadGpu, ThinPaintMapsNothingAndChangesNothing) {
  auto context = create_headless_context();
  paintcore::Canvas canvas = make_edge_canvas();
  glaze(canvas, 30, 12, kWidth, kHeight, 0.005f);  // far thinner than a quarter cell
  render::RenderSettings settings = ghs_settings();
  CanvasRenderer gpu(kWidth, kHeight, settings,
                     render::SpectralPalette(settings, test::kWhiteBlueRedBlack));
  gpu.upload_all(canvas);
  EXPECT_EQ(gpu.subsurface_cells(), 0);
  const render::Image with = draw_cells(gpu);
  settings.surface.subsurface = false;
  gpu.set_settings(settings, render::SpectralPalette(settings, test::kWhiteBlueRedBlack));
  gpu.upload_all(canvas);
  EXPECT_EQ(draw_cells(gpu).rgb, with.rgb);
}

// The debug view: each mapped cell shows its spread lengths (the CPU's subsurface_map_image),
// every other cell the painting at a quarter of its light.
TEST(SubsurfaceSpreadGpu, MapViewShowsTheCpuMapOverThePaintingDimmed) {
  auto context = create_headless_context();
  paintcore::Canvas canvas = make_edge_canvas();
  glaze(canvas, 30, 12, kWidth, kHeight, 0.3f);
  render::RenderSettings settings = ghs_settings();
  settings.display = render::DisplayEncoding::linear_srgb;
  const render::SpectralPalette palette(settings, test::kWhiteBlueRedBlack);
  const render::SubsurfaceMap map = render::subsurface_map(canvas, palette, settings);
  const render::Image map_image = render::subsurface_map_image(map);
  CanvasRenderer gpu(kWidth, kHeight, settings, palette);
  gpu.upload_all(canvas);
  const render::Image painting = draw_cells(gpu);
  GpuViewOptions options;
  options.subsurface_map = true;
  gpu.set_view_options(options);
  const render::Image shown = draw_cells(gpu);
  std::vector<bool> mapped(static_cast<std::size_t>(kWidth) * kHeight, false);
  for (const render::SpreadingCell& cell : map.cells) {
    mapped[static_cast<std::size_t>(cell.y) * kWidth + cell.x] = true;
  }
  double worst = 0.0;
  for (int y = 0; y < kHeight; ++y) {
    for (int x = 0; x < kWidth; ++x) {
      const bool m = mapped[static_cast<std::size_t>(y) * kWidth + x];
      for (int c = 0; c < 3; ++c) {
        const double expected = m ? map_image.pixel(x, y)[c] : 0.25 * painting.pixel(x, y)[c];
        worst = std::max(worst, std::abs(shown.pixel(x, y)[c] - expected));
      }
    }
  }
  EXPECT_LE(worst, 1e-4);
}

}  // namespace
}  // namespace impasto::render_gl
