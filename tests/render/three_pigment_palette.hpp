#pragma once
// The palette the tile renderer's tests paint with: White (its R∞ the ground, the
// painting's pigment 0), Black (1) and Blue Green Shade (2), under a named
// light (data::light_from_spec).
#include <string>
#include <vector>

#include "impasto/data/lights.hpp"
#include "impasto/data/pigments.hpp"
#include "impasto/render/tile_renderer.hpp"

namespace impasto::render {

inline std::vector<data::Pigment> test_pigments() {
  const auto& db = data::PigmentDatabase::defaults();
  return {db.get("White"), db.get("Black"), db.get("Blue Green Shade")};
}

inline SpectralPalette make_palette(const RenderSettings& settings, const char* light = "D65") {
  const auto pigments = test_pigments();
  return SpectralPalette(settings, data::light_from_spec(light), pigments,
                         hiding_reflectance(pigments[0]));
}

}  // namespace impasto::render
