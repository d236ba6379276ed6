#include "window/canvas_viewer.hpp"

#include <impasto/render/node_cache.hpp>

#include <algorithm>
#include <chrono>
#include <span>

namespace impasto::app::window {
namespace {

// How long the view and the light stay still before a coarse view is refined.
constexpr double kRefineAfter_s = 0.3;

}  // namespace

CanvasViewer::CanvasViewer(session::SimWorker& worker) : changes_(worker.subscribe_changes()) {}

void CanvasViewer::sync(session::SimWorker& worker, WindowState& state, bool in_stroke,
                        double now_s) {
  const auto start = std::chrono::steady_clock::now();
  worker.with_changes(changes_, [&](const paintcore::Painting& painting,
                                    std::span<const paintcore::DirtyTile> changed) {
    const paintcore::Canvas& canvas = painting.canvas();
    const bool resized =
        canvas.width_cells() != width_cells_ || canvas.height_cells() != height_cells_;
    const bool slots_changed = painting.pigment_slots() != rendered_slots_;
    // The palette's trained rule, built in the background, is ready: it takes over.
    const bool rule_ready =
        palette_stands_in_ && !in_stroke && render::palette_rules_finished() != rules_finished_;
    if (resized || slots_changed || state.settings_changed || !palette_ || rule_ready) {
      rules_finished_ = render::palette_rules_finished();
      const render::BackgroundPaletteRules background;  // no frame waits for a rule's build
      palette_ =
          std::make_unique<render::SpectralPalette>(state.settings, painting);  // its pigments
      palette_stands_in_ = background.stood_in();
      rendered_slots_ = painting.pigment_slots();
      if (resized || !renderer_) {
        renderer_ = std::make_unique<render_gl::CanvasRenderer>(
            canvas.width_cells(), canvas.height_cells(), state.settings, *palette_,
            state.view_options);
        width_cells_ = canvas.width_cells();
        height_cells_ = canvas.height_cells();
        state.fit_requested = true;
      } else {
        renderer_->set_settings(state.settings, *palette_);
      }
      // A new canvas: no hand moves while it is shaded, so it is shaded whole. A pigment the
      // user just loaded, or a setting the user changed, is answered at once, coarsely, and
      // refined as a motion is: shaded whole, the view took 2.4 s on llvmpipe (1000 x 700),
      // and the stroke begun after the chip click waited for it. The palette's own rule,
      // arriving alone, changes the colours by a fraction of a step: the view keeps its image
      // and refines it block by block, neither blurred nor frozen.
      shade_whole_ = shade_whole_ || resized;
      const bool hand = slots_changed || state.settings_changed;
      if (!resized && hand) look_changed_s_ = now_s;
      refine_upload_ = rule_ready && !resized && !hand;
      state.settings_changed = false;
      state.mix_changed = true;  // the swatch depends on the light
      full_upload_ = true;
    }
    if (state.visibility_changed) {
      renderer_->set_hidden_dry_layers(state.hidden_dry_layers);
      state.visibility_changed = false;
      full_upload_ = true;
      refine_upload_ = false;  // layers shown or hidden: a change the user waits to see
    }
    const std::vector<int> dirty = paintcore::tile_indices(changed);
    if (full_upload_) {
      renderer_->upload_all(canvas);
      if (refine_upload_)
        cache_.refine_all();
      else
        cache_.invalidate_all();
      refine_upload_ = false;
      state.tiles_uploaded += canvas.tile_count();
      full_upload_ = false;
    } else {
      renderer_->upload_tiles(canvas, dirty);
      cache_.invalidate_cells(changed);  // only the cells changed, not whole tiles
      if (!changed.empty()) canvas_changed_s_ = now_s;
      state.tiles_uploaded += static_cast<long long>(dirty.size());
    }
  });
  state.upload_ms =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
}

render_gl::CachedDrawStats CanvasViewer::shade(const WindowState& state,
                                               const render_gl::CanvasView& view, int fb_w,
                                               int fb_h, bool whole, bool in_stroke, double now_s,
                                               double tip_down_s) {
  renderer_->set_view_options(state.view_options);
  renderer_->set_shading(state.settings);
  const std::array<double, 6> motion = {view.center_x_cells,
                                        view.center_y_cells,
                                        view.pixels_per_cell,
                                        view.rotation_rad,
                                        state.settings.light_azimuth_deg,
                                        state.settings.light_elevation_deg};
  if (motion != last_motion_) last_motion_s_ = now_s;
  last_motion_ = motion;
  using Detail = render_gl::ShadedViewCache::Detail;
  // A stroke that changes nothing in view (an empty brush) is not kept waiting either.
  const double still_s =
      now_s - std::max({last_motion_s_, canvas_changed_s_, look_changed_s_, tip_down_s});
  whole = whole || (shade_whole_ && !in_stroke);
  const Detail detail = whole                      ? Detail::kFull
                        : still_s < kRefineAfter_s ? Detail::kCoarse
                                                   : Detail::kRefining;
  if (whole) shade_whole_ = false;
  return cache_.update(*renderer_, view, fb_w, fb_h, detail);
}

void CanvasViewer::set_moving(bool moving) {
  using Cache = render_gl::ShadedViewCache;
  cache_.set_coarse_budget_ms(Cache::kDefaultCoarseBudgetMs / (moving ? 2.0 : 1.0));
}

void CanvasViewer::painting_replaced() {
  rendered_slots_.clear();
  width_cells_ = height_cells_ = 0;
}

void CanvasViewer::make_room() {
  if (renderer_) renderer_->make_room();
}

}  // namespace impasto::app::window
