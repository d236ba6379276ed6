// The window's view between cells (GpuViewOptions::smooth_zoom): zoomed in, colour, normal and
// relief light interpolated between cell centres, so a pixel on a cell centre shows that cell
// and neighbouring pixels change gently; zoomed out, each pixel the average of the shaded
// cells under it, which is the CPU reference image box-filtered.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <memory>
#include <string>
#include <vector>

#include "gl_test_slots.hpp"
#include "impasto/paintcore/canvas.hpp"
#include "impasto/render/box_filter.hpp"
#include "impasto/render/tile_renderer.hpp"
#include "impasto/render_gl/canvas_renderer.hpp"
#include "impasto/render_gl/gl_context.hpp"
#include "impasto/render_gl/render_painting_gpu.hpp"

namespace impasto::render_gl {
namespace {

using paintcore::kTileSize;

// 96 x 64 cells at 150 dpi: a dome of paint whose mix changes every few cells.
paintcore::Canvas dome_canvas() {
  paintcore::Canvas canvas({96, 64, 150.0, 2});
  for (int index : {0, 1}) {
    paintcore::Tile& tile = canvas.ensure_tile(index, 3);
    for (int y = 0; y < kTileSize; ++y) {
      for (int x = 0; x < kTileSize; ++x) {
        const int gx = (index % canvas.tiles_x()) * kTileSize + x;
        const double r = std::hypot(gx - 48.0, y - 32.0);
        const float v = r < 28.0 ? static_cast<float>(1.2 * (1.0 - r / 28.0)) : 0.0f;
        const int cell = y * kTileSize + x;
        tile.wet_volume_mm[cell] = v;
        tile.pigment(0)[cell] = 0.5f * v;
        tile.pigment((gx / 5 + y / 5) % 2 == 0 ? 1 : 2)[cell] = 0.3f * v;
      }
    }
  }
  return canvas;
}

render::RenderSettings linear_settings() {
  render::RenderSettings settings;
  settings.wavelengths = 4;
  settings.display = render::DisplayEncoding::linear_srgb;
  settings.light_elevation_deg = 35.0;
  return settings;
}

// The view at `pixels_per_cell` over the whole canvas, rows top-down, RGB.
std::vector<float> draw(CanvasRenderer& renderer, double pixels_per_cell, int w, int h) {
  const CanvasView centred{0.5 * renderer.width_cells(), 0.5 * renderer.height_cells(),
                           pixels_per_cell, 0.0};
  return draw_to_image(renderer, centred, w, h).rgb;
}

// The dome canvas rendered on the CPU (the reference) and uploaded to a GPU renderer, for the
// zoomed-out views.
class ZoomedOut : public ::testing::Test {
 protected:
  std::unique_ptr<GlContext> context = create_headless_context();
  const paintcore::Canvas canvas = dome_canvas();
  const render::RenderSettings settings = linear_settings();
  const int W = canvas.width_cells(), H = canvas.height_cells();
  const render::Image reference = cpu_image();
  CanvasRenderer renderer{W, H, settings, render::SpectralPalette(settings, test::kWhiteRedBlue)};

  void SetUp() override { renderer.upload_all(canvas); }

