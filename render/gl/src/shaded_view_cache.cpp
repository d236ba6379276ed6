#include "impasto/render_gl/shaded_view_cache.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>

#include "impasto/render/shading_key.hpp"

namespace impasto::render_gl {

using paintcore::kTileSize;

PixelRect tile_screen_rect(int tile_index, int tiles_x, const CanvasView& view, int viewport_w,
                           int viewport_h, render::relief::Reach reach) {
  const int x0 = tile_index % tiles_x * kTileSize, y0 = tile_index / tiles_x * kTileSize;
  return cells_screen_rect({x0, y0, x0 + kTileSize, y0 + kTileSize}, view, viewport_w, viewport_h,
                           reach);
}

PixelRect cells_screen_rect(const paintcore::CellRect& cells, const CanvasView& view,
                            int viewport_w, int viewport_h, render::relief::Reach reach) {
  // The cells and the rim of cells whose shading reads their heights.
  const double x0 = cells.x0 - static_cast<double>(reach.left);
  const double y0 = cells.y0 - static_cast<double>(reach.top);
  const double x1 = cells.x1 + static_cast<double>(reach.right);
  const double y1 = cells.y1 + static_cast<double>(reach.bottom);
  double lo_x = std::numeric_limits<double>::max(), lo_y = lo_x;
  double hi_x = std::numeric_limits<double>::lowest(), hi_y = hi_x;
  for (const auto& [cx, cy] : {std::pair{x0, y0}, {x1, y0}, {x0, y1}, {x1, y1}}) {
    const auto window = view.cell_to_window(cx, cy, viewport_w, viewport_h);
    const double gl_y = viewport_h - window[1];  // GL rows count up from the bottom
    lo_x = std::min(lo_x, window[0]);
    hi_x = std::max(hi_x, window[0]);
    lo_y = std::min(lo_y, gl_y);
    hi_y = std::max(hi_y, gl_y);
  }
  // A pixel is shaded at its centre: widen by one so rounding never drops an edge pixel.
  const auto clamp_to = [](double v, int limit) {
    return static_cast<int>(std::clamp(v, 0.0, static_cast<double>(limit)));
  };
  return {clamp_to(std::floor(lo_x) - 1, viewport_w), clamp_to(std::floor(lo_y) - 1, viewport_h),
          clamp_to(std::ceil(hi_x) + 1, viewport_w), clamp_to(std::ceil(hi_y) + 1, viewport_h)};
}

void ShadedViewCache::invalidate_tiles(std::span<const int> tiles) {
  dirty_tiles_.insert(dirty_tiles_.end(), tiles.begin(), tiles.end());
}

void ShadedViewCache::invalidate_cells(std::span<const paintcore::DirtyTile> changed) {
  for (const paintcore::DirtyTile& d : changed)
    if (!d.cells.empty()) dirty_cells_.push_back(d.cells);
}

std::vector<double> ShadedViewCache::look_of(const CanvasRenderer& renderer,
                                             const CanvasView& view) const {
  const render::RenderSettings& s = renderer.settings();
  const GpuViewOptions& o = renderer.view_options();
  // The shading (render/shading_key.hpp, as the CPU renderer's relight), then the rest of
  // what the shader reads as uniforms (CanvasRenderer::set_shading) and the view.
  std::vector<double> look = render::shading_settings_key(s);
  const std::vector<double> colour = render::shader_colour_settings_key(s);
  look.insert(look.end(), colour.begin(), colour.end());
  look.insert(look.end(),
              {o.light_intensity, o.background_rgb[0], o.background_rgb[1], o.background_rgb[2],
               o.crack_close_up_min_pixels, o.smooth_zoom ? 1.0 : 0.0, o.subsurface_map ? 1.0 : 0.0,
               view.pixels_per_cell, view.rotation_rad, renderer.cell_mm()});
  return look;
}

std::vector<PixelRect> ShadedViewCache::shift_image(int dx, int dy) {
  const int w = image_->width(), h = image_->height();
  if (!spare_ || spare_->width() != w || spare_->height() != h) {
    spare_ = std::make_unique<Framebuffer>(w, h, TexelFormat::kRGBA8);
  }
  const int x0 = std::max(0, -dx), y0 = std::max(0, -dy);
  const int x1 = w - std::max(0, dx), y1 = h - std::max(0, dy);
  glBindFramebuffer(GL_READ_FRAMEBUFFER, image_->id());
  glBindFramebuffer(GL_DRAW_FRAMEBUFFER, spare_->id());
  glBlitFramebuffer(x0, y0, x1, y1, x0 + dx, y0 + dy, x1 + dx, y1 + dy, GL_COLOR_BUFFER_BIT,
                    GL_NEAREST);
  std::swap(image_, spare_);
  std::vector<PixelRect> uncovered;
  if (dx > 0) uncovered.push_back({0, 0, dx, h});
  if (dx < 0) uncovered.push_back({w + dx, 0, w, h});
  if (dy > 0) uncovered.push_back({0, 0, w, dy});
  if (dy < 0) uncovered.push_back({0, h + dy, w, h});
  return uncovered;
}

CachedDrawStats ShadedViewCache::draw(CanvasRenderer& renderer, const CanvasView& view,
                                      int viewport_w, int viewport_h, GLuint target) {
  CachedDrawStats stats = update(renderer, view, viewport_w, viewport_h);
  copy_to(target, {0, 0, viewport_w, viewport_h});
  glViewport(0, 0, viewport_w, viewport_h);
  check_gl_error("cached canvas view");
  return stats;
}

void ShadedViewCache::copy_to(GLuint target, const PixelRect& rect) const {
  if (!image_ || rect.empty()) return;
  glBindFramebuffer(GL_READ_FRAMEBUFFER, image_->id());
  glBindFramebuffer(GL_DRAW_FRAMEBUFFER, target);
  glBlitFramebuffer(rect.x0, rect.y0, rect.x1, rect.y1, rect.x0, rect.y0, rect.x1, rect.y1,
                    GL_COLOR_BUFFER_BIT, GL_NEAREST);
  glBindFramebuffer(GL_FRAMEBUFFER, target);
}

int ShadedViewCache::coarse_factor_for(double ms_per_pixel, int viewport_w, int viewport_h,
                                       double budget_ms) {
  if (!(ms_per_pixel > 0.0)) return kMinCoarseFactor;
  for (int factor = kMinCoarseFactor; factor < kMaxCoarseFactor; ++factor) {
    const double pixels = static_cast<double>((viewport_w + factor - 1) / factor) *
                          ((viewport_h + factor - 1) / factor);
    if (pixels * ms_per_pixel <= budget_ms) return factor;
  }
  return kMaxCoarseFactor;
}

int ShadedViewCache::next_coarse_factor(int viewport_w, int viewport_h) const {
  const double ms_per_pixel =
      coarse_ms_per_pixel_ > 0.0 ? coarse_ms_per_pixel_ : fine_ms_per_pixel_ * kCoarsePixelCost;
  return coarse_factor_for(ms_per_pixel, viewport_w, viewport_h, coarse_budget_ms_);
}

namespace {

// The time GL takes for `draw`: whatever was queued before is finished first.
template <typename Draw>
double timed_gl_ms(Draw&& draw) {
  glFinish();
  const auto start = std::chrono::steady_clock::now();
  draw();
  glFinish();
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
      .count();
}

// Many small passes cost more than one pass over their bounding box, and overlapping ones
// shade pixels twice: one pass over the box when it is no larger than their sum.
std::vector<PixelRect> fewer_passes(std::vector<PixelRect> regions) {
  constexpr std::size_t kMaxPasses = 32;
  std::erase_if(regions, [](const PixelRect& r) { return r.empty(); });
  if (regions.size() <= 1) return regions;
  PixelRect box = regions.front();
  long long sum = 0;
  for (const PixelRect& r : regions) {
    box = {std::min(box.x0, r.x0), std::min(box.y0, r.y0), std::max(box.x1, r.x1),
           std::max(box.y1, r.y1)};
    sum += r.area();
  }
  if (regions.size() > kMaxPasses || box.area() <= sum) regions.assign(1, box);
  return regions;
}

}  // namespace

long long ShadedViewCache::shade_coarse(CanvasRenderer& renderer, const CanvasView& view,
                                        int viewport_w, int viewport_h, int factor,
                                        double& shade_ms) {
  const int w = std::max(1, (viewport_w + factor - 1) / factor);
  const int h = std::max(1, (viewport_h + factor - 1) / factor);
  if (!coarse_image_ || coarse_image_->width() != w || coarse_image_->height() != h) {
    coarse_image_ = std::make_unique<Framebuffer>(w, h, TexelFormat::kRGBA8);
  }
  CanvasView small = view;
  small.pixels_per_cell *= static_cast<double>(w) / viewport_w;
  // One cell a coarse pixel: zoomed out, smooth zoom would average up to 4 x 4 cells under
  // each (16 times the work of a fine pixel's 2 x 2 at 0.8 px a cell), undoing the saving.
  const GpuViewOptions options = renderer.view_options();
  GpuViewOptions sharp = options;
  sharp.smooth_zoom = false;
  renderer.set_view_options(sharp);
  const long long pixels = static_cast<long long>(w) * h;
  shade_ms = timed_gl_ms([&] {
    coarse_image_->bind();
    renderer.draw(small, w, h);
  });
  coarse_ms_per_pixel_ = shade_ms / static_cast<double>(pixels);
  renderer.set_view_options(options);
  glBindFramebuffer(GL_READ_FRAMEBUFFER, coarse_image_->id());
  glBindFramebuffer(GL_DRAW_FRAMEBUFFER, image_->id());
  glBlitFramebuffer(0, 0, w, h, 0, 0, viewport_w, viewport_h, GL_COLOR_BUFFER_BIT, GL_LINEAR);
  return pixels;
}

int ShadedViewCache::draft_factor_for(std::span<const PixelRect> regions,
                                      const CanvasRenderer& renderer,
                                      const CanvasView& view) const {
  double pixels = 0.0;
  for (const PixelRect& r : regions) pixels += static_cast<double>(r.area());
  if (pixels <= 0.0) return 0;
  const double fine = changed_ms_per_pixel_ > 0.0 ? changed_ms_per_pixel_ : fine_ms_per_pixel_;
  if (draft_budget_ms_ <= 0.0) return kMaxDraftFactor;
  if (!(fine > 0.0) || pixels * fine <= draft_budget_ms_) return 0;  // unknown: measure it
  // Zoomed out, smooth zoom averages up to 4 x 4 cells a pixel: one cell a pixel at full
  // resolution may already fit. Elsewhere a draft pixel costs what a fine one does.
  const bool averages = renderer.view_options().smooth_zoom && view.pixels_per_cell <= 1.0 / 1.5;
  const double draft = draft_ms_per_pixel_ > 0.0 ? draft_ms_per_pixel_ : fine;
  for (int factor = averages ? 1 : 2; factor < kMaxDraftFactor; ++factor) {
    if (pixels / (factor * factor) * draft <= draft_budget_ms_) return factor;
  }
  return kMaxDraftFactor;
}

long long ShadedViewCache::shade_draft(CanvasRenderer& renderer, const CanvasView& view,
                                       int viewport_w, int viewport_h,
                                       std::span<const PixelRect> regions, int factor,
                                       std::vector<PixelRect>& drafted) {
  const int w = (viewport_w + factor - 1) / factor, h = (viewport_h + factor - 1) / factor;
  if (!draft_image_ || draft_image_->width() != w || draft_image_->height() != h) {
    draft_image_ = std::make_unique<Framebuffer>(w, h, TexelFormat::kRGBA8);
  }
  // The draft's pixel (X, Y) covers the viewport's pixels [X f, (X + 1) f) x [Y f, (Y + 1) f):
  // its view is the viewport's own, w f x h f pixels large from the same bottom-left corner.
  CanvasView small = view;
  const auto centre =
      view.window_to_cell(w * factor / 2.0, viewport_h - h * factor / 2.0, viewport_w, viewport_h);
  small.center_x_cells = centre[0];
  small.center_y_cells = centre[1];
  small.pixels_per_cell = view.pixels_per_cell / factor;
  const GpuViewOptions options = renderer.view_options();
  GpuViewOptions sharp = options;
  sharp.smooth_zoom = false;  // one cell a pixel
  renderer.set_view_options(sharp);
  // Each region's draft pixels, and one more each way for the magnification to blend.
  const auto draft_rect = [&](const PixelRect& r, int rim) {
    return PixelRect{std::max(0, r.x0 / factor - rim), std::max(0, r.y0 / factor - rim),
                     std::min(w, (r.x1 + factor - 1) / factor + rim),
                     std::min(h, (r.y1 + factor - 1) / factor + rim)};
  };
  long long pixels = 0;
  const double ms = timed_gl_ms([&] {
    draft_image_->bind();
    glEnable(GL_SCISSOR_TEST);
    for (const PixelRect& r : regions) {
      const PixelRect d = draft_rect(r, 1);
      glScissor(d.x0, d.y0, d.x1 - d.x0, d.y1 - d.y0);
      renderer.draw(small, w, h);
      pixels += d.area();
    }
    glDisable(GL_SCISSOR_TEST);
  });
  if (pixels > 0) draft_ms_per_pixel_ = ms / static_cast<double>(pixels);
  renderer.set_view_options(options);
  glBindFramebuffer(GL_READ_FRAMEBUFFER, draft_image_->id());
  glBindFramebuffer(GL_DRAW_FRAMEBUFFER, image_->id());
  drafted.clear();
  for (const PixelRect& r : regions) {
    const PixelRect d = draft_rect(r, 0);
    const PixelRect onto{d.x0 * factor, d.y0 * factor, d.x1 * factor, d.y1 * factor};
    glBlitFramebuffer(d.x0, d.y0, d.x1, d.y1, onto.x0, onto.y0, onto.x1, onto.y1,
                      GL_COLOR_BUFFER_BIT, factor > 1 ? GL_LINEAR : GL_NEAREST);
    drafted.push_back(
        {onto.x0, onto.y0, std::min(viewport_w, onto.x1), std::min(viewport_h, onto.y1)});
  }
  return pixels;
}

CachedDrawStats ShadedViewCache::update(CanvasRenderer& renderer, const CanvasView& view,
                                        int viewport_w, int viewport_h, Detail detail) {
  CachedDrawStats stats;
  if (!image_ || image_->width() != viewport_w || image_->height() != viewport_h) {
    image_ = std::make_unique<Framebuffer>(viewport_w, viewport_h, TexelFormat::kRGBA8);
    rough_.resize(viewport_w, viewport_h, kRefineBlock);
    all_invalid_ = true;
  }
  const auto look = look_of(renderer, view);
  if (&renderer != renderer_ || look != look_) {
    all_invalid_ = true;
    // A pixel's cost depends on the zoom and the look: a draft decision from the old one could
    // draft for ever what now fits the budget.
    changed_ms_per_pixel_ = draft_ms_per_pixel_ = 0.0;
  }
  renderer_ = &renderer;
  look_ = look;

  // A pan: where the view's centre moved by whole pixels, move the image instead.
  std::vector<PixelRect> regions;
  if (!all_invalid_ && (view.center_x_cells != view_.center_x_cells ||
                        view.center_y_cells != view_.center_y_cells)) {
    const auto before = view_.cell_to_window(0.0, 0.0, viewport_w, viewport_h);
    const auto after = view.cell_to_window(0.0, 0.0, viewport_w, viewport_h);
    const double dx = after[0] - before[0], dy_down = after[1] - before[1];
    const double rx = std::round(dx), ry = std::round(dy_down);
    constexpr double kWholePixel = 1e-3;
    if (std::abs(dx - rx) < kWholePixel && std::abs(dy_down - ry) < kWholePixel &&
        std::abs(rx) < viewport_w && std::abs(ry) < viewport_h) {
      regions = shift_image(static_cast<int>(rx), -static_cast<int>(ry));  // GL rows go up
      rough_.shift(static_cast<int>(rx), -static_cast<int>(ry));  // the rough parts moved too
      stats.shifted = true;
    } else {
      all_invalid_ = true;
    }
  }
  view_ = view;

  if (rough_.any() && detail == Detail::kFull) all_invalid_ = true;  // refine at once
  if (all_invalid_ && detail == Detail::kCoarse) {
    stats.coarse_factor = next_coarse_factor(viewport_w, viewport_h);
    stats.pixels_shaded =
        shade_coarse(renderer, view, viewport_w, viewport_h, stats.coarse_factor, stats.shade_ms);
    stats.full = stats.coarse = stats.refining = true;
    rough_.mark_all();
    stats.changed.assign(1, {0, 0, viewport_w, viewport_h});
    all_invalid_ = false;
    dirty_tiles_.clear();
    dirty_cells_.clear();
    check_gl_error("coarse canvas view");
    return stats;
  }

  // The regions to re-shade: the whole viewport, or the uncovered strips, the changed tiles
  // and cells in view (drafted when they cost too much) and the next rough blocks to refine.
  std::vector<PixelRect> drafted;
  bool refining_blocks = false;
  if (all_invalid_) {
    regions.assign(1, {0, 0, viewport_w, viewport_h});
    stats.full = true;
    rough_.clear();
  } else {
    std::sort(dirty_tiles_.begin(), dirty_tiles_.end());
    dirty_tiles_.erase(std::unique(dirty_tiles_.begin(), dirty_tiles_.end()), dirty_tiles_.end());
    const int tiles_x = (renderer.width_cells() + kTileSize - 1) / kTileSize;
    render::relief::Reach reach = renderer.relief_reach();
    if (renderer.view_options().smooth_zoom) {
      // Zoomed in, a pixel blends its neighbour cells' shading: one cell more each way.
      for (int* side : {&reach.left, &reach.top, &reach.right, &reach.bottom}) ++*side;
    }
    std::vector<PixelRect> changed;
    for (int tile : dirty_tiles_) {
      const PixelRect rect = tile_screen_rect(tile, tiles_x, view, viewport_w, viewport_h, reach);
      if (!rect.empty()) changed.push_back(rect);
    }
    for (const paintcore::CellRect& cells : dirty_cells_) {
      const PixelRect rect = cells_screen_rect(cells, view, viewport_w, viewport_h, reach);
      if (!rect.empty()) changed.push_back(rect);
    }
    changed = fewer_passes(std::move(changed));
    stats.draft_factor = detail == Detail::kCoarse ? draft_factor_for(changed, renderer, view) : 0;
    if (stats.draft_factor > 0) {
      stats.pixels_shaded +=
          shade_draft(renderer, view, viewport_w, viewport_h, changed, stats.draft_factor, drafted);
      for (const PixelRect& r : drafted) rough_.mark(r);
    } else {
      regions.insert(regions.end(), changed.begin(), changed.end());
    }
    if (rough_.any() && detail == Detail::kRefining) {
      // The next rough blocks in reading order, as many as the refine budget allows, within
      // one row of blocks: one scissored pass.
      const double ms_per_pixel =
          fine_ms_per_pixel_ > 0.0 ? fine_ms_per_pixel_ : coarse_ms_per_pixel_ / kCoarsePixelCost;
      const int blocks_x = (viewport_w + kRefineBlock - 1) / kRefineBlock;
      // In double until clamped: a tiny measured cost would overflow an int.
      const double fit = ms_per_pixel > 0.0
                             ? refine_step_ms_ / (ms_per_pixel * kRefineBlock * kRefineBlock)
                             : blocks_x;
      regions.push_back(
          rough_.take_run(static_cast<int>(std::clamp(std::floor(fit), 1.0, 1.0 * blocks_x))));
      refining_blocks = true;
    }
    regions = fewer_passes(std::move(regions));
  }
  all_invalid_ = false;
  dirty_tiles_.clear();
  dirty_cells_.clear();

  const auto shade_regions = [&] {
    image_->bind();
    glEnable(GL_SCISSOR_TEST);
    for (const PixelRect& r : regions) {
      glScissor(r.x0, r.y0, r.x1 - r.x0, r.y1 - r.y0);
      renderer.draw(view, viewport_w, viewport_h);
      stats.pixels_shaded += r.area();
    }
    glDisable(GL_SCISSOR_TEST);
  };
  long long fine_pixels = 0;
  for (const PixelRect& r : regions) fine_pixels += r.area();
  if ((stats.full || refining_blocks) && fine_pixels > 0) {
    // Timed: the cost of a pixel predicts the coarse factor of the next motion's first frame
    // and the size of the next step of a refinement.
    stats.shade_ms = timed_gl_ms(shade_regions);
    fine_ms_per_pixel_ = stats.shade_ms / static_cast<double>(fine_pixels);
  } else if (detail == Detail::kCoarse && fine_pixels > 0) {
    // Timed while the canvas changes: the cost of a pixel decides whether the next changed
    // regions are drafted.
    changed_ms_per_pixel_ = timed_gl_ms(shade_regions) / static_cast<double>(fine_pixels);
  } else if (!regions.empty()) {
    shade_regions();
  }
  for (const PixelRect& r : regions) rough_.clear_covered(r);
  stats.regions = static_cast<int>(regions.size() + drafted.size());
  stats.refining = rough_.any();
  if (stats.shifted) {
    stats.changed.assign(1, {0, 0, viewport_w, viewport_h});
  } else {
    stats.changed = std::move(regions);
    stats.changed.insert(stats.changed.end(), drafted.begin(), drafted.end());
  }
  check_gl_error("cached canvas view");
  return stats;
}

}  // namespace impasto::render_gl
