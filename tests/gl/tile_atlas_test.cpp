// The GPU keeps paint only for the tiles that hold some (render_gl::TileAtlas): a bare canvas
// takes no place, each painted tile one, and a renderer whose atlas grew tile by tile draws
// exactly what a fresh renderer of the finished canvas draws.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <vector>

#include "gl_test_slots.hpp"
#include "impasto/paintcore/canvas.hpp"
#include "impasto/render_gl/canvas_renderer.hpp"
#include "impasto/render_gl/framebuffer.hpp"
#include "impasto/render_gl/gl_context.hpp"

namespace impasto::render_gl {
// Named, not anonymous: the test program is built from several sources in one unit.
namespace tile_atlas_test {

using paintcore::kTileCells;
using paintcore::kTileSize;

const std::vector<std::string>& slots() {
  return test::kWhiteBlueRedYellowBlack;
}

render::SpectralPalette palette(const render::RenderSettings& settings) {
  return render::SpectralPalette(settings, slots());
}

// Wet paint over the whole tile, its thickness and mix different in every tile.
void paint_tile(paintcore::Canvas& canvas, int index) {
  const int slot_count = static_cast<int>(slots().size());
  paintcore::Tile& tile = canvas.ensure_tile(index, slot_count);
  for (int cell = 0; cell < kTileCells; ++cell) {
    const float volume = 0.02f + 0.01f * static_cast<float>((index * 7 + cell / kTileSize) % 13);
    tile.wet_volume_mm[cell] = volume;
    const int main_slot = index % slot_count;
    tile.pigment(main_slot)[cell] = 0.7f * volume;
    tile.pigment((main_slot + 1) % slot_count)[cell] = 0.3f * volume;
  }
}

// One dry layer with paint in `index`, a tile with no wet paint.
void dry_tile(paintcore::Canvas& canvas, int index) {
  paintcore::DryTile dry;
  dry.tile_index = index;
  dry.volume_mm.assign(kTileCells, 0.05f);
  dry.slots = {2};
  dry.pigment_mm.assign(kTileCells, 0.02f);
  paintcore::DryLayer layer;
  layer.tiles.push_back(std::move(dry));
  canvas.dry_layers().push_back(std::move(layer));
}

std::vector<std::uint8_t> draw(CanvasRenderer& renderer) {
  const int w = renderer.width_cells(), h = renderer.height_cells();
  Framebuffer target(w, h, TexelFormat::kRGBA8);
  target.bind();
  renderer.draw(CanvasView{w / 2.0, h / 2.0, 1.0, 0.0}, w, h);
  return target.read_rgba8();
}

TEST(TileAtlas, BareTilesTakeNoGpuMemory) {
  auto context = create_headless_context();
  paintcore::Canvas canvas({640, 384, 300.0, 7});  // 10 x 6 tiles
  render::RenderSettings settings;
  CanvasRenderer renderer(canvas.width_cells(), canvas.height_cells(), settings, palette(settings));
  renderer.upload_all(canvas);
  EXPECT_EQ(renderer.tiles_on_gpu(), 0);
  EXPECT_EQ(renderer.tile_data_bytes(), 60u * sizeof(float)) << "the table of places alone";

  paint_tile(canvas, 3);
  paint_tile(canvas, 17);
  dry_tile(canvas, 42);
  renderer.upload_tiles(canvas, std::vector<int>{3, 17, 42, 43});
  EXPECT_EQ(renderer.tiles_on_gpu(), 3) << "wet paint and a dry layer take a place";
  EXPECT_GT(renderer.tile_data_bytes(), 3u * kTileCells * 16u);
}

TEST(TileAtlas, GrowingKeepsWhatEveryPlaceHolds) {
  auto context = create_headless_context();
  // 9 x 8 tiles: the atlas (64 places a row) grows from one row to two at the 65th.
  paintcore::Canvas canvas({576, 512, 300.0, 7});
  render::RenderSettings settings;
  settings.wavelengths = 8;
  CanvasRenderer renderer(canvas.width_cells(), canvas.height_cells(), settings, palette(settings));
  renderer.upload_all(canvas);
  // Tiles painted one at a time in an order unlike their indices, each uploaded as it is made.
  int placed = 0;
  for (int step = 0; step < canvas.tile_count(); ++step) {
    const int index = (step * 31) % canvas.tile_count();  // 31 and 72 share no factor
    if (index % 9 == 4) {
      dry_tile(canvas, index);
    } else {
      paint_tile(canvas, index);
    }
    renderer.upload_tiles(canvas, std::vector<int>{index});
    EXPECT_EQ(renderer.tiles_on_gpu(), ++placed);
    if (placed == 64 || placed == canvas.tile_count()) {
      CanvasRenderer fresh(canvas.width_cells(), canvas.height_cells(), settings,
                           palette(settings));
      fresh.upload_all(canvas);
      EXPECT_EQ(draw(renderer), draw(fresh)) << "after " << placed << " tiles";
    }
  }
}

}  // namespace tile_atlas_test
}  // namespace impasto::render_gl
