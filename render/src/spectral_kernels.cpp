#include "spectral_kernels.hpp"

#include <array>
#include <cmath>

#include "impasto/data/kubelka_munk.hpp"
#include "impasto/paintcore/painting.hpp"
#include "impasto/render/paint_layer.hpp"

namespace impasto::render::kernels {
namespace {

using util::greater;

// One K-M layer (K, S per lane, thickness d) over `below`, in place: kubelka_munk_cell.hpp's
// layer() and composite() with both branches computed and selected.
inline void layer_over(const float* __restrict absorption, const float* __restrict scattering,
                       float d, float* __restrict below) {
  for (int i = 0; i < kLanes; ++i) {
    const float K = absorption[i];
    const float S = scattering[i];
    const float alpha = K + S;
    const float beta = std::sqrt(K) * std::sqrt(K + 2.0f * S);
    const float e = fast_exp(-beta * d);
    const float x = 2.0f * beta * d;
    const float series = 1.0f - x * (0.5f - x * (1.0f / 6.0f));
    // e^(−x) = e²: one exponential, not two (the reference calls exp twice).
    const float full = (1.0f - e * e) / greater(x, 1e-3f);
    const float f = 2.0f * d * (x < 1e-3f ? series : full);
    // One division for both (the reference divides twice: R and T may differ by an ulp).
    const float inverse = 1.0f / (alpha * f + 1.0f + e * e);
    const float R = S * f * inverse;
    const float T = 2.0f * e * inverse;
    const float r = below[i];
    const float inner = 1.0f - R * r;
    const float through = T * T * r / (inner > 0.0f ? inner : 1.0f);
    below[i] = inner > 0.0f ? R + through : R;
  }
}

}  // namespace

PaddedPalette::PaddedPalette(const SpectralPalette& palette, const RenderSettings& settings)
    : nodes(palette.nodes()), padded(padded_nodes(palette.nodes())) {
  const auto n = static_cast<std::size_t>(nodes);
  const auto p = static_cast<std::size_t>(padded);
  absorption.assign(p * static_cast<std::size_t>(palette.pigment_count()), 0.0f);
  scattering.assign(absorption.size(), 0.0f);
  for (int k = 0; k < palette.pigment_count(); ++k) {
    std::copy_n(palette.absorption(k), n, &absorption[static_cast<std::size_t>(k) * p]);
    std::copy_n(palette.scattering(k), n, &scattering[static_cast<std::size_t>(k) * p]);
  }
  ground.assign(p, 0.0f);
  std::copy_n(palette.ground(), n, ground.begin());
  to_xyz.assign(3 * p, 0.0f);
  for (int c = 0; c < 3; ++c) {
    std::copy_n(palette.to_display_xyz(c), n, &to_xyz[static_cast<std::size_t>(c) * p]);
  }
  saunderson = settings.saunderson;
  k1 = static_cast<float>(settings.saunderson_k1);
  k2 = static_cast<float>(settings.saunderson_k2);
}

IMPASTO_SIMD_CLONES
void composite_layer_cells(const PaddedPalette& palette, const LayerCells& layer, int count,
                           float optical_per_mm, float* reflectance) {
  const int padded = palette.padded;
  alignas(32) std::array<float, kMaxNodes> absorption{}, scattering{};
  for (int c = 0; c < count; ++c) {
    const float volume = layer.volume_mm[c];
    const float thickness = volume * optical_per_mm;
    if (!(volume > 0.0f) || !(thickness > 0.0f)) continue;
    absorption.fill(0.0f);
    scattering.fill(0.0f);
    const float inverse_volume = 1.0f / volume;
    // Every slot, a pigment absent from the cell with concentration 0: adding 0 · K leaves
    // the sums' bits as the reference's skip does (K and S are finite), with no branch to
    // mispredict.
    for (int k = 0; k < layer.slot_count; ++k) {
      const float* amounts = layer.amount_mm[k];
      if (amounts == nullptr) continue;
      const float amount = amounts[c];
      const float concentration =
          amount > 0.0f ? pigment_concentration(amount, inverse_volume) : 0.0f;
      const float* K = palette.absorption_of(layer.pigment[k]);
      const float* S = palette.scattering_of(layer.pigment[k]);
      for (int b = 0; b < padded; b += kLanes) {
        for (int i = 0; i < kLanes; ++i) {
          absorption[static_cast<std::size_t>(b + i)] += concentration * K[b + i];
          scattering[static_cast<std::size_t>(b + i)] += concentration * S[b + i];
        }
      }
    }
    float* r = reflectance + static_cast<std::ptrdiff_t>(c) * padded;
    for (int b = 0; b < padded; b += kLanes) {
      layer_over(&absorption[static_cast<std::size_t>(b)], &scattering[static_cast<std::size_t>(b)],
                 thickness, r + b);
    }
  }
}

IMPASTO_SIMD_CLONES
void cells_to_xyz(const PaddedPalette& palette, float* reflectance, int count, float* xyz) {
  const int padded = palette.padded;
  const int nodes = palette.nodes;
  const float* wx = palette.to_xyz.data();
  const float* wy = wx + padded;
  const float* wz = wy + padded;
  const float k1 = palette.k1, k2 = palette.k2;
  for (int c = 0; c < count; ++c) {
    float* r = reflectance + static_cast<std::ptrdiff_t>(c) * padded;
    if (palette.saunderson) {
      for (int b = 0; b < padded; b += kLanes) {
        for (int i = 0; i < kLanes; ++i) {
          r[b + i] = data::saunderson_body(r[b + i], k1, k2);
        }
      }
    }
    // Summed in node order, as the reference does: the same bits.
    float x = 0.0f, y = 0.0f, z = 0.0f;
    for (int i = 0; i < nodes; ++i) {
      x += wx[i] * r[i];
      y += wy[i] * r[i];
      z += wz[i] * r[i];
    }
    xyz[3 * c] = x;
    xyz[3 * c + 1] = y;
    xyz[3 * c + 2] = z;
  }
}

}  // namespace impasto::render::kernels
