#include "impasto/render/dry_stack.hpp"

#include <algorithm>
#include <array>
#include <cstddef>

#include "impasto/render/paint_layer.hpp"

namespace impasto::render {

using paintcore::kTileCells;

void composite_dry_stack(const SpectralPalette& palette,
                         std::span<const paintcore::DryTile* const> layers, int cell,
                         float optical_per_mm, float* reflectance) {
  std::copy_n(palette.ground(), palette.nodes(), reflectance);
  const auto c = static_cast<std::size_t>(cell);
  std::array<PigmentShare, paintcore::kMaxPigmentSlots> shares{};
  for (const paintcore::DryTile* dry : layers) {
    const float volume = dry->volume_mm[c];
    if (!(volume > 0.0f)) continue;
    // Concentration = amount / volume, as for the wet layer.
    const float inverse_volume = 1.0f / volume;
    std::size_t count = 0;
    for (std::size_t k = 0; k < dry->slots.size() && count < shares.size(); ++k) {
      const float amount = dry->pigment_mm[k * kTileCells + c];
      if (amount > 0.0f)
        shares[count++] = {dry->slots[k], pigment_concentration(amount, inverse_volume)};
    }
    composite_paint_layer(palette, std::span(shares.data(), count), volume * optical_per_mm,
                          reflectance);
  }
}

void DryStackSignature::add(std::size_t layer_index, const paintcore::DryTile& layer) {
  hash_.add(&layer_index, sizeof layer_index);
  hash_.add(layer.volume_mm.data(), layer.volume_mm.size() * sizeof(float));
  hash_.add(layer.slots.data(), layer.slots.size());
  hash_.add(layer.pigment_mm.data(), layer.pigment_mm.size() * sizeof(float));
  any_ = true;
}

}  // namespace impasto::render
