#pragma once
// The canvas on the GPU: its cell data as textures, updated tile by tile, and the K-M
// shading pass that draws it through a CanvasView. Needs a current GL 3.3+ context.
#include <cstdint>
#include <memory>
#include <optional>
#include <span>
#include <vector>

#include "impasto/paintcore/canvas.hpp"
#include "impasto/render/dry_stack.hpp"
#include "impasto/render/relief_shading.hpp"
#include "impasto/render/render_settings.hpp"
#include "impasto/render/spectral_palette.hpp"
#include "impasto/render_gl/canvas_view.hpp"
#include "impasto/render_gl/crack_texture.hpp"
#include "impasto/render_gl/flake_textures.hpp"
#include "impasto/render_gl/fullscreen_pass.hpp"
#include "impasto/render_gl/ghs_surface_tables.hpp"
#include "impasto/render_gl/gpu_display_transform.hpp"
#include "impasto/render_gl/gpu_view_options.hpp"
#include "impasto/render_gl/subsurface_spread.hpp"
#include "impasto/render_gl/texture.hpp"
#include "impasto/render_gl/tile_atlas.hpp"

namespace impasto::render_gl {

class CanvasRenderer {
 public:
  // Allocates textures for a canvas of this size and compiles the shaders for the settings'
  // display encoding. Pigment i of the palette is painting slot i (as for the CPU's
  // render::TileRenderer). Throws std::runtime_error on invalid settings or GL failure.
  CanvasRenderer(int width_cells, int height_cells, const render::RenderSettings& settings,
                 render::SpectralPalette palette, GpuViewOptions options = {});
  ~CanvasRenderer();
  CanvasRenderer(const CanvasRenderer&) = delete;
  CanvasRenderer& operator=(const CanvasRenderer&) = delete;

  // New light, pigments, materials or display: call upload_all afterwards (the dry stack is
  // baked per node, so its reflectance changes with the light).
  void set_settings(const render::RenderSettings& settings, render::SpectralPalette palette);
  // Takes only what the shader reads as uniforms (light direction, ambient, materials,
  // gloss, Saunderson, cracks and their model) from `settings`: no re-bake, no upload (the
  // ghs surface's tables follow the light's elevation). For dragging the light. The surface
  // model, medium and varnish come with set_settings.
  void set_shading(const render::RenderSettings& settings);
  // Dry layer i is not shown where hidden[i] (colour only; heights keep every layer). Call
  // upload_all afterwards.
  void set_hidden_dry_layers(std::vector<bool> hidden) {
    hidden_dry_layers_ = std::move(hidden);
    dry_bakes_.clear();
  }
  // Exposure, background, the subsurface map's view: nothing to upload.
  void set_view_options(const GpuViewOptions& options);
  // How many cells spread light sideways now (the ghs surface with its subsurface spread).
  int subsurface_cells() const { return spread_->mapped_count(); }
  const render::RenderSettings& settings() const { return settings_; }
  const render::SpectralPalette& palette() const { return palette_; }
  const GpuViewOptions& view_options() const { return options_; }

  // Copies every tile of the canvas to the GPU (after load, resize or new inputs).
  void upload_all(const paintcore::Canvas& canvas);
  // Copies only these tiles (Painting::take_changes).
  void upload_tiles(const paintcore::Canvas& canvas, std::span<const int> tile_indices);
  // Makes room on the GPU for tiles strokes will paint: half as many again as hold paint, at
  // least kRoomTiles. Growing costs a frame (tens of ms a row on llvmpipe), so a window calls
  // this while the pen is up and the simulation idle, and strokes rarely wait for a growth.
  static constexpr int kRoomTiles = 256;
  void make_room();

  // How many tiles' dry stacks have been baked so far (a stroke changes only wet paint and
  // bakes none; a tile with no dry paint takes the ground's reflectance, no bake).
  std::uint64_t dry_tiles_baked() const { return dry_tiles_baked_; }
  // How many tiles hold paint or dry layers on the GPU (bare tiles take no texture memory),
  // and the bytes their textures take.
  int tiles_on_gpu() const { return tile_data_.places(); }
  std::size_t tile_data_bytes() const { return tile_data_.bytes(); }

  // Draws the shaded canvas into the bound framebuffer's viewport of the given size.
  void draw(const CanvasView& view, int viewport_w, int viewport_h);

  int width_cells() const { return width_; }
  int height_cells() const { return height_; }
  double cell_mm() const { return cell_mm_; }
  // How far beyond a changed tile the shading of cells reads its heights (normals,
  // occlusion, shadows), for the current settings and cell size, and the subsurface
  // spread's radius where it is on.
  render::relief::Reach relief_reach() const;

 private:
  struct TileScratch;
  void build_program();
  void allocate_textures();
  void upload_tile(const paintcore::Canvas& canvas, int tile_index, TileScratch& scratch);
  // A placed tile's pigments and (when its dry stack changed) its dry reflectance.
  void upload_tile_data(const paintcore::Tile* tile, const render::VisibleDryStack& dry,
                        int tile_index, int w, int h, TileScratch& scratch);
  // The canvas pass's uniforms and textures for `view` (the program in use).
  void set_uniforms(const CanvasView& view, int viewport_w, int viewport_h);
  bool spread_on() const;
  // Brings the spread's change up to date where cells changed (the body's light drawn there
  // first); keeps the caller's framebuffer, viewport and scissor.
  void update_spread();

  int width_, height_;
  double cell_mm_ = 0.1;
  render::RenderSettings settings_;
  render::SpectralPalette palette_;
  GpuViewOptions options_;
  std::vector<bool> hidden_dry_layers_;
  std::unique_ptr<GpuDisplayTransform> display_;
  std::unique_ptr<FullscreenPass> pass_;
  Texture surface_;  // wet volume, total height (mm), every cell (bare ones show the weave)
  // The tiles with paint or dry layers: ceil(slots / 4) layers of 4 slot amounts (mm), then
  // ceil(nodes / 4) layers of 4 node reflectances of the dry stack beneath the wet paint.
  // A bare tile has no place: no pigment, and the ground's reflectance (bare_reflectance_).
  TileAtlas tile_data_;
  std::vector<float> bare_reflectance_;  // per node, as a bake stores it
  // Per tile: the signature of the dry stack whose bake tile_data_ holds for today's
  // settings (render::DryStackSignature); none where it holds none.
  std::vector<std::optional<std::uint64_t>> dry_bakes_;
  std::uint64_t dry_tiles_baked_ = 0;
  int pigment_layers_ = 0, node_layers_ = 0;
  std::unique_ptr<FlakeTextures> flakes_;        // sparkles of flake pigments (nothing without)
  std::unique_ptr<CrackTexture> cracks_;         // crack optics per cell (nothing without cracks)
  std::unique_ptr<GhsSurfaceTables> ghs_;        // the ghs surface model (inactive for blinn)
  std::unique_ptr<GpuSubsurfaceSpread> spread_;  // the ghs surface's subsurface spread
  paintcore::CellRect spread_stale_;             // cells whose body or map changed
  paintcore::CellRect spread_written_;           // where the spread's change may be non-zero
  std::vector<float> tile_min_height_;           // each tile's lowest total height (mm)
  std::vector<float> tile_max_height_;           // each tile's highest total height (mm)
  float max_height_ = 0.0f;
  // The largest height range since the last upload_all: bounds the shadows' length (as
  // render::TileRenderer keeps it), of the heights now and of those an upload replaced.
  float height_range_ = 0.0f;
  void update_height_range(bool reset);
};

}  // namespace impasto::render_gl
