// Analytic view factors of the six cavity shapes (derivations: docs/cracks.md).
#include "impasto/cracks/cavity.hpp"

#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

namespace impasto::cracks {

std::string_view shape_name(CavityShape shape) {
  return util::name_of(kCavityShapeNames, shape);
}

CavityShape shape_from_name(std::string_view name) {
  return util::parse_name(kCavityShapeNames, name, "cavity shape");
}

void validate(const CavityDims& dims) {
  if (!(dims.depth_mm >= 0.0) || !std::isfinite(dims.depth_mm)) {
    throw std::runtime_error("cavity depth_mm must be finite and >= 0, got " +
                             std::to_string(dims.depth_mm));
  }
  if (!(dims.half_width_mm > 0.0) || !std::isfinite(dims.half_width_mm)) {
    throw std::runtime_error("cavity half_width_mm must be finite and > 0, got " +
                             std::to_string(dims.half_width_mm));
  }
}

CavityAreas cavity_areas(CavityShape shape, const CavityDims& d) {
  const double L = d.depth_mm;
  const double R = d.half_width_mm;
  const double pi = std::numbers::pi;
  switch (shape) {
    case CavityShape::ArcGroove: {
      // Circle through (+-R, 0) and (0, -L): radius r = (R^2 + L^2) / 2L, arc = 2 r beta with
      // beta = 2 atan(L / R). Written as r beta = beta (R^2 + L^2) / 2L, which tends to R as
      // L -> 0 (the arc becomes the chord); below 1e-8 R that limit is used directly.
      if (L < 1e-8 * R) return {2.0 * R, 2.0 * R};
      const double beta = 2.0 * std::atan(L / R);
      return {2.0 * R, beta * (R * R + L * L) / L};
    }
    case CavityShape::VGroove:
      return {2.0 * R, 2.0 * std::sqrt(R * R + L * L)};
    case CavityShape::BoxGroove:
      return {2.0 * R, 2.0 * R + 2.0 * L};
    case CavityShape::SpherePit:
      return {pi * R * R, pi * (R * R + L * L)};
    case CavityShape::ConePit:
      return {pi * R * R, pi * R * std::sqrt(R * R + L * L)};
    case CavityShape::CylinderPit:
      return {pi * R * R, pi * R * R + 2.0 * pi * R * L};
  }
  return {};
}

ViewFactors view_factors(CavityShape shape, const CavityDims& dims) {
  validate(dims);
  const double L = dims.depth_mm;
  const double R = dims.half_width_mm;
  const CavityAreas areas = cavity_areas(shape, dims);
  ViewFactors vf;
  vf.G = areas.opening / areas.walls;
  // F: the deepest element, facing +z, sees the opening (half-width R) at height L.
  // Grooves (2-D): F = (sin phi2 - sin phi1) / 2 with phi = +-atan(R/L): R / sqrt(R^2+L^2).
  // Pits (disc of radius R on the axis): F = sin^2(atan(R/L)) = R^2 / (R^2 + L^2).
  const double sin_half_angle = R / std::sqrt(R * R + L * L);
  vf.F = is_groove(shape) ? sin_half_angle : sin_half_angle * sin_half_angle;
  return vf;
}

}  // namespace impasto::cracks
