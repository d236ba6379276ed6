#include "impasto/render_gl/dry_reflectance.hpp"

#include <Imath/half.h>

#include "impasto/render/dry_stack.hpp"

namespace impasto::render_gl {

using paintcore::kTileCells;

namespace {

// A reflectance as the CPU reference stores it (settings.storage).
float stored(float value, const render::RenderSettings& settings) {
  return settings.storage == render::ReflectanceStorage::float16
             ? static_cast<float>(Imath::half(value))
             : value;
}

}  // namespace

void bake_dry_reflectance(const render::VisibleDryStack& stack,
                          const render::RenderSettings& settings,
                          const render::SpectralPalette& palette, std::vector<float>& out) {
  const std::vector<const paintcore::DryTile*>& layers = stack.layers;
  const int nodes = palette.nodes();
  out.resize(static_cast<size_t>(nodes) * kTileCells);
  std::vector<float> reflectance(static_cast<size_t>(nodes));
  // The CPU reference's own bake, stored as it stores it, so the two agree bit for bit.
  const auto optical_per_mm = static_cast<float>(1.0 / settings.thickness_scale_mm);
  for (int cell = 0; cell < kTileCells; ++cell) {
    render::composite_dry_stack(palette, layers, cell, optical_per_mm, reflectance.data());
    for (int node = 0; node < nodes; ++node) {
      out[static_cast<size_t>(node) * kTileCells + static_cast<size_t>(cell)] =
          stored(reflectance[static_cast<size_t>(node)], settings);
    }
  }
}

std::vector<float> bare_ground_reflectance(const render::RenderSettings& settings,
                                           const render::SpectralPalette& palette) {
  // composite_dry_stack of no layers: the ground, the same for every cell.
  std::vector<float> reflectance(static_cast<std::size_t>(palette.nodes()));
  const auto optical_per_mm = static_cast<float>(1.0 / settings.thickness_scale_mm);
  render::composite_dry_stack(palette, {}, 0, optical_per_mm, reflectance.data());
  for (float& value : reflectance) value = stored(value, settings);
  return reflectance;
}

}  // namespace impasto::render_gl
