#pragma once
// The shaded canvas as a window shows it, kept between frames. A frame re-shades only the
// screen pixels that show something that changed — the cells the simulation dirtied (or
// whole tiles), grown by the rim whose shading reads their heights, and only in view —
// and copies the rest from the previous frame. A pan by whole pixels moves the cached image
// and shades only the strips it uncovers. What changes every pixel (zoom, rotation, a pan
// by a fraction of a pixel, the viewport size, the light, the look) re-shades the viewport
// once: while the view moves, coarsely, refined a few blocks a frame once it stops (Detail).
// While a stroke changes more than the draft budget can shade each frame, its regions are
// shaded as a draft, refined the same way once the canvas stops changing.
// The shading runs at
// screen resolution, so a zoomed-out view of a large canvas costs its pixels, not its cells.
#include <array>
#include <memory>
#include <span>
#include <vector>

#include "impasto/render_gl/canvas_renderer.hpp"
#include "impasto/render_gl/canvas_view.hpp"
#include "impasto/render_gl/framebuffer.hpp"
#include "impasto/render_gl/pixel_rect.hpp"
#include "impasto/render_gl/rough_blocks.hpp"

namespace impasto::render_gl {

// What one draw did.
struct CachedDrawStats {
  long long pixels_shaded = 0;  // pixels the K-M pass ran for
  int regions = 0;              // scissored passes (0: nothing changed in view)
  bool full = false;            // the whole viewport was re-shaded
  bool shifted = false;         // the cached image was moved (a pan by whole pixels)
  bool coarse = false;          // the whole viewport was shaded coarsely (Detail::kCoarse)
  int coarse_factor = 0;        // its pixels' size in viewport pixels each way (0: not coarse)
  double shade_ms = 0.0;        // a whole-viewport pass or a refining step: its shading's GL time
  int draft_factor = 0;         // the changed regions were drafted at 1/factor (0: shaded finely)
  bool refining = false;  // the image still has coarse or draft parts, which kRefining refines
  // The viewport pixels whose cached image changed: the shaded regions, or the whole
  // viewport after a shift. A window that keeps its last frame re-presents only these.
  std::vector<PixelRect> changed;
};

// The pixels of a viewport that show any of tile `tile_index`'s cells or the rim around
// them whose shading reads the tile's heights (`reach`: the normals' one cell, occlusion
// and shadows), clipped to the viewport (empty when out of view). Conservative by a pixel.
PixelRect tile_screen_rect(int tile_index, int tiles_x, const CanvasView& view, int viewport_w,
                           int viewport_h, render::relief::Reach reach = {});
// The same for any box of cells.
PixelRect cells_screen_rect(const paintcore::CellRect& cells, const CanvasView& view,
                            int viewport_w, int viewport_h, render::relief::Reach reach = {});

class ShadedViewCache {
 public:
  // How update() re-shades the whole viewport when it must (a zoom, rotation, light): kFull
  // at every pixel, or kCoarse at 1/factor of the resolution each way, magnified, for the
  // first frames of a motion. The factor is the smallest from kMinCoarseFactor up whose
  // shading the measured cost of the last whole-viewport pass predicts within the coarse
  // budget, so a slow machine (llvmpipe, a loaded CPU) still shows a motion's first frame in
  // time. The next kFull update() after a coarse one re-shades the viewport at every pixel.
  //
  // kCoarse is also for while the canvas changes (a stroke): changed regions whose shading the
  // measured cost of a pixel predicts over the draft budget (set_draft_budget_ms) are shaded
  // as a draft instead — one cell a pixel (smooth zoom off) at 1/factor of the resolution,
  // magnified, the factor the smallest that fits from 1 (zoomed out, where smooth zoom
  // averages many cells a pixel) or 2 up to kMaxDraftFactor.
  //
  // kRefining refines the coarse and draft parts of the image a few kRefineBlock-square
  // blocks a call, in reading order from the top, as many as the measured cost of a pixel
  // fits in kRefineStepMs (set_refine_step_ms), so the window answers input between them (a
  // wheel click waits for one call, not the whole re-shade); the image is the same as
  // kFull's once `refining` is false. Otherwise it is kFull. Blocks, not thin bands of rows:
  // llvmpipe shades in 64-pixel square tiles, and a band a few rows high cost it 2-5 times as
  // much a pixel. 32 pixels, not 64: zoomed out over a large canvas (16 cells a pixel) a 64-pixel
  // block took 70 ms on llvmpipe, and a stroke begun meanwhile waited for it.
  enum class Detail { kFull, kCoarse, kRefining };
  static constexpr double kRefineStepMs = 25.0;
  static constexpr int kRefineBlock = 32;
  static constexpr int kMinCoarseFactor = 4;
  static constexpr int kMaxCoarseFactor = 16;
  // The coarse pass's shading budget, of the 100 ms a motion's first frame may take: in a
  // 1400×900 window on llvmpipe the rest costs 35-50 ms (magnifying 10, the panels and the
  // present 15, waiting for the refinement's pass under way up to 25), and the prediction
  // misses by a third either way on a loaded machine.
  static constexpr double kDefaultCoarseBudgetMs = 40.0;
  // Until a coarse pass has been timed, a coarse pixel is taken to cost this many fine ones:
  // its texel reads lie several cells apart, and the fine figure is diluted by the cheap
  // background around a fitted canvas (on llvmpipe 1.2-2: `impasto bench gpu`).
  static constexpr double kCoarsePixelCost = 2.0;
  // A stroke's frame on llvmpipe (1400×900, two cores) leaves its shading about this much of
  // the 30 ms from the pen to the screen: the simulation, the upload, the panels and the
  // present take the rest, and a frame already under way when the pen moves is waited for.
  static constexpr double kDefaultDraftBudgetMs = 4.0;
  static constexpr int kMaxDraftFactor = 4;

