// The GPU canvas bakes a tile's dry stack again only when its dry layers change: a stroke
// over dried paint uploads the tile's wet paint and keeps the bake, while a drying, an undo
// of it or a hidden layer bakes again. Either way the image is exactly a fresh renderer's.
#include <gtest/gtest.h>

#include <cstdint>
#include <vector>

#include "impasto/paintcore/painting.hpp"
#include "impasto/render_gl/canvas_renderer.hpp"
#include "impasto/render_gl/framebuffer.hpp"
#include "impasto/render_gl/gl_context.hpp"

namespace impasto::render_gl {
// Named, not anonymous: the test program is built from several sources in one unit.
namespace dry_bake_cache_test {

constexpr int kWidth = 192, kHeight = 144;

void stroke(paintcore::Painting& painting, double x0_mm, double y0_mm, double x1_mm, double y1_mm) {
  painting.begin_stroke();
  for (int i = 0; i <= 12; ++i) {
    paintcore::PenSample s;
    s.x_mm = x0_mm + (x1_mm - x0_mm) * i / 12.0;
    s.y_mm = y0_mm + (y1_mm - y0_mm) * i / 12.0;
    s.pressure = 0.8f;
    s.buttons = paintcore::kPenTip;
    painting.stroke_to(s);
  }
  painting.end_stroke();
}

std::vector<std::uint8_t> draw(CanvasRenderer& renderer) {
  Framebuffer target(kWidth, kHeight, TexelFormat::kRGBA8);
  target.bind();
  renderer.draw(CanvasView{96.0, 72.0, 1.0, 0.0}, kWidth, kHeight);
  return target.read_rgba8();
}

// The image of a renderer that has seen every change tile by tile, against one that
// uploads the painting as it is now.
void expect_fresh_image(CanvasRenderer& renderer, const paintcore::Painting& painting,
                        const std::vector<bool>& hidden, const char* after) {
  CanvasRenderer fresh(kWidth, kHeight, renderer.settings(), renderer.palette());
  fresh.set_hidden_dry_layers(hidden);
  fresh.upload_all(painting.canvas());
  EXPECT_EQ(draw(renderer), draw(fresh)) << "after " << after;
}

TEST(DryBakeCache, StrokesKeepTheBakeAndDryingsRenewIt) {
  auto context = create_headless_context();
  paintcore::Painting painting({kWidth, kHeight, 150.0, 3}, 1);
  painting.set_brush({"round", 4.0, 0.5});
  painting.load_brush({{"Blue Red Shade", 2.0}, {"White", 1.0}}, 80.0);
  stroke(painting, 6.0, 8.0, 26.0, 16.0);
  painting.dry(1.0);
  render::RenderSettings settings;
  settings.wavelengths = 4;
  CanvasRenderer renderer(kWidth, kHeight, settings,
                          render::SpectralPalette(settings, painting.pigment_slots()));
  renderer.upload_all(painting.canvas());
  const paintcore::Painting::ChangeSubscriber changes = painting.subscribe_changes();
  (void)painting.take_changes(changes);  // the canvas as uploaded
  const auto upload_changes = [&] {
    const std::vector<int> tiles = paintcore::tile_indices(painting.take_changes(changes));
    EXPECT_FALSE(tiles.empty());
    renderer.upload_tiles(painting.canvas(), tiles);
  };

  // Wet paint across the dried stroke: its tiles are uploaded, their dry stacks not baked.
  std::uint64_t baked = renderer.dry_tiles_baked();
  painting.load_brush({{"White", 1.0}}, 60.0);
  stroke(painting, 8.0, 18.0, 24.0, 6.0);
  upload_changes();
  EXPECT_EQ(renderer.dry_tiles_baked(), baked);
  expect_fresh_image(renderer, painting, {}, "a stroke over dry paint");

  // Drying it adds a dry layer under those tiles: baked again.
  painting.dry(1.0);
  upload_changes();
  EXPECT_GT(renderer.dry_tiles_baked(), baked);
  expect_fresh_image(renderer, painting, {}, "a drying");

  baked = renderer.dry_tiles_baked();
  ASSERT_TRUE(painting.undo());
  upload_changes();
  EXPECT_GT(renderer.dry_tiles_baked(), baked);
  expect_fresh_image(renderer, painting, {}, "an undone drying");

  // A new visibility forgets every bake: the tiles are baked again. Hiding the only layer
  // left leaves them the bare ground's reflectance, which needs no bake.
  baked = renderer.dry_tiles_baked();
  renderer.set_hidden_dry_layers({false});
  renderer.upload_all(painting.canvas());
  EXPECT_GT(renderer.dry_tiles_baked(), baked);
  expect_fresh_image(renderer, painting, {false}, "a visibility change");
  baked = renderer.dry_tiles_baked();
  renderer.set_hidden_dry_layers({true});
  renderer.upload_all(painting.canvas());
  EXPECT_EQ(renderer.dry_tiles_baked(), baked);
  expect_fresh_image(renderer, painting, {true}, "hiding a layer");
}

}  // namespace dry_bake_cache_test
}  // namespace impasto::render_gl
