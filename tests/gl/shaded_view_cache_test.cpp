// The window's cached view: after strokes, a frame that re-shades only the changed tiles'
// pixels must show exactly what re-shading the whole view shows, for any pan, zoom and
// rotation; a frame with nothing new shades nothing; a change of light re-shades everything.
#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <vector>

#include "impasto/paintcore/painting.hpp"
#include "impasto/render_gl/canvas_renderer.hpp"
#include "impasto/render_gl/framebuffer.hpp"
#include "impasto/render_gl/gl_context.hpp"
#include "impasto/render_gl/shaded_view_cache.hpp"

namespace impasto::render_gl {
namespace {

TEST(TileScreenRect, CoversTheTileAndItsRimAndNothingOutOfView) {
  // One pixel a cell, the canvas's top-left cell at the viewport's top-left pixel.
  const CanvasView view{100.0, 50.0, 1.0, 0.0};
  const PixelRect r = tile_screen_rect(1, 3, view, 200, 100);  // cells x 64..127, y 0..63
  // GL rows count from the bottom: cells y 0..63 are rows 36..99.
  EXPECT_LE(r.x0, 63);
  EXPECT_GE(r.x1, 129);
  EXPECT_LE(r.y0, 100 - 65);
  EXPECT_EQ(r.y1, 100);
  EXPECT_LE(r.x1 - r.x0, 64 + 2 + 4);  // tight: the rim and a pixel of rounding each side
  const PixelRect away = tile_screen_rect(2, 3, CanvasView{-500.0, 50.0, 1.0, 0.0}, 200, 100);
  EXPECT_TRUE(away.empty());
}

std::vector<std::uint8_t> full_redraw(CanvasRenderer& renderer, const CanvasView& view, int w,
                                      int h) {
  Framebuffer target(w, h, TexelFormat::kRGBA8);
  target.bind();
  renderer.draw(view, w, h);
  return target.read_rgba8();
}

void stroke(paintcore::Painting& painting, double y_mm, double x0_mm, double x1_mm) {
  painting.begin_stroke();
  for (int i = 0; i <= 10; ++i) {
    paintcore::PenSample s;
    s.time_s = 0.01 * i;
    s.x_mm = x0_mm + (x1_mm - x0_mm) * i / 10.0;
    s.y_mm = y_mm;
    s.pressure = 0.8f;
    s.buttons = paintcore::kPenTip;
    painting.stroke_to(s);
  }
  painting.end_stroke();
}

// The scene both cached-view tests draw: a 256 x 192-cell canvas with the round brush loaded
// with `mix`, and its renderer at four wavelength nodes.
paintcore::Painting loaded_painting(const std::vector<paintcore::PigmentMixPart>& mix) {
  paintcore::Painting painting({256, 192, 150.0, 3}, 1);
  painting.set_brush({"round", 4.0, 0.5});
  painting.load_brush(mix, 80.0);
  return painting;
}

render::RenderSettings four_nodes() {
  render::RenderSettings settings;
  settings.wavelengths = 4;
  return settings;
}

// The painting's renderer with every tile uploaded.
std::unique_ptr<CanvasRenderer> uploaded_renderer(const paintcore::Painting& painting,
                                                  const render::RenderSettings& settings) {
  auto renderer = std::make_unique<CanvasRenderer>(
      256, 192, settings, render::SpectralPalette(settings, painting.pigment_slots()));
  renderer->upload_all(painting.canvas());
  return renderer;
}

class CachedView : public ::testing::TestWithParam<CanvasView> {};

TEST_P(CachedView, PartialReshadesMatchAWholeRedraw) {
  auto context = create_headless_context();
  const CanvasView view = GetParam();
  const int w = 240, h = 180;
  paintcore::Painting painting =
      loaded_painting({{"Ultramarine Blue", 2.0}, {"Titanium White", 1.0}});
  (void)painting.canvas().take_dirty_tiles();
  const render::RenderSettings settings = four_nodes();
  const auto uploaded = uploaded_renderer(painting, settings);
  CanvasRenderer& renderer = *uploaded;
  Framebuffer window(w, h, TexelFormat::kRGBA8);
  ShadedViewCache cache;
  const CachedDrawStats first = cache.draw(renderer, view, w, h, window.id());
  EXPECT_TRUE(first.full);
  EXPECT_EQ(first.pixels_shaded, static_cast<long long>(w) * h);

  // Two strokes in different tiles, each followed by a cached frame.
  for (const double y_mm : {8.0, 24.0}) {
    stroke(painting, y_mm, 6.0, 14.0 + y_mm / 4);
    const std::vector<int> dirty = painting.canvas().take_dirty_tiles();
    ASSERT_FALSE(dirty.empty());
    renderer.upload_tiles(painting.canvas(), dirty);
    cache.invalidate_tiles(dirty);
    const CachedDrawStats stats = cache.draw(renderer, view, w, h, window.id());
    EXPECT_FALSE(stats.full);
    // Zoomed in, one tile may fill the view; otherwise only part of it is re-shaded.
    EXPECT_LE(stats.pixels_shaded, static_cast<long long>(w) * h);
    if (view.pixels_per_cell <= 1.0) {
      EXPECT_LT(stats.pixels_shaded, static_cast<long long>(w) * h);
    }
    EXPECT_EQ(window.read_rgba8(), full_redraw(renderer, view, w, h)) << "after y=" << y_mm;
  }
  // Nothing new: nothing shaded, the same picture.
  const CachedDrawStats idle = cache.draw(renderer, view, w, h, window.id());
  EXPECT_EQ(idle.pixels_shaded, 0);
  EXPECT_EQ(window.read_rgba8(), full_redraw(renderer, view, w, h));
  // The light moved: every pixel again.
  render::RenderSettings moved = settings;
  moved.light_azimuth_deg += 40.0;
  renderer.set_shading(moved);
  EXPECT_TRUE(cache.draw(renderer, view, w, h, window.id()).full);
  EXPECT_EQ(window.read_rgba8(), full_redraw(renderer, view, w, h));
}

INSTANTIATE_TEST_SUITE_P(Views, CachedView,
                         ::testing::Values(CanvasView{120.0, 90.0, 1.0, 0.0},  // 1:1
                                           CanvasView{128.0, 96.0, 0.7, 0.3},  // out, turned
                                           CanvasView{60.0, 40.0, 3.5, -1.1}));

// Pans by whole pixels move the cached image and shade only what they uncover.
TEST(CachedViewPan, WholePixelPansShadeOnlyTheUncoveredStrips) {
  auto context = create_headless_context();
  const int w = 240, h = 180;
  paintcore::Painting painting = loaded_painting({{"Pyrrole Red", 1.0}, {"Titanium White", 1.0}});
  stroke(painting, 14.0, 4.0, 30.0);
  const auto uploaded = uploaded_renderer(painting, four_nodes());
  CanvasRenderer& renderer = *uploaded;
  Framebuffer window(w, h, TexelFormat::kRGBA8);
  ShadedViewCache cache;

  // One pixel a cell: the shifted image is exactly what a redraw gives.
  CanvasView view{120.0, 90.0, 1.0, 0.0};
  cache.draw(renderer, view, w, h, window.id());
  view.center_x_cells += 7.0;
  view.center_y_cells -= 5.0;
  const CachedDrawStats pan = cache.draw(renderer, view, w, h, window.id());
  EXPECT_TRUE(pan.shifted);
  EXPECT_FALSE(pan.full);
  EXPECT_EQ(pan.pixels_shaded, 7LL * h + 5LL * w);
  EXPECT_EQ(window.read_rgba8(), full_redraw(renderer, view, w, h));

  // Zoomed out and turned, panned as the mouse drags (12 px right, 9 px up): the same picture
  // but for cells whose edge falls within float rounding of a pixel centre.
  view = {128.0, 96.0, 0.7, 0.3};
  cache.draw(renderer, view, w, h, window.id());
  const auto from = view.window_to_cell(100.0, 100.0, w, h);
  const auto to = view.window_to_cell(112.0, 91.0, w, h);
  view.center_x_cells -= to[0] - from[0];
  view.center_y_cells -= to[1] - from[1];
  const CachedDrawStats drag = cache.draw(renderer, view, w, h, window.id());
  EXPECT_TRUE(drag.shifted);
  EXPECT_EQ(drag.pixels_shaded, 12LL * h + 9LL * w);
  const auto cached = window.read_rgba8();
  const auto redrawn = full_redraw(renderer, view, w, h);
  ASSERT_EQ(cached.size(), redrawn.size());
  int differing = 0;
  for (std::size_t i = 0; i < cached.size(); i += 4) {
    differing += cached[i] != redrawn[i] || cached[i + 1] != redrawn[i + 1] ||
                 cached[i + 2] != redrawn[i + 2];
  }
  EXPECT_LE(differing, w * h / 200) << "pixels that differ from a whole redraw";

  // A pan by a fraction of a pixel moves every cell edge: everything again.
  view.center_x_cells += 0.3;
  EXPECT_TRUE(cache.draw(renderer, view, w, h, window.id()).full);
  EXPECT_EQ(window.read_rgba8(), full_redraw(renderer, view, w, h));
}
// in, turned

}  // namespace
}  // namespace impasto::render_gl
