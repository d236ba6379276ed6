#include "impasto/render_gl/dry_reflectance.hpp"

#include <Imath/half.h>

#include <algorithm>

#include "impasto/render/paint_layer.hpp"

namespace impasto::render_gl {

using paintcore::kTileCells;

void bake_dry_reflectance(const paintcore::Canvas& canvas, int tile_index,
                          const render::RenderSettings& settings,
                          const render::SpectralPalette& palette, std::vector<float>& out,
                          const std::vector<bool>& hidden) {
  const int nodes = palette.nodes();
  out.resize(static_cast<size_t>(nodes) * kTileCells);
  std::vector<float> reflectance(static_cast<size_t>(nodes));
  std::vector<render::PigmentShare> shares;
  // The same float operations as render::TileRenderer's bake, so the two agree bit for bit.
  const auto optical_per_mm = static_cast<float>(1.0 / settings.thickness_scale_mm);
  const bool half = settings.storage == render::ReflectanceStorage::float16;
  for (int cell = 0; cell < kTileCells; ++cell) {
    std::copy_n(palette.ground(), nodes, reflectance.begin());
    const auto& layers = canvas.dry_layers();
    for (size_t l = 0; l < layers.size(); ++l) {  // bottom first
      if (l < hidden.size() && hidden[l]) continue;
      const paintcore::DryTile* tile = layers[l].find(tile_index);
      if (tile == nullptr) continue;
      const float volume = tile->volume_mm[static_cast<size_t>(cell)];
      if (!(volume > 0.0f)) continue;
      const float inverse_volume = 1.0f / volume;
      shares.clear();
      for (size_t i = 0; i < tile->slots.size(); ++i) {
        const int slot = tile->slots[i];
        const float amount = tile->pigment_mm[i * kTileCells + static_cast<size_t>(cell)];
        if (slot < palette.pigment_count() && amount > 0.0f) {
          shares.push_back({slot, amount * inverse_volume});
        }
      }
      render::composite_paint_layer(palette, shares, volume * optical_per_mm, reflectance.data());
    }
    for (int node = 0; node < nodes; ++node) {
      out[static_cast<size_t>(node) * kTileCells + static_cast<size_t>(cell)] =
          half ? static_cast<float>(Imath::half(reflectance[static_cast<size_t>(node)]))
               : reflectance[static_cast<size_t>(node)];
    }
  }
}

}  // namespace impasto::render_gl
