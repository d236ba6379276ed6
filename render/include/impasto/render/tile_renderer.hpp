#pragma once
// The CPU reference renderer of a canvas, tile by tile (64×64 cells), in parallel with TBB.
// Per cell: the wet layer composited (K-M) over the dry stack, which is baked once per light
// into a reflectance per node, over the canvas ground; shaded from the total height; XYZ to
// the display through OpenColorIO. Results do not depend on the thread count.
#include <cstdint>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include "impasto/paintcore/canvas.hpp"
#include "impasto/render/display.hpp"
#include "impasto/render/image.hpp"
#include "impasto/render/relief_shading.hpp"
#include "impasto/render/render_settings.hpp"
#include "impasto/render/spectral_palette.hpp"
#include "impasto/util/progress.hpp"

namespace impasto::render {

class FlakeShading;
class FlakeTileView;
namespace kernels {
struct PaddedPalette;
}
class SurfaceShading;

// What one update() did.
struct RenderStats {
  int tiles_shaded = 0;  // tiles whose every cell was re-shaded
  int tiles_baked = 0;   // tiles whose dry stack was re-baked
  int border_cells = 0;  // cells of unchanged neighbours re-shaded: their relief read changes
};

class TileRenderer {
 public:
  // Pigment i of the palette is the painting's pigment slot i.
  TileRenderer(const RenderSettings& settings, SpectralPalette palette);
  // The palette from the default pigment database and settings.light.
  TileRenderer(const RenderSettings& settings, std::span<const std::string> pigment_slots);
  ~TileRenderer();
  TileRenderer(TileRenderer&&) noexcept;
  TileRenderer& operator=(TileRenderer&&) noexcept;

  const RenderSettings& settings() const { return settings_; }
  const SpectralPalette& palette() const { return palette_; }

  // New settings (light, wavelengths, shading, ...): everything is re-baked and re-shaded at
  // the next update. The palette is rebuilt for the same pigment names.
  void set_settings(const RenderSettings& settings);
  // New settings with a palette built by the caller (explicit spectra).
  void set_settings(const RenderSettings& settings, SpectralPalette palette);

  // Brings the image up to date with `canvas`. The first call after construction, a settings
  // change or a canvas of another size renders every tile; later calls re-shade only
  // `changed_tiles` (from Painting::take_changes) and the rims of their neighbours whose
  // normals, occlusion or shadows read the changed heights (relief::reach). A changed tile's dry
  // stack is re-baked only when its dry layers differ from those it was baked from.
  RenderStats update(const paintcore::Canvas& canvas, std::span<const int> changed_tiles);
  // Renders every tile (a relight).
  // progress, when given, hears of each tile shaded (from the worker threads).
  RenderStats render_all(const paintcore::Canvas& canvas,
                         const util::ProgressCallback& progress = {});

  // The display-encoded (or linear, per settings.display) RGB of the whole canvas.
  Image image() const;
  // The per-cell scalar code (kubelka_munk_cell.hpp, one node at a time) instead of the spectral
  // kernels (structure-of-arrays over the nodes, SIMD): the reference the kernels are tested
  // against. Takes effect at the next render_all.
  void use_reference_kernels(bool reference) {
    reference_kernels_ = reference;
    needs_full_render_ = true;
  }
  // How many times each tile has been fully shaded since construction (tests, profiling).
  std::uint64_t shade_count(int tile_index) const;
  // How many cells of a tile the flake-paint hook has looked at since construction: zero for
  // a tile that never held flake pigment (its check is once per tile, no per-cell work).
  std::uint64_t flake_cell_count(int tile_index) const;

 private:
  struct TileCache;
  void reset_caches(const paintcore::Canvas& canvas);
  // may_reuse_shading: the heights and the shading settings are those the tile's cached
  // shading factors were computed with (a relight).
  void shade_region(const paintcore::Canvas& canvas, int tile_index, int x0, int y0, int x1, int y1,
                    TileCache& cache, bool may_reuse_shading) const;
  // The two ways shade_region shades: the spectral kernels a row at a time with cached shading
  // factors, or a cell at a time (the reference, cracks, the ghs surface model).
  struct RegionShading;
  struct CellLight;
  void shade_with_kernels(const RegionShading& region, TileCache& cache, FlakeTileView& flakes,
                          bool may_reuse_shading) const;
  void shade_cell_by_cell(const RegionShading& region, TileCache& cache,
                          FlakeTileView& flakes) const;
  CellLight light_at(const RegionShading& region, int gx, int gy, float wet_volume) const;
  void display_rows(const RegionShading& region, int y, TileCache& cache) const;
  // Returns whether any height of the tile changed.
  bool store_heights(const paintcore::Canvas& canvas, int tile_index);
  // Everything besides the heights and wet paint that the shading factors depend on.
  std::vector<double> shading_key() const;
  bool fast_kernels() const { return !reference_kernels_ && palette_.nodes() <= kMaxNodes; }
  void bake_dry_stack(const paintcore::Canvas& canvas, int tile_index, TileCache& cache) const;
  template <typename Work>
  void run_parallel(std::size_t count, const Work& work) const;

  RenderSettings settings_;
  SpectralPalette palette_;
  std::unique_ptr<DisplayTransform> display_;
  std::unique_ptr<FlakeShading> flakes_;           // null when no pigment of the palette has flakes
  std::unique_ptr<kernels::PaddedPalette> lanes_;  // the palette laid out for the kernels
  bool reference_kernels_ = false;
  std::vector<double> shading_key_;          // shading_key() when the cached shading was computed
  std::unique_ptr<SurfaceShading> surface_;  // null for the Blinn-Phong surface model
  int width_ = 0, height_ = 0, tiles_x_ = 0, tiles_y_ = 0;
  double cell_mm_ = 0.0;
  std::uint64_t weave_seed_ = 0;  // the bare canvas's heights (the weave) depend on it
  bool needs_full_render_ = true;
  std::vector<TileCache> tiles_;
  // The total height of every cell (row-major), each tile's lowest and highest: what the
  // normals, shadows and occlusion read across tile boundaries.
  std::vector<float> heights_;
  std::vector<float> tile_min_height_, tile_max_height_;
  float max_height_ = 0.0f;
  // The largest height range since the last full render: it bounds the shadows' length, of
  // the heights now and of those an update replaced (whose shadows must be re-shaded away).
  float height_range_ = 0.0f;
  relief::ReliefParams relief_;
  void update_height_range(bool reset);
};

}  // namespace impasto::render
