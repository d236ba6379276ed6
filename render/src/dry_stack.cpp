#include "impasto/render/dry_stack.hpp"

#include <algorithm>
#include <array>
#include <cstddef>
#include <stdexcept>
#include <string>

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

VisibleDryStack visible_dry_stack(const paintcore::Canvas& canvas, int tile_index,
                                  const SpectralPalette& palette, const std::vector<bool>& hidden) {
  VisibleDryStack stack;
  DryStackSignature signature;
  const auto& dry_layers = canvas.dry_layers();
  for (std::size_t l = 0; l < dry_layers.size(); ++l) {
    if (l < hidden.size() && hidden[l]) continue;
    const paintcore::DryTile* dry = dry_layers[l].find(tile_index);
    if (dry == nullptr) continue;
    const std::string where =
        "render: dry layer " + std::to_string(l) + " of tile " + std::to_string(tile_index);
    if (dry->volume_mm.size() != static_cast<std::size_t>(kTileCells) ||
        dry->pigment_mm.size() != dry->slots.size() * static_cast<std::size_t>(kTileCells)) {
      throw std::runtime_error(where + " has inconsistent sizes");
    }
    for (std::uint8_t slot : dry->slots) {
      if (slot >= palette.pigment_count()) {
        throw std::runtime_error(where + " uses pigment slot " + std::to_string(slot) +
                                 " but the palette has " + std::to_string(palette.pigment_count()) +
                                 " pigments");
      }
    }
    stack.layers.push_back(dry);
    signature.add(l, *dry);
  }
  stack.signature = signature.value();
  return stack;
}

void DryStackSignature::add(std::size_t layer_index, const paintcore::DryTile& layer) {
  hash_.value(layer_index);
  hash_.bytes(layer.volume_mm.data(), layer.volume_mm.size() * sizeof(float));
  hash_.bytes(layer.slots.data(), layer.slots.size());
  hash_.bytes(layer.pigment_mm.data(), layer.pigment_mm.size() * sizeof(float));
  any_ = true;
}

}  // namespace impasto::render
