// Cracks on the GPU (cracks_lib.glsl, CrackTexture) against the CPU reference renderer, pixel
// by pixel: grooves and pits of every shape over bare ground, wet paint and a dry glaze, with
// walls of the ground or of the dry stack; then cracks set on a painting and sent tile by tile.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <string>
#include <vector>

#include "gl_test_slots.hpp"
#include "image_difference.hpp"
#include "impasto/paintcore/painting.hpp"
#include "impasto/render/tile_renderer.hpp"
#include "impasto/render_gl/canvas_renderer.hpp"
#include "impasto/render_gl/framebuffer.hpp"
#include "impasto/render_gl/render_painting_gpu.hpp"

namespace impasto::render_gl {
namespace {

using test::max_difference;

using paintcore::kTileCells;
using paintcore::kTileSize;

void set_crack(paintcore::Canvas& canvas, int x, int y, paintcore::CrackRecord record) {
  const int index = (y / kTileSize) * canvas.tiles_x() + x / kTileSize;
  canvas.cracks()
      .ensure_tile(index)
      .cells[static_cast<std::size_t>((y % kTileSize) * kTileSize + x % kTileSize)] = record;
}

// 150 x 100 cells (3 x 2 tiles, edge tiles partial): wet red over tile 0's left, a dry black
// glaze over tiles 1 and 4, and a crack network of every shape, depth and width across it.
paintcore::Canvas cracked_canvas() {
  paintcore::Canvas canvas({150, 100, 254.0, 5});
  paintcore::Tile& tile = canvas.ensure_tile(0, 3);
  for (int cell = 0; cell < kTileCells; ++cell) {
    if (cell % kTileSize >= 40) continue;
    tile.wet_volume_mm[static_cast<std::size_t>(cell)] = 0.03f;
    tile.pigment(1)[cell] = 0.01f;
    tile.pigment(0)[cell] = 0.005f;
  }
  paintcore::DryLayer layer;
  for (int index : {1, 4}) {
    paintcore::DryTile dry;
    dry.tile_index = index;
    dry.volume_mm.assign(kTileCells, 0.01f);
    dry.slots = {2};
    dry.pigment_mm.assign(kTileCells, 0.0005f);
    layer.tiles.push_back(std::move(dry));
    canvas.ensure_tile(index, 3).dry_height_mm.fill(0.01f);
  }
  canvas.dry_layers().push_back(std::move(layer));
  for (int i = 0; i < 140; ++i) {
    const int x = 3 + i, y = 5 + (i * 13) % 90;
    const auto shape = static_cast<std::uint8_t>(i % paintcore::kCrackShapeCount);
    const float depth = 0.005f * static_cast<float>(1 + i % 37);
    const float half_width = 0.004f * static_cast<float>(1 + i % 11);
    const std::uint8_t walls = i % 3 == 0 ? 0 : paintcore::kCrackExposesGround;
    set_crack(canvas, x, y, {depth, half_width, shape, walls});
    set_crack(canvas, x, std::min(99, y + 1), {depth, half_width, shape, walls});
  }
  return canvas;
}

TEST(CrackCanvas, GpuMatchesCpuWithinTwoLevelsOf255) {
  const paintcore::Canvas canvas = cracked_canvas();
  render::RenderSettings settings;
  settings.saunderson = true;  // the blend comes before the surface correction on both
  render::TileRenderer cpu(settings, test::kWhiteRedBlack);
  cpu.render_all(canvas);
  const render::Image expected = cpu.image();
  const render::Image actual = render_painting_gpu(canvas, test::kWhiteRedBlack, settings);
  ASSERT_EQ(actual.rgb.size(), expected.rgb.size());
  const double worst = max_difference(actual, expected);
  std::cout << "[ cracks ] GPU vs CPU: max " << worst * 255 << "/255\n";
  EXPECT_LE(worst, 2.0 / 255.0);

  // The cracks show, on both paths: without them the same canvas renders otherwise.
  settings.cracks = false;
  const render::Image plain = render_painting_gpu(canvas, test::kWhiteRedBlack, settings);
  EXPECT_GT(max_difference(plain, actual), 20.0 / 255.0);
  render::TileRenderer cpu_plain(settings, test::kWhiteRedBlack);
  cpu_plain.render_all(canvas);
  EXPECT_LE(max_difference(plain, cpu_plain.image()), 2.0 / 255.0);
}

TEST(CrackCanvas, CracksSetOnAPaintingReachTheGpuTileByTile) {
  paintcore::Painting painting({200, 140, 254.0, 3}, 1);
  render::RenderSettings settings;
  const render::SpectralPalette palette(settings, test::kWhiteRedBlack);
  auto context = create_headless_context();
  const paintcore::Canvas& canvas = painting.canvas();
  CanvasRenderer gpu(canvas.width_cells(), canvas.height_cells(), settings, palette);
  gpu.upload_all(canvas);
  const paintcore::Painting::ChangeSubscriber changes = painting.subscribe_changes();
  (void)painting.take_changes(changes);  // the canvas as uploaded
  Framebuffer target(canvas.width_cells(), canvas.height_cells(), TexelFormat::kRGBA32F);
  const auto check = [&](const char* step) {
    const std::vector<int> dirty = paintcore::tile_indices(painting.take_changes(changes));
    EXPECT_LT(dirty.size(), static_cast<std::size_t>(canvas.tile_count())) << step;
    gpu.upload_tiles(canvas, dirty);
    target.bind();
    gpu.draw(one_pixel_per_cell(canvas.width_cells(), canvas.height_cells()), canvas.width_cells(),
             canvas.height_cells());
    const auto rgba = target.read_rgba_float();
    render::TileRenderer cpu(settings, palette);
    cpu.render_all(canvas);
    const render::Image expected = cpu.image();
    double worst = 0.0;
    for (int y = 0; y < target.height(); ++y) {
      for (int x = 0; x < target.width(); ++x) {
        const float* p =
            &rgba[static_cast<std::size_t>(((target.height() - 1 - y) * target.width() + x) * 4)];
        for (int ch = 0; ch < 3; ++ch) {
          worst = std::max(worst, std::abs(double(p[ch]) - expected.pixel(x, y)[ch]));
        }
      }
    }
    std::cout << "[ " << step << " ] max " << worst * 255 << "/255\n";
    EXPECT_LE(worst, 2.0 / 255.0) << step;
  };
  paintcore::CrackLayer cracks;
  for (int x = 10; x < 120; ++x) {
    cracks.ensure_tile(x / kTileSize).cells[static_cast<std::size_t>(30 * kTileSize + x % 64)] = {
        0.2f, 0.04f, 1, paintcore::kCrackExposesGround};
  }
  painting.set_cracks(std::move(cracks));
  check("cracks set");
  painting.set_cracks(paintcore::CrackLayer{});
  check("cracks removed");
}

}  // namespace
}  // namespace impasto::render_gl
