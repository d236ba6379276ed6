#pragma once
// The subsurface spread on the GPU (docs/surface.md, "The spread on the GPU"): the map of
// render::subsurface_map as per-cell kernel indices, the kernels of render::spread_kernel in
// an atlas, and the gather pass that turns the body's light into the spread's change
// (spread(body) − body, as render::apply_spread adds it). The canvas pass adds that change
// to each cell's light. Until a cell spreads, every texture is a single texel: a painting
// without glazes costs nothing. Needs a current GL 3.3+ context.
#include <map>
#include <memory>
#include <string>
#include <tuple>
#include <vector>

#include "impasto/paintcore/canvas.hpp"
#include "impasto/render/subsurface.hpp"
#include "impasto/render_gl/framebuffer.hpp"
#include "impasto/render_gl/fullscreen_pass.hpp"
#include "impasto/render_gl/texture.hpp"

namespace impasto::render_gl {

class GpuSubsurfaceSpread {
 public:
  // Texture units the canvas pass reads the change and the map's lengths from.
  static constexpr int kDeltaUnit = 7, kLengthsUnit = 8;

  GpuSubsurfaceSpread(int width_cells, int height_cells);
  ~GpuSubsurfaceSpread();
  GpuSubsurfaceSpread(const GpuSubsurfaceSpread&) = delete;
  GpuSubsurfaceSpread& operator=(const GpuSubsurfaceSpread&) = delete;

  // GLSL for the canvas pass (after the display function): subsurface_light, canvas_output.
  static std::string canvas_glsl();

  // Replaces the map inside `region` (cells) by `map`'s cells there; `map` covers the canvas.
  void set_cells(const paintcore::CellRect& region, const render::SubsurfaceMap& map);
  // No cell spreads (new settings: the kernels change with the palette and the cell size).
  void clear();
  bool empty() const { return mapped_count_ == 0; }
  int mapped_count() const { return mapped_count_; }
  // The largest kernel radius since clear() (cells): how far a change of body spreads.
  int radius() const { return radius_; }
  // The box of the mapped cells (empty when none).
  paintcore::CellRect mapped_box() const;

  // The target the canvas pass draws the body's linear light into (one pixel a cell, GL rows
  // bottom-up), made at the canvas's size on first use.
  Framebuffer& body();
  // Recomputes the change over `cells` from body(). Binds its own target, program and
  // scissor: the caller restores its state.
  void spread(const paintcore::CellRect& cells);

  // Points the canvas pass's samplers at the change and the lengths (units kDeltaUnit and
  // kLengthsUnit) and sets its spread uniforms. The program must be in use.
  void bind(const ShaderProgram& canvas_program, bool enabled, bool map_view) const;

 private:
  using KernelKey = std::tuple<double, double, double, float>;
  int kernel_id(const render::dipole::Medium& medium, float layer_mm, double cell_mm);
  void allocate_cell_textures();
  // Remakes the gather's radius of the blocks [bx0, bx1) x [by0, by1) and their neighbours.
  void update_block_radius(int bx0, int by0, int bx1, int by1);

  int width_, height_;
  double cell_mm_ = 0.0;
  std::map<KernelKey, int> kernel_ids_;
  std::vector<int> kernel_radius_;
  std::vector<float> atlas_texels_;  // RG per texel, kAtlasColumns blocks a row
  int atlas_rows_ = 0;               // rows of blocks the atlas texture holds
  bool atlas_stale_ = false;
  int radius_ = 0;
  std::vector<std::uint8_t> mapped_;  // per cell: its largest kernel radius, 0: not mapped
  std::vector<std::uint8_t> own_block_radius_;  // per block: the largest radius in it
  int mapped_count_ = 0;
  Texture ids_;           // RGBA32F: kernel + 1 per channel (0: none)
  Texture lengths_;       // RGBA32F: spread lengths (cells), for the map's view
  Texture atlas_;         // RG32F: kernel weights and their prefix sums
  Texture block_radius_;  // R32F per block: the largest radius that reaches it
  std::unique_ptr<Framebuffer> body_;
  std::unique_ptr<Framebuffer> delta_;
  Texture blank_;  // one zero texel, bound while nothing spreads
  std::unique_ptr<FullscreenPass> pass_;
};

}  // namespace impasto::render_gl
