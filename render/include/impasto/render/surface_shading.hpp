#pragma once
// The tile renderer's cell shading when the surface model is ghs (surface_settings.hpp):
// per wavelength node, the rough surface's reflection (surface_brdf.hpp) of the direct light
// and of the sky, plus the K-M body lit by what the surface lets through, to XYZ. Built once
// per settings and palette (its BRDF tables are shared between renderers); shade() is
// thread-safe. docs/surface.md derives the terms.
#include <array>
#include <memory>
#include <vector>

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

  // The surface of one node (dry: the varnish's when varnished, else the medium's; wet).
  const surface::GhsBrdf& dry_brdf(int node) const { return *dry_[static_cast<std::size_t>(node)]; }
  const surface::GhsBrdf& wet_brdf(int node) const { return *wet_[static_cast<std::size_t>(node)]; }

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
};

}  // namespace impasto::render
