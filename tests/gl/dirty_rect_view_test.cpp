// The window's cached view fed the cells a brush changed (Painting::take_changes) instead
// of whole tiles: frame by frame along a stroke it shows exactly what a whole redraw shows,
// while shading a fraction of the pixels the whole tiles and their shadow rims would.
#include <gtest/gtest.h>

#include <cstdio>
#include <vector>

#include "impasto/paintcore/painting.hpp"
#include "impasto/render_gl/canvas_renderer.hpp"
#include "impasto/render_gl/framebuffer.hpp"
#include "impasto/render_gl/gl_context.hpp"
#include "impasto/render_gl/shaded_view_cache.hpp"

namespace impasto::render_gl {
namespace {

paintcore::PenSample pen(double x_mm, double y_mm) {
  paintcore::PenSample s;
  s.x_mm = x_mm;
  s.y_mm = y_mm;
  s.pressure = 0.8f;
  s.buttons = paintcore::kPenTip;
  return s;
}

TEST(DirtyRectView, FramesAlongAStrokeMatchAWholeRedrawAndShadeLess) {
  auto context = create_headless_context();
  const int w = 240, h = 180;
  paintcore::Painting painting({256, 192, 150.0, 3}, 1);
  painting.set_brush({"round", 3.0, 0.5});
  painting.load_brush({{"Blue Red Shade", 2.0}, {"White", 1.0}}, 80.0);
  render::RenderSettings settings;
  settings.wavelengths = 4;
  settings.shadows = true;  // the longest reach: the rim toward the light
  CanvasRenderer renderer(256, 192, settings,
                          render::SpectralPalette(settings, painting.pigment_slots()));
  renderer.upload_all(painting.canvas());
  const paintcore::Painting::ChangeSubscriber changes = painting.subscribe_changes();
  (void)painting.take_changes(changes);          // the canvas as uploaded
  const CanvasView view{128.0, 96.0, 0.9, 0.2};  // zoomed out a little and turned
  Framebuffer by_cells(w, h, TexelFormat::kRGBA8), by_tiles(w, h, TexelFormat::kRGBA8);
  Framebuffer whole(w, h, TexelFormat::kRGBA8);
  ShadedViewCache cells_cache, tiles_cache;
  (void)cells_cache.draw(renderer, view, w, h, by_cells.id());
  (void)tiles_cache.draw(renderer, view, w, h, by_tiles.id());

  // A stroke across the middle of the canvas (tile corners at 64-cell steps = 10.8 mm), a
  // few samples a frame as the window hands them over.
  long long shaded_cells = 0, shaded_tiles = 0;
  painting.begin_stroke();
  for (int frame = 0; frame < 8; ++frame) {
    for (int i = 0; i < 3; ++i) {
      const double t = (frame * 3 + i) / 24.0;
      painting.stroke_to(pen(16.0 + 12.0 * t, 14.0 + 8.0 * t));
    }
    const std::vector<paintcore::DirtyTile> changed = painting.take_changes(changes);
    const std::vector<int> tiles = paintcore::tile_indices(changed);
    renderer.upload_tiles(painting.canvas(), tiles);
    cells_cache.invalidate_cells(changed);
    tiles_cache.invalidate_tiles(tiles);
    const CachedDrawStats stats = cells_cache.draw(renderer, view, w, h, by_cells.id());
    EXPECT_FALSE(stats.full);
    shaded_cells += stats.pixels_shaded;
    shaded_tiles += tiles_cache.draw(renderer, view, w, h, by_tiles.id()).pixels_shaded;
    whole.bind();
    renderer.draw(view, w, h);
    EXPECT_EQ(by_cells.read_rgba8(), whole.read_rgba8()) << "frame " << frame;
  }
  painting.end_stroke();
  ASSERT_GT(painting.steps(), 0u);
  std::printf("pixels shaded over 8 frames: %lld by changed cells, %lld by whole tiles\n",
              shaded_cells, shaded_tiles);
  EXPECT_GT(shaded_cells, 0);
  EXPECT_LT(shaded_cells * 2, shaded_tiles);
}

}  // namespace
}  // namespace impasto::render_gl
