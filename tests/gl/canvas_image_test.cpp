// The GPU canvas pass against the CPU reference renderer (render::TileRenderer), pixel by
// pixel: wet paint of several mixes and thicknesses over dry layers, untouched tiles, edge
// tiles, under several lights, node counts and display encodings.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <string>
#include <vector>

#include "gl_test_slots.hpp"
#include "image_difference.hpp"
#include "impasto/paintcore/canvas.hpp"
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

// A 150x100-cell canvas (3x2 tiles, the right and bottom ones partial): blobs of wet paint
// with smoothly varying thickness and mix, a dry layer under part of it, one tile untouched.
paintcore::Canvas make_test_canvas() {
  paintcore::Canvas canvas({150, 100, 300.0, 7});
  const int slots = static_cast<int>(test::kWhiteBlueRedYellowBlack.size());
  for (int index : {0, 1, 4}) {  // tiles 2, 3 and 5 stay untouched
    paintcore::Tile& tile = canvas.ensure_tile(index, slots);
    const int x0 = (index % canvas.tiles_x()) * kTileSize;
    const int y0 = (index / canvas.tiles_x()) * kTileSize;
    for (int y = 0; y < kTileSize; ++y) {
      for (int x = 0; x < kTileSize; ++x) {
        const int gx = x0 + x, gy = y0 + y;
        if (gx >= canvas.width_cells() || gy >= canvas.height_cells()) continue;
        const int cell = y * kTileSize + x;
        const double r = std::hypot(gx - 60.0, gy - 45.0);
        const float volume = r < 50.0 ? static_cast<float>(0.3 * (1.0 - r / 50.0)) : 0.0f;
        tile.wet_volume_mm[cell] = volume;
        if (volume <= 0.0f) continue;
        // Shares that sum to one, varying across the blob.
        const float a = 0.5f + 0.5f * static_cast<float>(std::sin(gx * 0.11));
        const float b = 0.5f + 0.5f * static_cast<float>(std::cos(gy * 0.07));
        const float shares[] = {0.4f * a, 0.3f * b, 0.2f * (1 - a), 0.1f * (1 - b), 0.02f};
        float total = 0.0f;
        for (float s : shares) total += s;
        for (int s = 0; s < slots; ++s) tile.pigment(s)[cell] = volume * shares[s] / total;
      }
    }
  }
  // One dry layer in tiles 0 and 4: a thin glaze of red and a thick stripe of blue.
  paintcore::DryLayer layer;
  for (int index : {0, 4}) {
    paintcore::DryTile dry;
    dry.tile_index = index;
    dry.volume_mm.assign(kTileCells, 0.0f);
    dry.slots = {1, 2};
    dry.pigment_mm.assign(2 * kTileCells, 0.0f);
    for (int cell = 0; cell < kTileCells; ++cell) {
      const int x = cell % kTileSize;
      const float volume = x < 20 ? 0.2f : 0.01f;
      dry.volume_mm[cell] = volume;
      dry.pigment_mm[cell] = x < 20 ? volume * 0.5f : 0.0f;               // blue
      dry.pigment_mm[kTileCells + cell] = x < 20 ? 0.0f : volume * 0.3f;  // red glaze
    }
    layer.tiles.push_back(std::move(dry));
  }
  canvas.dry_layers().push_back(std::move(layer));
  for (int index : {0, 4}) {
    paintcore::Tile& tile = canvas.ensure_tile(index, slots);
    for (int cell = 0; cell < kTileCells; ++cell) {
      tile.dry_height_mm[cell] = (cell % kTileSize) < 20 ? 0.2f : 0.01f;
    }
  }
  return canvas;
}

struct RenderCase {
  std::string name;
  std::string light;
  int wavelengths;
  render::DisplayEncoding display;
  bool saunderson;
  render::ReflectanceStorage storage;
};

// Test names show the case's name rather than its bytes.
void PrintTo(const RenderCase& c, std::ostream* os) {
  *os << c.name;
}

class CanvasImage : public ::testing::TestWithParam<RenderCase> {};

TEST_P(CanvasImage, GpuMatchesCpuWithinTwoLevelsOf255) {
  const RenderCase& c = GetParam();
  render::RenderSettings settings;
  settings.light = c.light;
  settings.wavelengths = c.wavelengths;
  settings.display = c.display;
  settings.saunderson = c.saunderson;
  settings.storage = c.storage;
  const paintcore::Canvas canvas = make_test_canvas();

  render::TileRenderer cpu(settings, test::kWhiteBlueRedYellowBlack);
  cpu.render_all(canvas);
  const render::Image expected = cpu.image();
  const render::Image actual =
      render_painting_gpu(canvas, test::kWhiteBlueRedYellowBlack, settings);

  ASSERT_EQ(actual.width, expected.width);
  ASSERT_EQ(actual.height, expected.height);
  const auto [max_difference, mean, worst_x, worst_y] = test::compare_images(actual, expected);
  std::cout << "[ " << c.name << " ] GPU vs CPU: max " << max_difference * 255 << "/255 at ("
            << worst_x << "," << worst_y << "), mean " << mean * 255 << "/255\n";
  RecordProperty("max_difference_255", std::to_string(max_difference * 255));
  RecordProperty("mean_difference_255", std::to_string(mean * 255));
  EXPECT_LE(max_difference, 2.0 / 255.0) << "worst pixel (" << worst_x << "," << worst_y << ")";
  // The picture is not trivially flat: paint, glaze and bare ground all differ.
  EXPECT_GT(std::abs(expected.pixel(60, 45)[0] - expected.pixel(140, 90)[0]) +
                std::abs(expected.pixel(60, 45)[2] - expected.pixel(140, 90)[2]),
            0.05f);
}

