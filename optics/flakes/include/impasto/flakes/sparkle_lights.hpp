#pragma once
// Lights and the viewer as the sparkle model sees them. Only lights with a direction make
// sparkles; diffuse (ambient) light lights every flake a little and none brightly.
#include <numbers>
#include <vector>

#include "impasto/flakes/vec3.hpp"

namespace impasto::flakes {

struct Light {
  enum class Kind { directional, point, spot, diffuse };
  Kind kind = Kind::directional;
  Vec3 direction{0, 0, -1};  // directional, spot: the direction the light travels (unit)
  Vec3 position_mm{};        // point, spot: the emitter's centre
  // Apparent diameter of the emitter seen from the canvas, radians (the sun: 0.53°). The
  // model uses the angular radius Δ = diameter / 2 (its cone has solid angle πΔ²).
  double angular_diameter_rad = 0.53 * std::numbers::pi / 180.0;
  double spot_inner_rad = 0.3;  // spot: full intensity inside this half-angle
  double spot_outer_rad = 0.4;  // spot: nothing outside this half-angle (smooth between)
  // Per wavelength node: for directional light the irradiance on a plane normal to the
  // beam; for point and spot lights the radiant intensity (per steradian), so that the
  // irradiance normal to the beam is intensity / distance² (distance in mm).
  std::vector<double> spectral;
};

struct View {
  bool orthographic = true;
  Vec3 direction{0, 0, 1};  // orthographic: unit direction from the canvas to the viewer
  Vec3 position_mm{};       // perspective: the eye
};

}  // namespace impasto::flakes
