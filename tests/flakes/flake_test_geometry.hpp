#pragma once
// Angles, wavelengths and the viewer shared by the flake tests.
#include <cmath>
#include <numbers>
#include <vector>

#include "impasto/flakes/sparkle_lights.hpp"

namespace impasto::flakes::test {

inline constexpr double kPi = std::numbers::pi;
inline constexpr double kDegree = kPi / 180.0;
// Three wavelength nodes (nm) across the visible.
inline const std::vector<double> kNodes{450.0, 550.0, 650.0};

// The unit vector `polar_deg` from the zenith (+z), `azimuth_deg` round from +x.
inline Vec3 direction(double polar_deg, double azimuth_deg) {
  const double p = polar_deg * kDegree, a = azimuth_deg * kDegree;
  return {std::sin(p) * std::cos(a), std::sin(p) * std::sin(a), std::cos(p)};
}

// The viewer 25° from the zenith, on the side away from the lights at azimuth 0.
inline View viewer() {
  View view;
  view.direction = direction(25, 180);
  return view;
}

}  // namespace impasto::flakes::test