INSTANTIATE_TEST_SUITE_P(
    Lights, CanvasImage,
    ::testing::Values(RenderCase{"D65_8_srgb", "D65", 8, render::DisplayEncoding::srgb, false,
                                 render::ReflectanceStorage::float32},
                      RenderCase{"A_4_rec709_saunderson", "A", 4, render::DisplayEncoding::rec709,
                                 true, render::ReflectanceStorage::float32},
                      RenderCase{"F11_16_p3_half", "F11", 16, render::DisplayEncoding::display_p3,
                                 false, render::ReflectanceStorage::float16},
                      RenderCase{"blackbody_3_linear", "blackbody:3200", 3,
                                 render::DisplayEncoding::linear_srgb, false,
                                 render::ReflectanceStorage::float32}),
    [](const ::testing::TestParamInfo<RenderCase>& info) { return info.param.name; });

render::Image read_back(const Framebuffer& target) {
  const auto rgba = target.read_rgba_float();
  render::Image image{target.width(), target.height(), {}};
  image.rgb.resize(static_cast<size_t>(3 * target.width() * target.height()));
  for (int y = 0; y < target.height(); ++y) {
    for (int x = 0; x < target.width(); ++x) {
      const float* p =
          &rgba[static_cast<size_t>(((target.height() - 1 - y) * target.width() + x) * 4)];
      std::copy_n(p, 3, image.pixel(x, y));
    }
  }
  return image;
}

// The window's path: a real stroke on a Painting, then only the dirty tiles uploaded. The
// GPU image must follow the CPU reference after every change, and tiles the stroke did not
// touch must not be re-sent.
TEST(CanvasTiles, DirtyTileUploadsFollowStrokesUndoAndDry) {
  paintcore::Painting painting({200, 140, 150.0, 3}, 1);
  painting.set_brush({"round", 5.0, 0.5});
  painting.load_brush({{"Blue Red Shade", 2.0}, {"White", 1.0}}, 60.0);
  render::RenderSettings settings;
  auto context = create_headless_context();
  const paintcore::Canvas& canvas = painting.canvas();
  const paintcore::Painting::ChangeSubscriber changes = painting.subscribe_changes();
  (void)painting.take_changes(changes);

  std::unique_ptr<CanvasRenderer> gpu;
  Framebuffer target(canvas.width_cells(), canvas.height_cells(), TexelFormat::kRGBA32F);
  auto check = [&](const char* step, bool full) {
    const std::vector<int> dirty = paintcore::tile_indices(painting.take_changes(changes));
    render::SpectralPalette palette(settings, painting.pigment_slots());
    if (full || !gpu) {
      gpu = std::make_unique<CanvasRenderer>(canvas.width_cells(), canvas.height_cells(), settings,
                                             palette);
      gpu->upload_all(canvas);
    } else {
      EXPECT_LT(dirty.size(), static_cast<size_t>(canvas.tile_count())) << step;
      gpu->upload_tiles(canvas, dirty);
    }
    target.bind();
    gpu->draw(one_pixel_per_cell(canvas.width_cells(), canvas.height_cells()), canvas.width_cells(),
              canvas.height_cells());
    render::TileRenderer cpu(settings, palette);
    cpu.render_all(canvas);
    const double worst = max_difference(read_back(target), cpu.image());
    std::cout << "[ " << step << " ] max " << worst * 255 << "/255\n";
    EXPECT_LE(worst, 2.0 / 255.0) << step;
  };

  painting.begin_stroke();
  for (int i = 0; i <= 40; ++i) {
    paintcore::PenSample sample;
    sample.time_s = 0.01 * i;
    sample.x_mm = 4.0 + 0.5 * i;
    sample.y_mm = 8.0 + 3.0 * std::sin(0.2 * i);
    sample.pressure = 0.7f;
    sample.buttons = paintcore::kPenTip | paintcore::kPenInRange;
    painting.stroke_to(sample);
  }
  painting.end_stroke();
  check("stroke", true);  // first pigments: the palette is new
  painting.dry(0.5);
  check("dry half", false);
  painting.undo();
  check("undo dry", false);
}

TEST(CanvasImageErrors, FullSpectrumIsRefusedWithAClearMessage) {
  render::RenderSettings settings;
  settings.wavelengths = 0;
  const paintcore::Canvas canvas({8, 8, 100.0, 0});
  try {
    render_painting_gpu(canvas, test::kWhiteBlueRedYellowBlack, settings);
    FAIL() << "full-spectrum rendering was accepted on the GPU";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("nodes"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace impasto::render_gl
