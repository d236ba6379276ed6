#pragma once
// The tile renderer's per-cell spectral work, structure-of-arrays over the wavelength nodes:
// every spectral quantity of a cell is `padded` floats (the nodes rounded up to a multiple of
// kLanes, the rest zero), so at 8 nodes a K-M layer is one 8-wide vector per quantity. The
// loops are written branch-free over fixed 8-wide blocks and compiled twice (AVX2 and
// baseline x86-64, util/simd_clones.hpp, no FMA: both give the same bits).
//
// They follow kubelka_munk_cell.hpp (the reference) operation for operation, except that e^x is
// fast_exp below (within 2 ulp of std::exp), so results agree with the reference within a
// few float ulps (tests/render/spectral_kernels_test.cpp).
#include <bit>
#include <vector>

#include "impasto/render/render_settings.hpp"
#include "impasto/render/spectral_palette.hpp"
#include "impasto/util/simd_clones.hpp"

namespace impasto::render::kernels {

inline constexpr int kLanes = 8;
inline int padded_nodes(int nodes) {
  return (nodes + kLanes - 1) / kLanes * kLanes;
}

// e^x for x in [-87, 88] (clamped there, NaN taken as -87), relative error below 2.5e-7: Cody-Waite
// reduction by ln 2 and Cephes' expf polynomial, in plain float operations that vectorise.
inline float fast_exp(float x) {
  x = x > -87.0f ? x : -87.0f;  // NaN too: never an out-of-range conversion below
  x = x < 88.0f ? x : 88.0f;
  constexpr float kShifter = 12582912.0f;  // 1.5 · 2^23: adding it rounds to an integer
  const float n = (x * 1.44269504088896341f + kShifter) - kShifter;
  float r = x - n * 0.693359375f;
  r = r - n * -2.12194440e-4f;
  float p = 1.9875691500e-4f;
  p = p * r + 1.3981999507e-3f;
  p = p * r + 8.3334519073e-3f;
  p = p * r + 4.1665795894e-2f;
  p = p * r + 1.6666665459e-1f;
  p = p * r + 5.0000001201e-1f;
  p = p * (r * r) + r + 1.0f;
  return p * std::bit_cast<float>((static_cast<int>(n) + 127) << 23);
}

// The palette at the nodes, each row padded with zeros (a zero K and S lane composites to
// zero over a zero ground: no NaN in the padding).
struct PaddedPalette {
  int nodes = 0;
  int padded = 0;
  std::vector<float> absorption, scattering;  // pigment-major, `padded` per pigment
  std::vector<float> ground;
  std::vector<float> to_xyz;  // 3 rows of `padded`
  bool saunderson = false;
  float k1 = 0.0f, k2 = 0.0f;

  PaddedPalette() = default;
  PaddedPalette(const SpectralPalette& palette, const RenderSettings& settings);
  const float* absorption_of(int pigment) const {
    return &absorption[static_cast<std::size_t>(pigment) * static_cast<std::size_t>(padded)];
  }
  const float* scattering_of(int pigment) const {
    return &scattering[static_cast<std::size_t>(pigment) * static_cast<std::size_t>(padded)];
  }
};

// One paint layer over a run of cells: its volume per cell and, per slot, the palette pigment
// and its amount per cell (null: none in this layer).
struct LayerCells {
  const float* volume_mm = nullptr;
  int slot_count = 0;
  const int* pigment = nullptr;
  const float* const* amount_mm = nullptr;
};

// reflectance (`padded` per cell, `count` cells) becomes the layer composited over it, for
// the cells with paint (volume > 0): the pigments mixed by concentration (amount / volume,
// capped as pigment_concentration), thickness volume · optical_per_mm. As
// composite_paint_layer.
void composite_layer_cells(const PaddedPalette& palette, const LayerCells& layer, int count,
                           float optical_per_mm, float* reflectance);

// Display-referred XYZ (3 per cell) of `count` cells' reflectances, Saunderson-corrected first
// when the palette says so (reflectance is changed in place then). As
// node_reflectance_to_xyz.
void cells_to_xyz(const PaddedPalette& palette, float* reflectance, int count, float* xyz);

}  // namespace impasto::render::kernels
