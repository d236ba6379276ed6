#pragma once
// A pigment's concentration in its layer: amount / volume (given as 1 / volume), at most
// kMaxConcentration. A cell's pigment is part of its paint, so real mixes stay at or below 1
// (up to rounding) and are untouched; a degenerate cell (a denormal volume, more pigment than
// paint) would otherwise reach Kubelka-Munk as Inf and render NaN.
inline constexpr float kMaxConcentration = 4.0f;
inline float pigment_concentration(float amount, float inverse_volume) {
  return std::min(amount * inverse_volume, kMaxConcentration);
}

// One paint layer of a cell composited over what lies beneath it, at every wavelength node:
// stages 1–3 of IMPaSTo Fig. 6 for a whole cell. Inline so the tile renderer, the colour
// benchmark and the tests run the very same code.
#include <algorithm>
#include <span>

#include "impasto/render/kubelka_munk_cell.hpp"
#include "impasto/render/spectral_palette.hpp"

namespace impasto::render {

// A pigment present in a layer: palette index and concentration (amount / volume).
struct PigmentShare {
  int pigment;
  float concentration;
};

// reflectance[i] (what lies beneath, per node) becomes the reflectance with a layer of
// `thickness` (K-M optical units: mm / thickness scale) of the mix `shares` on top.
inline void composite_paint_layer(const SpectralPalette& palette,
                                  std::span<const PigmentShare> shares, float thickness,
                                  float* reflectance) {
  if (!(thickness > 0.0f)) return;
  const int nodes = palette.nodes();
  for (int i = 0; i < nodes; ++i) {
    float absorption = 0.0f;
    float scattering = 0.0f;
    for (const PigmentShare& share : shares) {
      km::accumulate_pigment(share.concentration, palette.absorption(share.pigment)[i],
                             palette.scattering(share.pigment)[i], absorption, scattering);
    }
    reflectance[i] = km::composite(km::layer(absorption, scattering, thickness), reflectance[i]);
  }
}

// Display-referred XYZ of node reflectances.
inline void node_reflectance_to_xyz(const SpectralPalette& palette, const float* reflectance,
                                    float xyz[3]) {
  const int nodes = palette.nodes();
  for (int c = 0; c < 3; ++c) {
    const float* weights = palette.to_display_xyz(c);
    float sum = 0.0f;
    for (int i = 0; i < nodes; ++i) sum += weights[i] * reflectance[i];
    xyz[c] = sum;
  }
}

}  // namespace impasto::render
