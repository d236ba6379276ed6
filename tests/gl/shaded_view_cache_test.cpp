// The window's cached view: after strokes, a frame that re-shades only the changed tiles'
// pixels must show exactly what re-shading the whole view shows, for any pan, zoom and
// rotation; a frame with nothing new shades nothing; a change of light re-shades everything;
// coarse frames while the view moves are refined to the same picture.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <vector>

#include "impasto/paintcore/painting.hpp"
#include "impasto/render_gl/canvas_renderer.hpp"
#include "impasto/render_gl/framebuffer.hpp"
#include "impasto/render_gl/gl_context.hpp"
#include "impasto/render_gl/rough_blocks.hpp"
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

// How many RGBA pixels' colours differ between two images of the same size.
int pixels_differing(const std::vector<std::uint8_t>& a, const std::vector<std::uint8_t>& b) {
  EXPECT_EQ(a.size(), b.size());
  int differing = 0;
  for (std::size_t i = 0; i + 3 < std::min(a.size(), b.size()); i += 4)
    differing += a[i] != b[i] || a[i + 1] != b[i + 1] || a[i + 2] != b[i + 2];
  return differing;
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

// What most of these tests shade: a stroke of red and white on the GPU (four nodes), and a
// window of width x height to show it in.
struct StrokeScene {
  StrokeScene(int width, int height)
      : context(create_headless_context()),
        painting(loaded_painting({{"Red", 1.0}, {"White", 1.0}})),
        window(width, height, TexelFormat::kRGBA8) {
    stroke(painting, 14.0, 4.0, 30.0);
    uploaded = uploaded_renderer(painting, four_nodes());
  }
  CanvasRenderer& renderer() { return *uploaded; }

  std::unique_ptr<GlContext> context;
  paintcore::Painting painting;
  Framebuffer window;
  std::unique_ptr<CanvasRenderer> uploaded;
};

// The cells the painting changed since the last call, uploaded and invalidated in the cache.
void upload_changes(paintcore::Painting& painting, paintcore::Painting::ChangeSubscriber changes,
                    CanvasRenderer& renderer, ShadedViewCache& cache) {
  const std::vector<paintcore::DirtyTile> changed = painting.take_changes(changes);
  renderer.upload_tiles(painting.canvas(), paintcore::tile_indices(changed));
  cache.invalidate_cells(changed);
}

class CachedView : public ::testing::TestWithParam<CanvasView> {};

TEST_P(CachedView, PartialReshadesMatchAWholeRedraw) {
  auto context = create_headless_context();
  const CanvasView view = GetParam();
  const int w = 240, h = 180;
  paintcore::Painting painting = loaded_painting({{"Blue Red Shade", 2.0}, {"White", 1.0}});
  const paintcore::Painting::ChangeSubscriber changes = painting.subscribe_changes();
  (void)painting.take_changes(changes);  // the canvas as it will be uploaded
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
    const std::vector<int> dirty = paintcore::tile_indices(painting.take_changes(changes));
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
  const int w = 240, h = 180;
  StrokeScene scene(w, h);
  CanvasRenderer& renderer = scene.renderer();
  Framebuffer& window = scene.window;
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
  EXPECT_LE(pixels_differing(window.read_rgba8(), full_redraw(renderer, view, w, h)), w * h / 200)
      << "pixels that differ from a whole redraw";

  // A pan by a fraction of a pixel moves every cell edge: everything again.
  view.center_x_cells += 0.3;
  EXPECT_TRUE(cache.draw(renderer, view, w, h, window.id()).full);
  EXPECT_EQ(window.read_rgba8(), full_redraw(renderer, view, w, h));
}
// Each view option the shader reads is part of the cached view's look: changing one
// re-shades every pixel (the subsurface map's toggle once did not, and the window rebuilt the
// surface tables to show it).
TEST(CachedViewOptions, EachViewOptionReshadesEverything) {
  const int w = 120, h = 90;
  StrokeScene scene(w, h);
  CanvasRenderer& renderer = scene.renderer();
  Framebuffer& window = scene.window;
  ShadedViewCache cache;
  const CanvasView view{128.0, 96.0, 0.5, 0.0};
  cache.draw(renderer, view, w, h, window.id());
  const auto changes = std::vector<void (*)(GpuViewOptions&)>{
      [](GpuViewOptions& o) { o.light_intensity *= 1.5f; },
      [](GpuViewOptions& o) { o.background_rgb[1] += 0.2f; },
      [](GpuViewOptions& o) { o.crack_close_up_min_pixels += 1.0f; },
      [](GpuViewOptions& o) { o.smooth_zoom = !o.smooth_zoom; },
      [](GpuViewOptions& o) { o.subsurface_map = !o.subsurface_map; }};
  for (std::size_t i = 0; i < changes.size(); ++i) {
    GpuViewOptions options = renderer.view_options();
    changes[i](options);
    renderer.set_view_options(options);
    EXPECT_TRUE(cache.draw(renderer, view, w, h, window.id()).full) << "option " << i;
    EXPECT_EQ(cache.draw(renderer, view, w, h, window.id()).pixels_shaded, 0) << "option " << i;
  }
}

// The coarse factor: the smallest whose predicted shading fits the budget.
TEST(CoarseFactor, TheSmallestThatFitsTheBudget) {
  using Cache = ShadedViewCache;
  const int w = 1400, h = 900;
  EXPECT_EQ(Cache::coarse_factor_for(0.0, w, h, 50.0), Cache::kMinCoarseFactor);  // unknown
  EXPECT_EQ(Cache::coarse_factor_for(1e-9, w, h, 50.0), Cache::kMinCoarseFactor);
  EXPECT_EQ(Cache::coarse_factor_for(1.0, w, h, 50.0), Cache::kMaxCoarseFactor);  // cannot fit
  // 1 µs a pixel (llvmpipe's order): 1/4 is 79 000 px, 79 ms; 1/6 is 35 100 px, 35 ms.
  const int factor = Cache::coarse_factor_for(1e-3, w, h, 50.0);
  EXPECT_GT(factor, Cache::kMinCoarseFactor);
  const auto cost = [&](int f) { return 1e-3 * ((w + f - 1) / f) * ((h + f - 1) / f); };
  EXPECT_LE(cost(factor), 50.0);
  EXPECT_GT(cost(factor - 1), 50.0);
  // A dearer pixel or a smaller budget never gives a finer factor.
  EXPECT_GE(Cache::coarse_factor_for(2e-3, w, h, 50.0), factor);
  EXPECT_GE(Cache::coarse_factor_for(1e-3, w, h, 25.0), factor);
}

// Coarse frames while the view moves, at whatever factor the budget asks for; the refined
// frame after them is exactly a whole redraw.
TEST(CachedViewCoarse, RefinedAfterCoarseFramesMatchesAWholeRedraw) {
  const int w = 240, h = 180;
  StrokeScene scene(w, h);
  CanvasRenderer& renderer = scene.renderer();
  Framebuffer& window = scene.window;
  using Detail = ShadedViewCache::Detail;
  for (const double budget_ms : {1e9, 1e-9}) {  // the finest factor, then the coarsest
    ShadedViewCache cache;
    cache.set_coarse_budget_ms(budget_ms);
    CanvasView view{120.0, 90.0, 1.0, 0.0};
    const CachedDrawStats first = cache.draw(renderer, view, w, h, window.id());
    EXPECT_TRUE(first.full);
    EXPECT_FALSE(first.coarse);
    EXPECT_GT(first.shade_ms, 0.0);  // timed: the next coarse factor is chosen from it
    for (int step = 0; step < 3; ++step) {
      view.pixels_per_cell *= 1.15;  // a zoom step
      view.rotation_rad += 0.1;
      const CachedDrawStats moving = cache.update(renderer, view, w, h, Detail::kCoarse);
      EXPECT_TRUE(moving.coarse);
      EXPECT_EQ(moving.coarse_factor, budget_ms > 1.0 ? ShadedViewCache::kMinCoarseFactor
                                                      : ShadedViewCache::kMaxCoarseFactor);
      const int f = moving.coarse_factor;
      EXPECT_EQ(moving.pixels_shaded, static_cast<long long>((w + f - 1) / f) * ((h + f - 1) / f));
    }
    const CachedDrawStats refined = cache.draw(renderer, view, w, h, window.id());
    EXPECT_TRUE(refined.full);
    EXPECT_FALSE(refined.coarse);
    EXPECT_FALSE(refined.refining);
    EXPECT_EQ(refined.pixels_shaded, static_cast<long long>(w) * h);
    EXPECT_EQ(window.read_rgba8(), full_redraw(renderer, view, w, h)) << "budget " << budget_ms;
  }
}

// The window's refinement: a block a frame in reading order from the top, each presented as
// it is refined; once done, exactly a whole redraw. A pan by whole pixels meanwhile moves the
// blocks still to refine with the image: the refined ones are not refined again.
TEST(CachedViewCoarse, RefinedInBlocksMatchesAWholeRedraw) {
  const int w = 240, h = 180;
  StrokeScene scene(w, h);
  CanvasRenderer& renderer = scene.renderer();
  Framebuffer& window = scene.window;
  using Detail = ShadedViewCache::Detail;
  ShadedViewCache cache;
  cache.set_refine_step_ms(1e-9);  // one block a frame
  CanvasView view{120.0, 90.0, 1.0, 0.0};
  cache.draw(renderer, view, w, h, window.id());
  view.pixels_per_cell = 1.3;
  view.rotation_rad = 0.2;
  const CachedDrawStats coarse = cache.update(renderer, view, w, h, Detail::kCoarse);
  cache.copy_to(window.id(), {0, 0, w, h});
  EXPECT_TRUE(coarse.refining);
  constexpr int kBlock = ShadedViewCache::kRefineBlock;
  const int blocks = (w + kBlock - 1) / kBlock * ((h + kBlock - 1) / kBlock);
  // Half way, a pan by whole pixels: what is left to refine moved with the image.
  for (int frame = 0; frame < blocks / 2; ++frame)
    EXPECT_TRUE(cache.update(renderer, view, w, h, Detail::kRefining).refining);
  const auto from = view.window_to_cell(100.0, 100.0, w, h);
  const auto to = view.window_to_cell(100.0, 95.0, w, h);  // 5 px up
  view.center_x_cells -= to[0] - from[0];
  view.center_y_cells -= to[1] - from[1];
  const CachedDrawStats pan = cache.update(renderer, view, w, h, Detail::kCoarse);
  cache.copy_to(window.id(), {0, 0, w, h});
  EXPECT_TRUE(pan.shifted);
  EXPECT_TRUE(pan.refining);
  int frames = 0;
  long long shaded = 0;
  int top = h;  // the top of the row of blocks being refined
  for (bool refining = true; refining && frames < 1000; ++frames) {
    const CachedDrawStats block = cache.update(renderer, view, w, h, Detail::kRefining);
    EXPECT_FALSE(block.full);
    ASSERT_EQ(block.changed.size(), 1u);
    const PixelRect& r = block.changed[0];
    EXPECT_LE(r.x1 - r.x0, kBlock);
    EXPECT_LE(r.y1 - r.y0, kBlock);
    EXPECT_LE(r.y1, top);  // from the top down
    top = r.y1;
    shaded += block.pixels_shaded;
    cache.copy_to(window.id(), r);
    refining = block.refining;
  }
  // The unrefined half, moved 5 px up, touches at most one more row of blocks.
  const int columns = (w + kBlock - 1) / kBlock;
  EXPECT_GE(frames, blocks - blocks / 2);
  EXPECT_LE(frames, blocks - blocks / 2 + columns);
  EXPECT_LT(shaded, static_cast<long long>(w) * h);
  // The blocks refined before the pan moved with the image, which is the same as a redraw
  // but for cells whose edge falls within float rounding of a pixel centre (as a pan's).
  EXPECT_LE(pixels_differing(window.read_rgba8(), full_redraw(renderer, view, w, h)), w * h / 200);
}

// A full upload whose colours change a little (a palette's own rule replacing its stand-in)
// keeps the image and refines it block by block: no frame re-shades the whole view, and the
// refined image is the whole redraw of the new data.
TEST(CachedViewRefineAll, KeepsTheImageAndRefinesItBlockByBlock) {
  const int w = 240, h = 180;
  StrokeScene scene(w, h);
  paintcore::Painting& painting = scene.painting;
  CanvasRenderer& renderer = scene.renderer();
  Framebuffer& window = scene.window;
  using Detail = ShadedViewCache::Detail;
  ShadedViewCache cache;
  cache.set_refine_step_ms(1e-9);  // one block a frame
  const CanvasView view{120.0, 90.0, 1.0, 0.0};
  cache.draw(renderer, view, w, h, window.id());
  const std::vector<std::uint8_t> before = window.read_rgba8();
  // The same painting's canvas changed under the view: more paint, uploaded whole.
  stroke(painting, 20.0, 6.0, 30.0);
  renderer.upload_all(painting.canvas());
  cache.refine_all();
  const CachedDrawStats first = cache.update(renderer, view, w, h, Detail::kRefining);
  cache.copy_to(window.id(), {0, 0, w, h});
  EXPECT_TRUE(first.refining);
  EXPECT_FALSE(first.full);
  constexpr int kBlock = ShadedViewCache::kRefineBlock;
  EXPECT_LE(first.pixels_shaded, static_cast<long long>(kBlock) * kBlock);
  // Still the old image but for the block refined.
  EXPECT_LE(pixels_differing(window.read_rgba8(), before), kBlock * kBlock);
  int frames = 1;
  for (bool refining = true; refining && frames < 1000; ++frames)
    refining = cache.update(renderer, view, w, h, Detail::kRefining).refining;
  const int blocks = (w + kBlock - 1) / kBlock * ((h + kBlock - 1) / kBlock);
  EXPECT_EQ(frames, blocks);  // a block a frame, the first one included
  cache.copy_to(window.id(), {0, 0, w, h});
  EXPECT_EQ(window.read_rgba8(), full_redraw(renderer, view, w, h));
  EXPECT_NE(window.read_rgba8(), before);
}

// While a stroke changes the canvas (kCoarse), changed regions over the draft budget are
// shaded as a draft at a fraction of the pixels, and refined to exactly a whole redraw.
TEST(CachedViewDraft, DraftedStrokesAreRefinedToAWholeRedraw) {
  auto context = create_headless_context();
  const int w = 240, h = 180;
  using Detail = ShadedViewCache::Detail;
  for (const CanvasView& view :
       {CanvasView{120.0, 90.0, 1.0, 0.0}, CanvasView{128.0, 96.0, 0.4, 0.3},
        CanvasView{60.0, 40.0, 2.5, -1.1}}) {
    paintcore::Painting painting = loaded_painting({{"Blue Red Shade", 2.0}, {"White", 1.0}});
    const auto uploaded = uploaded_renderer(painting, four_nodes());
    CanvasRenderer& renderer = *uploaded;
    const paintcore::Painting::ChangeSubscriber changes = painting.subscribe_changes();
    (void)painting.take_changes(changes);  // the canvas as uploaded
    Framebuffer window(w, h, TexelFormat::kRGBA8);
    ShadedViewCache cache;
    cache.set_draft_budget_ms(0.0);  // every change drafted, at the coarsest factor
    cache.draw(renderer, view, w, h, window.id());
    for (const double y_mm : {8.0, 20.0}) {
      stroke(painting, y_mm, 6.0, 30.0);
      upload_changes(painting, changes, renderer, cache);
      const CachedDrawStats draft = cache.update(renderer, view, w, h, Detail::kCoarse);
      cache.copy_to(window.id(), {0, 0, w, h});
      EXPECT_EQ(draft.draft_factor, ShadedViewCache::kMaxDraftFactor);
      EXPECT_TRUE(draft.refining);
      ASSERT_FALSE(draft.changed.empty());
      long long drafted = 0;
      for (const PixelRect& r : draft.changed) drafted += r.area();
      // A sixteenth of the pixels, and a draft pixel's rim each way.
      EXPECT_LT(draft.pixels_shaded, drafted / 4);
      EXPECT_NE(window.read_rgba8(), full_redraw(renderer, view, w, h));
    }
    int frames = 0;
    for (bool refining = true; refining && frames < 100; ++frames) {
      const CachedDrawStats step = cache.update(renderer, view, w, h, Detail::kRefining);
      EXPECT_EQ(step.draft_factor, 0);
      for (const PixelRect& r : step.changed) cache.copy_to(window.id(), r);
      refining = step.refining;
    }
    EXPECT_EQ(window.read_rgba8(), full_redraw(renderer, view, w, h))
        << "view at " << view.pixels_per_cell << " px a cell";
    // Within the budget the changes are shaded finely: nothing to refine.
    cache.set_draft_budget_ms(1e9);
    stroke(painting, 14.0, 10.0, 20.0);
    upload_changes(painting, changes, renderer, cache);
    const CachedDrawStats fine = cache.update(renderer, view, w, h, Detail::kCoarse);
    cache.copy_to(window.id(), {0, 0, w, h});
    EXPECT_EQ(fine.draft_factor, 0);
    EXPECT_FALSE(fine.refining);
    EXPECT_EQ(window.read_rgba8(), full_redraw(renderer, view, w, h));
  }
}

TEST(RoughBlocks, MarksRefinesAndMovesBlocks) {
  RoughBlocks rough;
  rough.resize(200, 130, 64);  // 4 x 3 blocks, the last column and row partial
  EXPECT_FALSE(rough.any());
  rough.mark({70, 10, 140, 20});  // touches columns 1 and 2 of the bottom row
  EXPECT_EQ(rough.count(), 2);
  rough.clear_covered({64, 0, 127, 64});  // one pixel short of block (1, 0)
  EXPECT_EQ(rough.count(), 2);
  rough.clear_covered({64, 0, 128, 64});
  EXPECT_EQ(rough.count(), 1);
  rough.mark_all();
  EXPECT_EQ(rough.count(), 12);
  rough.clear_covered({0, 0, 200, 130});  // the partial blocks at the edge count as covered
  EXPECT_FALSE(rough.any());
  // Runs in reading order from the top (GL rows up), along a row, at most max_blocks.
  rough.mark({0, 0, 10, 10});
  rough.mark({130, 128, 200, 130});
  const PixelRect top = rough.take_run(8);
  EXPECT_EQ(top.x0, 128);
  EXPECT_EQ(top.x1, 200);
  EXPECT_EQ(top.y0, 128);
  EXPECT_EQ(top.y1, 130);
  const PixelRect bottom = rough.take_run(8);
  EXPECT_EQ(bottom.x0, 0);
  EXPECT_EQ(bottom.x1, 64);
  EXPECT_EQ(bottom.y0, 0);
  EXPECT_TRUE(rough.take_run(8).empty());
  rough.mark({0, 70, 200, 100});
  EXPECT_EQ(rough.take_run(2).x1, 128);
  EXPECT_EQ(rough.count(), 2);
  // A shift: a block moved by 10 px right and up touches four; off the viewport it is gone.
  rough.clear();
  rough.mark({0, 0, 1, 1});
  rough.shift(10, 10);
  EXPECT_EQ(rough.count(), 4);
  rough.shift(-300, 0);
  EXPECT_FALSE(rough.any());
}

}  // namespace
}  // namespace impasto::render_gl
