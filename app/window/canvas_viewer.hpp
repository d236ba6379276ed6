#pragma once
// The canvas viewer: the painting's copy on the GPU and its shaded view. Each frame it takes
// what the simulation changed (its own change subscription) and uploads it, makes the palette
// and the renderer again when the canvas, its pigments, the light or the palette's trained
// rule change, and shades the view at the detail the view's motion and the strokes allow
// (render_gl::ShadedViewCache). The window presents what it shaded.
#include <impasto/render/spectral_palette.hpp>
#include <impasto/render_gl/canvas_renderer.hpp>
#include <impasto/render_gl/shaded_view_cache.hpp>

#include <array>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "impasto/session/sim_worker.hpp"
#include "window/window_state.hpp"

namespace impasto::app::window {

class CanvasViewer {
 public:
  // Subscribes to the worker's painting's changes (the subscription outlives a replaced
  // painting: the next frame uploads the new one whole).
  explicit CanvasViewer(session::SimWorker& worker);

  // Brings the GPU's copy up to date: every tile after a new painting, light or slot table,
  // otherwise only what changed since the last frame. Reads state's settings and hidden dry
  // layers; asks for a fit of a new canvas (state.fit_requested); counts the upload.
  // `in_stroke`: the palette's trained rule waits for the pen to lift rather than re-shade
  // under it.
  void sync(session::SimWorker& worker, WindowState& state, bool in_stroke, double now_s);

  // Shades `view` (framebuffer pixels) into the view's cache: whole when asked (a screenshot)
  // or when the canvas changed by no hand (opened, fitted, the rule arrived) and no stroke is
  // drawing; coarsely while the view or the light moves or a stroke changes the canvas;
  // refined block by block once all have been still for kRefineAfter_s.
  render_gl::CachedDrawStats shade(const WindowState& state, const render_gl::CanvasView& view,
                                   int fb_w, int fb_h, bool whole, bool in_stroke, double now_s,
                                   double tip_down_s);
  // Copies the shaded view's `rect` into `framebuffer` (0: the window's).
  void copy_to(unsigned framebuffer, const render_gl::PixelRect& rect) {
    cache_.copy_to(framebuffer, rect);
  }
  // While a motion goes on, a coarse pass gets half the budget (a drag's next move waits for
  // the frame being drawn, then for its own).
  void set_moving(bool moving);

  // The painting was replaced (new, open, recovered, reframed): new textures, fit the canvas.
  void painting_replaced();
  // Pen up and nothing to simulate: the GPU makes room for the next strokes' tiles.
  void make_room();

  const render::SpectralPalette& palette() const { return *palette_; }
  // The wavelength rule the canvas is shaded with; null before the first sync.
  const render::SpectralSampling* rule() const {
    return palette_ ? &palette_->sampling() : nullptr;
  }
  // The Gaussian rule stands in while the palette's own is built.
  bool palette_stands_in() const { return palette_stands_in_; }
  int width_cells() const { return width_cells_; }
  int height_cells() const { return height_cells_; }
  double cell_mm() const { return renderer_ ? renderer_->cell_mm() : 0.1; }

 private:
  paintcore::Painting::ChangeSubscriber changes_;
  std::unique_ptr<render_gl::CanvasRenderer> renderer_;
  render_gl::ShadedViewCache cache_;  // frames re-shade only what changed in view
  std::unique_ptr<render::SpectralPalette> palette_;
  bool palette_stands_in_ = false;
  std::uint64_t rules_finished_ = 0;  // render::palette_rules_finished() when it was made
  std::vector<std::string> rendered_slots_;
  int width_cells_ = 0, height_cells_ = 0;
  bool full_upload_ = true;
  bool refine_upload_ = false;  // the full upload changed the colours a little: refine the view
  // The view must be shaded whole, not coarsely, at the next frame that no stroke is drawing:
  // it changed by no hand (the window opened on a painting and fitted it, the palette's own
  // rule arrived), so no motion waits on it, and a coarse frame refined block by block over
  // seconds read as a blotchy, broken first look.
  bool shade_whole_ = true;
  std::array<double, 6> last_motion_{};  // the view and the light at the last frame
  double last_motion_s_ = -1e9;          // when they last changed
  double canvas_changed_s_ = -1e9;       // when the last upload had changed cells
  double look_changed_s_ = -1e9;         // when the user last changed the pigments or the settings
};

}  // namespace impasto::app::window
