#pragma once
// The tile renderer's cell shading when the surface model is ghs (surface_settings.hpp):
// per wavelength node, the rough surface's reflection (surface_brdf.hpp) of the direct light
// and of the sky, plus the K-M body lit by what the surface lets through, to XYZ. Built once
// per settings and palette (its BRDF tables are shared between renderers); shade() is
// thread-safe. docs/surface.md derives the terms.
#include <array>
#include <memory>
#include <mutex>
#include <vector>

#include "impasto/paintcore/paint_surface.hpp"
#include "impasto/render/render_settings.hpp"
#include "impasto/render/shading.hpp"
#include "impasto/render/spectral_palette.hpp"
#include "impasto/render/surface_brdf.hpp"

namespace impasto::render {

class SurfaceShading {
 public:
  // Null for the blinn model: the renderer keeps its Blinn-Phong path untouched.
  static std::unique_ptr<SurfaceShading> create(const RenderSettings& settings,
                                                const SpectralPalette& palette);
  SurfaceShading(const RenderSettings& settings, const SpectralPalette& palette);

  // One cell: its node reflectances (K-M, over everything beneath) under the light from
  // to_light, seen from straight above, on a surface with this normal, wet by `wetness`
  // (0 dry .. 1 fully wet, blended as Blinn-Phong's materials are); writes display XYZ.
  void shade(shade::Vec3 normal, shade::Vec3 to_light, shade::Visibility visibility, float wetness,
             const float* reflectance, float xyz[3]) const;
  // The same on the cell's own surface (paintcore::cell_surface): where the painting varnished
  // the cell, its varnish (glossy while wet); else the settings' varnish if any; else the
  // medium of the cell's paint, its share mixed in log RMS with the settings' medium; a cell
  // with neither shades exactly as above (old paintings render as before, bit for bit).
  void shade(shade::Vec3 normal, shade::Vec3 to_light, shade::Visibility visibility, float wetness,
             const paintcore::CellSurface& cell, const float* reflectance, float xyz[3]) const;

  // The dry surfaces a painting's cells use: log10 RMS quantised to kLevelStep (the BRDF
  // tables of a level are made the first time a cell needs them, ~20 ms a node).
  static constexpr double kLevelStep = 0.1;
  static constexpr int kLevels =
      static_cast<int>((paintcore::kMaxLogRms - paintcore::kMinLogRms) / kLevelStep) + 1;
  static int level_of(double log_rms);
  static double level_log_rms(int level);

  // Which dry surface a cell shades on (the choice shade(..., cell, ...) makes; the GPU port
  // makes it per cell the same way): the settings' own (level -1: dry_brdf), or a level of
  // paint or of varnish; and the least wetness the cell has (a varnish not yet dry).
  struct CellDry {
    bool varnish = false;
    int level = -1;
    float min_wetness = 0.0f;
  };
  CellDry cell_dry(const paintcore::CellSurface& cell) const;
  // The tables of a level, one a node: for the paint (binder index) or a varnish (varnish
  // index); made the first time they are asked for.
  using Brdfs = std::vector<std::shared_ptr<const surface::GhsBrdf>>;
  const Brdfs& level_brdfs(bool varnish, int level) const;

  // The surface of one node (dry: the varnish's when varnished, else the medium's; wet).
  const surface::GhsBrdf& dry_brdf(int node) const { return *dry_[static_cast<std::size_t>(node)]; }
  const surface::GhsBrdf& wet_brdf(int node) const { return *wet_[static_cast<std::size_t>(node)]; }
  // What the body is divided by at that node (see reference_ below): the GPU port reads it.
  float reference(int node) const { return reference_[static_cast<std::size_t>(node)]; }
  float reference_sky(int node) const { return reference_sky_[static_cast<std::size_t>(node)]; }
  bool reflection() const { return reflection_; }

 private:
  int nodes_;
  std::array<std::vector<float>, 3> to_xyz_;  // the palette's node weights to display XYZ
  float ambient_;
  bool reflection_;
  std::vector<std::shared_ptr<const surface::GhsBrdf>> dry_, wet_;
  // The smooth binder's transmittance where the K-M data were taken (light at the flat
  // canvas's elevation, viewer above, sky), per node: the body is divided by it, so a flat
  // smooth canvas shows its K-M reflectance as the Blinn-Phong path does.
  std::vector<float> reference_;      // t0(flat light) · t0(view)
  std::vector<float> reference_sky_;  // t̄0 · t0(view)

  void shade_on(const Brdfs& dry, shade::Vec3 normal, shade::Vec3 to_light,
                shade::Visibility visibility, float wetness, const float* reflectance,
                float xyz[3]) const;
  std::vector<double> wavelengths_;
  double source_sigma_ = 0.0;
  double subcell_slope_rms_ = 0.0;
  double binder_index_ = 1.48, varnish_index_ = 1.53;
  bool settings_varnish_ = false;  // the settings' varnish covers every cell
  double default_log_rms_ = 0.0;   // the settings' medium
  mutable std::array<std::once_flag, 2 * kLevels> level_made_;
  mutable std::array<Brdfs, 2 * kLevels> levels_;
};

}  // namespace impasto::render
