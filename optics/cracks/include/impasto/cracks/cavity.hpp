#pragma once
// The shapes a crack or a hole in the canvas can take, and their Gouffé view factors.
//
// Every cavity has a planar opening at z = 0 (the canvas surface) and lies below it, its
// deepest point at z = -depth. Grooves are long cracks: their cross-section (in the x-z
// plane) is extruded along y, and all their quantities are per unit length. Pits are round
// holes, symmetric about the z axis. All lengths in mm.
#include <array>
#include <cstdint>
#include <string_view>

#include "impasto/util/enum_names.hpp"

namespace impasto::cracks {

enum class CavityShape : std::uint8_t {
  ArcGroove,    // groove whose section is a circular arc (a cylinder cut by the opening)
  VGroove,      // groove with a V section
  BoxGroove,    // groove with vertical walls and a flat bottom
  SpherePit,    // round pit: a sphere cap
  ConePit,      // round pit: a cone, apex down
  CylinderPit,  // round pit: vertical wall, flat bottom
};

inline constexpr std::array<CavityShape, 6> kAllShapes = {
    CavityShape::ArcGroove, CavityShape::VGroove, CavityShape::BoxGroove,
    CavityShape::SpherePit, CavityShape::ConePit, CavityShape::CylinderPit};

constexpr bool is_groove(CavityShape s) {
  return s == CavityShape::ArcGroove || s == CavityShape::VGroove || s == CavityShape::BoxGroove;
}

// Their spellings (--shape), in kAllShapes' order.
inline constexpr util::EnumNames<CavityShape, 6> kCavityShapeNames{
    {{CavityShape::ArcGroove, "arc-groove"},
     {CavityShape::VGroove, "v-groove"},
     {CavityShape::BoxGroove, "box-groove"},
     {CavityShape::SpherePit, "sphere-pit"},
     {CavityShape::ConePit, "cone-pit"},
     {CavityShape::CylinderPit, "cylinder-pit"}}};

// The name of kCavityShapeNames.
std::string_view shape_name(CavityShape shape);
// Inverse of shape_name; throws std::runtime_error naming the unknown text and the choices.
CavityShape shape_from_name(std::string_view name);

// Size of a cavity: depth L below the opening and half-width R of the opening (mm).
struct CavityDims {
  double depth_mm = 0.0;       // L
  double half_width_mm = 0.0;  // R
};

// Throws std::runtime_error unless 0 <= L < inf and 0 < R < inf (no NaN).
void validate(const CavityDims& dims);

// Gouffé's two geometric factors of a cavity, both in [0, 1].
struct ViewFactors {
  // F: the fraction of the radiation diffusely reflected by the wall element opposite the
  // opening (the deepest point, its normal along +z) that leaves through the opening.
  double F = 1.0;
  // G: the fraction of radiation diffusely reflected by walls of uniform radiosity that
  // leaves through the opening. For a planar opening of area A and wall area S, G = A / S
  // exactly (reciprocity: the opening sees only walls, so A·1 = S·G).
  double G = 1.0;
};

// Analytic F and G for a shape of the given size (derivations in docs/cracks.md).
ViewFactors view_factors(CavityShape shape, const CavityDims& dims);

// Area of the opening A and of the inner walls S (for grooves: per unit length, so widths).
struct CavityAreas {
  double opening = 0.0;
  double walls = 0.0;
};
CavityAreas cavity_areas(CavityShape shape, const CavityDims& dims);

}  // namespace impasto::cracks
