#pragma once
// Close-up shading of points inside a cavity: where a wall point is, how much of the sky it
// sees through the opening (its own view factor), and its radiosity under sky and sun with
// the interreflections of Gouffé's uniform-wall assumption.
#include <impasto/util/vec3.hpp>

#include "impasto/cracks/cavity.hpp"

namespace impasto::cracks {

using Vec3d = util::Vec3<double>;  // mm, opening at z = 0, cavity below

struct CavityWallPoint {
  Vec3d position{};
  Vec3d normal{};  // unit, into the cavity
};

// A wall point from its place along the section's profile: s in [0, 1] runs from the
// deepest point (0) to the rim (1) along the wall (arc length fraction); `side` in
// [-pi, pi] is the azimuth for pits, and its sign picks the left or right wall of grooves.
CavityWallPoint cavity_wall_point(CavityShape shape, const CavityDims& dims, double s, double side);

// Exact view factor from a wall element to the opening: the fraction of its diffuse
// emission leaving through the opening. Grooves: Hottel's 2-D formula
// (sin phi2 - sin phi1) / 2; pits: the contour integral over the rim (closed forms for the
// sphere and the cylinder).
double opening_view_factor(CavityShape shape, const CavityDims& dims, const CavityWallPoint& p);

// The seed's bounds-based approximation F = sin^2(theta2) - sin^2(theta1) for the points
// it covers (cylinder-pit bottom at radius r and wall at depth x below the rim, cone wall),
// kept to compare with opening_view_factor in docs/cracks.md.
double seed_view_factor_cylinder_bottom(const CavityDims& dims, double r_mm);
double seed_view_factor_cylinder_wall(const CavityDims& dims, double depth_below_rim_mm);

// The mean view factor to the opening over the first reflection points of a parallel beam
// entering at zenith_rad (radians, across the groove): a better F for Gouffé's series
// under directional light than the deepest element's. Gauss quadrature over the opening.
double first_reflection_view_factor(CavityShape shape, const CavityDims& dims, double zenith_rad);

// Light falling on the canvas: a uniform sky and a sun (irradiances on the canvas plane
// per unit wavelength, any consistent unit).
struct CavityLighting {
  double sky_irradiance = 0.0;         // E_sky: from a uniformly bright hemisphere
  double sun_irradiance = 0.0;         // E_sun on a plane facing the sun
  Vec3d sun_direction{0.0, 0.0, 1.0};  // unit, towards the sun (z up)
};

// Radiosity B (same unit as the irradiances) of a wall point with reflectance rho0:
//   B = rho0 [ E_sky F_p + E_sun cos+ V_sun + (1 - F_p) E_walls ]
// with F_p its view factor to the opening, V_sun whether the sun is visible through the
// opening, and E_walls the interreflected irradiance of uniform walls
//   E_walls = rho0 (Phi_in / S) / (1 - rho0 (1 - G)),  Phi_in = A (E_sky + E_sun cos z).
// Its radiance is B / pi; the seed's I = pi I_gray cos(view, normal) is B cos(view, normal),
// the intensity of a unit of wall area seen at that angle.
double cavity_point_radiosity(CavityShape shape, const CavityDims& dims, const CavityWallPoint& p,
                              double rho0, const CavityLighting& light);

}  // namespace impasto::cracks