 private:
  render::Image cpu_image() const {
    render::TileRenderer cpu(settings, test::kWhiteRedBlue);
    cpu.render_all(canvas);
    return cpu.image();
  }
};

TEST(SmoothZoom, ZoomedInPixelsBlendNeighbourCellsGently) {
  auto context = create_headless_context();
  const paintcore::Canvas canvas = dome_canvas();
  const render::RenderSettings settings = linear_settings();
  const int W = canvas.width_cells(), H = canvas.height_cells(), P = 5;
  GpuViewOptions smooth, blocks;
  blocks.smooth_zoom = false;
  CanvasRenderer renderer(W, H, settings, render::SpectralPalette(settings, test::kWhiteRedBlue),
                          smooth);
  renderer.upload_all(canvas);
  const std::vector<float> one = draw(renderer, 1.0, W, H);
  const std::vector<float> zoomed = draw(renderer, P, W * P, H * P);
  renderer.set_view_options(blocks);
  const std::vector<float> blocky = draw(renderer, P, W * P, H * P);

  // Pixels on cell centres (P odd: pixel P / 2 of a cell has its centre there) show their cell.
  double centre_error = 0.0;
  for (int cy = 2; cy < H - 2; ++cy) {
    for (int cx = 2; cx < W - 2; ++cx) {
      const int px = cx * P + P / 2, py = cy * P + P / 2;
      for (int c = 0; c < 3; ++c) {
        centre_error =
            std::max(centre_error,
                     std::abs(double(zoomed[static_cast<std::size_t>(3 * (py * W * P + px) + c)]) -
                              one[static_cast<std::size_t>(3 * (cy * W + cx) + c)]));
      }
    }
  }
  double largest_step_blocks = 0.0, largest_step_smooth = 0.0;
  for (int y = 0; y < H * P; ++y) {
    for (int x = 0; x + 1 < W * P; ++x) {
      for (int c = 0; c < 3; ++c) {
        const auto i = static_cast<std::size_t>(3 * (y * W * P + x) + c);
        largest_step_blocks =
            std::max(largest_step_blocks, double(std::abs(blocky[i + 3] - blocky[i])));
        largest_step_smooth =
            std::max(largest_step_smooth, double(std::abs(zoomed[i + 3] - zoomed[i])));
      }
    }
  }
  std::cout << "[ zoom in ] centre error " << centre_error << "; largest step between pixels "
            << largest_step_smooth << " (cell blocks: " << largest_step_blocks << ")\n";
  EXPECT_LT(centre_error, 1e-4);
  EXPECT_LT(largest_step_smooth, 0.5 * largest_step_blocks);
}

TEST_F(ZoomedOut, PixelsAreTheCpuImageBoxFiltered) {
  const std::vector<float> half = draw(renderer, 0.5, W / 2, H / 2);
  const render::Image box = render::box_filtered(reference, 2.0, W / 2, H / 2);
  double worst = 0.0, worst_nearest = 0.0;
  for (int y = 0; y < H / 2; ++y) {
    for (int x = 0; x < W / 2; ++x) {
      for (int c = 0; c < 3; ++c) {
        const float expected = box.pixel(x, y)[c];
        const float got = half[static_cast<std::size_t>(3 * (y * (W / 2) + x) + c)];
        worst = std::max(worst, double(std::abs(got - expected)));
        worst_nearest = std::max(
            worst_nearest, double(std::abs(reference.pixel(2 * x + 1, 2 * y + 1)[c] - expected)));
      }
    }
  }
  std::cout << "[ zoom out ] GPU vs CPU box filter: max " << worst * 255
            << "/255 (one cell a pixel: " << worst_nearest * 255 << "/255)\n";
  EXPECT_LE(worst, 2.0 / 255.0);
  EXPECT_GT(worst_nearest, 10.0 * worst);  // the test can tell averaging from picking a cell
}

// Between whole cells a pixel (the fit zoom of most canvases) each pixel averages the cells
// its footprint covers, each by its share: a pixel's centre alone would pick one cell and
// skip others, so the weave and furrows would beat against the pixels as moiré.
TEST_F(ZoomedOut, BetweenWholeCellsEveryCellCountsByItsShare) {
  for (const double cells_per_pixel : {1.25, 1.7, 2.5}) {
    const int w = static_cast<int>(W / cells_per_pixel), h = static_cast<int>(H / cells_per_pixel);
    const std::vector<float> view = draw(renderer, 1.0 / cells_per_pixel, w, h);
    const render::Image box = render::box_filtered(reference, cells_per_pixel, w, h);
    double worst = 0.0, worst_centre_cell = 0.0;
    for (int y = 0; y < h; ++y) {
      for (int x = 0; x < w; ++x) {
        // The cell under the pixel's centre, which a point sample would show.
        const int cx = static_cast<int>(0.5 * W + (x + 0.5 - 0.5 * w) * cells_per_pixel);
        const int cy = static_cast<int>(0.5 * H + (y + 0.5 - 0.5 * h) * cells_per_pixel);
        for (int c = 0; c < 3; ++c) {
          const float expected = box.pixel(x, y)[c];
          worst = std::max(
              worst,
              double(std::abs(view[static_cast<std::size_t>(3 * (y * w + x) + c)] - expected)));
          worst_centre_cell =
              std::max(worst_centre_cell, double(std::abs(reference.pixel(cx, cy)[c] - expected)));
        }
      }
    }
    std::cout << "[ " << cells_per_pixel << " cells a pixel ] GPU vs the box filter: max "
              << worst * 255 << "/255 (the centre's cell: " << worst_centre_cell * 255 << "/255)\n";
    EXPECT_LE(worst, 2.0 / 255.0) << cells_per_pixel;
    EXPECT_GT(worst_centre_cell, 5.0 * worst) << cells_per_pixel;  // it can tell them apart
  }
}

}  // namespace
}  // namespace impasto::render_gl
