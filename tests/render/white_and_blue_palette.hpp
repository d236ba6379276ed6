#pragma once
// A palette of two pigments for the renderer's shading tests: White (its R∞ the
// ground, the painting's pigment 0) and Blue Green Shade (1), under the settings'
// light.
#include <vector>

#include "impasto/data/lights.hpp"
#include "impasto/data/pigments.hpp"
#include "impasto/render/tile_renderer.hpp"

namespace impasto::render {

inline std::vector<data::Pigment> white_and_blue() {
  const auto& db = data::PigmentDatabase::defaults();
  return {db.get("White"), db.get("Blue Green Shade")};
}

inline SpectralPalette white_and_blue_palette(const RenderSettings& settings) {
  const auto pigments = white_and_blue();
  return SpectralPalette(settings, data::light_from_spec(settings.light), pigments,
                         hiding_reflectance(pigments[0]));
}

}  // namespace impasto::render