  // The factor (kMinCoarseFactor..kMaxCoarseFactor) for a viewport_w × viewport_h viewport
  // whose pixels are predicted to cost ms_per_pixel each when shaded coarsely: the smallest
  // whose shading fits budget_ms, or the largest. An unknown cost (≤ 0) takes the smallest.
  static int coarse_factor_for(double ms_per_pixel, int viewport_w, int viewport_h,
                               double budget_ms);
  void set_coarse_budget_ms(double budget_ms) { coarse_budget_ms_ = budget_ms; }
  void set_refine_step_ms(double step_ms) { refine_step_ms_ = step_ms; }
  // At most 0: every changed region of a kCoarse update is drafted at kMaxDraftFactor.
  void set_draft_budget_ms(double budget_ms) { draft_budget_ms_ = budget_ms; }
  // The factor the next coarse pass on this viewport would take.
  int next_coarse_factor(int viewport_w, int viewport_h) const;

  // The tiles changed on the GPU (after CanvasRenderer::upload_tiles with the same list).
  void invalidate_tiles(std::span<const int> tiles);
  // Only these cells changed (Painting::take_changes, after uploading their tiles): a
  // brush moving a few cells a frame re-shades those cells and the rim their relief reaches,
  // not whole tiles.
  void invalidate_cells(std::span<const paintcore::DirtyTile> changed);
  // Everything changed (a full upload, new settings, a new renderer).
  void invalidate_all() { all_invalid_ = true; }
  // Everything changed a little (a full upload whose colours differ from the last by a
  // fraction of a step, as when a palette's own wavelength rule replaces its stand-in): the
  // image stays and every block is refined, a few a frame (kRefining), as after a coarse pass,
  // so no frame waits for a whole re-shade. Before the first update, as invalidate_all().
  void refine_all() { rough_.mark_all(); }

  // Brings the cached image up to date for `view` on a viewport_w × viewport_h viewport and
  // copies it into the framebuffer `target` (0: the window's). The shading uniforms are taken
  // from `renderer` as they are now: a change of light direction, ambient, materials or
  // view options re-shades everything.
  CachedDrawStats draw(CanvasRenderer& renderer, const CanvasView& view, int viewport_w,
                       int viewport_h, GLuint target);
  // draw() in two steps: bring the cached image up to date, then copy any part of it (in
  // the viewport's GL pixels) into the framebuffer `target`.
  CachedDrawStats update(CanvasRenderer& renderer, const CanvasView& view, int viewport_w,
                         int viewport_h, Detail detail = Detail::kFull);
  void copy_to(GLuint target, const PixelRect& rect) const;

 private:
  // Everything a pixel's colour depends on beside the canvas data and the view's centre.
  std::vector<double> look_of(const CanvasRenderer& renderer, const CanvasView& view) const;
  // Moves the cached image by (dx, dy) GL pixels; returns the strips left to shade.
  std::vector<PixelRect> shift_image(int dx, int dy);
  // Shades the whole viewport at 1/factor resolution into image_; returns the pixels shaded
  // and the shading's time in shade_ms.
  long long shade_coarse(CanvasRenderer& renderer, const CanvasView& view, int viewport_w,
                         int viewport_h, int factor, double& shade_ms);
  // The factor to draft `regions` at this frame (0: shade them finely).
  int draft_factor_for(std::span<const PixelRect> regions, const CanvasRenderer& renderer,
                       const CanvasView& view) const;
  // Shades `regions` as a draft at 1/factor into image_; returns the pixels shaded and, in
  // `drafted`, the image's rectangles it wrote.
  long long shade_draft(CanvasRenderer& renderer, const CanvasView& view, int viewport_w,
                        int viewport_h, std::span<const PixelRect> regions, int factor,
                        std::vector<PixelRect>& drafted);

  std::unique_ptr<Framebuffer> image_;
  std::unique_ptr<Framebuffer> spare_;  // the target of a shift, then swapped with image_
  std::unique_ptr<Framebuffer> coarse_image_;
  std::unique_ptr<Framebuffer> draft_image_;
  RoughBlocks rough_;  // image_'s blocks that show a coarse or draft shading, to refine
  double coarse_budget_ms_ = kDefaultCoarseBudgetMs;
  double refine_step_ms_ = kRefineStepMs;
  double draft_budget_ms_ = kDefaultDraftBudgetMs;
  // The measured cost of a pixel of the last whole-viewport pass, fine and coarse (0: none).
  double fine_ms_per_pixel_ = 0.0;
  double coarse_ms_per_pixel_ = 0.0;
  // The same of the last changed regions shaded finely and of the last draft (0: none).
  double changed_ms_per_pixel_ = 0.0;
  double draft_ms_per_pixel_ = 0.0;
  const CanvasRenderer* renderer_ = nullptr;
  std::vector<double> look_;
  CanvasView view_;
  bool all_invalid_ = true;
  std::vector<int> dirty_tiles_;
  std::vector<paintcore::CellRect> dirty_cells_;
};

}  // namespace impasto::render_gl
