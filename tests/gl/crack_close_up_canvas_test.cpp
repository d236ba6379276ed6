// The close-up of cracks in the canvas pass (crack_close_up_canvas_lib.glsl), as the window
// shows it when zoomed in, against the CPU's render_painting_close_up pixel by pixel; and the
// switch between the far view and the close-up by zoom.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <string>
#include <vector>

#include "../common/straight_stroke.hpp"

#include "impasto/paintcore/painting.hpp"
#include "impasto/render/crack_close_up.hpp"
#include "impasto/render_gl/canvas_renderer.hpp"
#include "impasto/render_gl/framebuffer.hpp"
#include "impasto/render_gl/gl_context.hpp"
#include "impasto/render_gl/render_painting_gpu.hpp"

namespace impasto::render_gl {
namespace {

using paintcore::kTileSize;

// 40 x 30 cells of 0.1 mm on a woven canvas: two strokes of red and white, the first dried,
// then cracks of every shape: grooves running along x and along y (runs of cells), pits,
// through the film to the ground or into the dry layer.
paintcore::Painting cracked_painting() {
  paintcore::Painting painting({40, 30, 254.0, 3}, 1);
  painting.set_brush({"round", 3.0, 0.5});
  for (int row = 0; row < 2; ++row) {
    painting.load_brush({{row == 0 ? "Red" : "White", 1.0}}, 40.0);
    impasto::test::paint_straight_stroke(painting, {0.3, 0.2, 0.8 + 1.2 * row, 16, 0.9f});
    if (row == 0) painting.dry(1.0);
  }
  paintcore::CrackLayer cracks;
  auto set = [&](int x, int y, paintcore::CrackRecord record) {
    cracks.ensure_tile((y / kTileSize) * painting.canvas().tiles_x() + x / kTileSize)
        .cells[static_cast<std::size_t>((y % kTileSize) * kTileSize + x % kTileSize)] = record;
  };
  for (int shape = 0; shape < paintcore::kCrackShapeCount; ++shape) {
    const std::uint8_t walls = shape % 2 == 0 ? paintcore::kCrackExposesGround : 0;
    const float depth = 0.02f + 0.03f * static_cast<float>(shape);
    const float half_width = shape < 3 ? 0.02f + 0.005f * static_cast<float>(shape) : 0.04f;
    const auto code = static_cast<std::uint8_t>(shape);
    if (shape < 3) {
      for (int k = 0; k < 4; ++k) set(2 + k, 3 + 4 * shape, {depth, half_width, code, walls});
      for (int k = 0; k < 4; ++k) set(10 + 3 * shape, 2 + k, {depth, half_width, code, walls});
    } else {
      set(4 + 5 * (shape - 3), 20, {depth, half_width, code, walls});
      set(5 + 5 * (shape - 3), 24, {2.0f * depth, 0.6f * half_width, code, walls});
    }
  }
  painting.set_cracks(std::move(cracks));
  return painting;
}

render::RenderSettings settings_for_test() {
  render::RenderSettings settings;
  settings.threads = 1;
  settings.light_elevation_deg = 50.0;  // walls lit on one side, shadowed on the other
  return settings;
}

// The GPU close-up against the CPU's, in linear sRGB. Both shade the same points with the
// same formulas; the GPU in float with 40 bisection steps, the CPU in double with 60. Measured
// (llvmpipe): largest difference 1.7e-6, mean 5.9e-8; allowed 1e-4 and 1e-6.
TEST(CrackCloseUpCanvas, GpuCloseUpMatchesTheCpu) {
  const paintcore::Painting painting = cracked_painting();
  const render::RenderSettings settings = settings_for_test();
  const render::CellRegion region{1, 1, 24, 26};
  const int P = 8;
  const render::Image cpu = render::render_painting_close_up(painting, settings, region, P);
  const render::Image gpu = render_painting_close_up_gpu(painting, settings, region, P);
  ASSERT_EQ(gpu.width, cpu.width);
  ASSERT_EQ(gpu.height, cpu.height);
  double worst = 0.0, sum = 0.0;
  int inside = 0;
  for (std::size_t i = 0; i < cpu.rgb.size(); ++i) {
    const double d = std::abs(static_cast<double>(gpu.rgb[i]) - cpu.rgb[i]);
    worst = std::max(worst, d);
    sum += d;
  }
  // The close-up shows: pixels over openings differ from their cell's far-view colour.
  const render::Image far = render_painting_gpu(painting.canvas(), painting.pigment_slots(), [&] {
    render::RenderSettings s = settings;
    s.display = render::DisplayEncoding::linear_srgb;
    return s;
  }());
  for (int y = 0; y < gpu.height; ++y) {
    for (int x = 0; x < gpu.width; ++x) {
      const float* cell = far.pixel(region.x + x / P, region.y + y / P);
      if (std::abs(gpu.pixel(x, y)[0] - cell[0]) > 1e-3f) ++inside;
    }
  }
  const double mean = sum / static_cast<double>(cpu.rgb.size());
  std::cout << "[ close-up ] GPU vs CPU: max " << worst << ", mean " << mean << "; " << inside
            << " pixels differ from the far view\n";
  EXPECT_LE(worst, 1e-4);
  EXPECT_LE(mean, 1e-6);
  EXPECT_GT(inside, 500);
}

// Below the zoom at which the close-up starts, every pixel is its cell's far-view colour (the
// same as one pixel per cell); from it on, pixels over openings change and only they.
TEST(CrackCloseUpCanvas, ZoomSwitchesBetweenFarViewAndCloseUp) {
  const paintcore::Painting painting = cracked_painting();
  render::RenderSettings settings = settings_for_test();
  settings.display = render::DisplayEncoding::linear_srgb;
  auto context = create_headless_context(HeadlessBackend::kAuto);
  const paintcore::Canvas& canvas = painting.canvas();
  const int W = canvas.width_cells(), H = canvas.height_cells();
  GpuViewOptions options;
  options.crack_close_up_min_pixels = 6.0f;
  options.smooth_zoom = false;  // each pixel its cell's colour, to compare with the far view
  CanvasRenderer renderer(W, H, settings,
                          render::SpectralPalette(settings, painting.pigment_slots()), options);
  renderer.upload_all(canvas);
  auto draw = [&](int P) {
    Framebuffer target(W * P, H * P, TexelFormat::kRGBA32F);
    target.bind();
    renderer.draw({0.5 * W, 0.5 * H, static_cast<double>(P), 0.0}, W * P, H * P);
    std::vector<float> rgba = target.read_rgba_float();
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    return rgba;
  };
  const std::vector<float> one = draw(1);
  // The far view's colour of the cell under pixel (px, py) of a view at P pixels per cell
  // (GL rows bottom-up in both).
  auto cell_of = [&](int P, int px, int py) {
    return &one[4 * (static_cast<std::size_t>(py / P) * W + static_cast<std::size_t>(px / P))];
  };
  for (int P : {3, 5}) {
    const std::vector<float> zoomed = draw(P);
    for (int py = 0; py < H * P; ++py) {
      for (int px = 0; px < W * P; ++px) {
        const float* far = cell_of(P, px, py);
        const float* pixel = &zoomed[4 * (static_cast<std::size_t>(py) * W * P + px)];
        for (int c = 0; c < 3; ++c) ASSERT_EQ(pixel[c], far[c]) << P << ": " << px << "," << py;
      }
    }
  }
  const int P = 6;
  const std::vector<float> zoomed = draw(P);
  int changed = 0;
  for (int py = 0; py < H * P; ++py) {
    for (int px = 0; px < W * P; ++px) {
      const float* pixel = &zoomed[4 * (static_cast<std::size_t>(py) * W * P + px)];
      const float* far = cell_of(P, px, py);
      if (pixel[0] == far[0] && pixel[1] == far[1] && pixel[2] == far[2]) continue;
      ++changed;
      // Only cracked cells change.
      const int cx = px / P, cy = H - 1 - py / P;
      const paintcore::CrackTile* tile =
          canvas.cracks().tile((cy / kTileSize) * canvas.tiles_x() + cx / kTileSize);
      ASSERT_NE(tile, nullptr);
      ASSERT_TRUE(
          tile->cells[static_cast<std::size_t>((cy % kTileSize) * kTileSize + cx % kTileSize)]
              .has_crack())
          << cx << "," << cy;
    }
  }
  EXPECT_GT(changed, 100);
}

// A painting without cracks: the GPU close-up is its one-pixel-per-cell render magnified.
TEST(CrackCloseUpCanvas, UncrackedPaintingIsItsRenderMagnified) {
  const paintcore::Painting painting({20, 16, 254.0, 5}, 1);
  render::RenderSettings settings = settings_for_test();
  settings.display = render::DisplayEncoding::linear_srgb;
  const render::Image one =
      render_painting_gpu(painting.canvas(), painting.pigment_slots(), settings);
  const int P = 7;
  const render::Image close = render_painting_close_up_gpu(painting, settings, {3, 2, 10, 9}, P);
  for (int y = 0; y < close.height; ++y) {
    for (int x = 0; x < close.width; ++x) {
      for (int c = 0; c < 3; ++c) {
        ASSERT_EQ(close.pixel(x, y)[c], one.pixel(3 + x / P, 2 + y / P)[c]) << x << "," << y;
      }
    }
  }
  EXPECT_THROW(render_painting_close_up_gpu(painting, settings, {15, 2, 10, 9}, P),
               std::runtime_error);
  EXPECT_THROW(render_painting_close_up_gpu(painting, settings, {3, 2, 10, 9}, 0),
               std::runtime_error);
}

}  // namespace
}  // namespace impasto::render_gl
