#pragma once
// Validation of a light before it reaches the per-cell maths.
#include <cmath>
#include <cstddef>
#include <stdexcept>
#include <string>

#include "impasto/flakes/sparkle_lights.hpp"

namespace impasto::flakes {

// Throws std::runtime_error unless a light that makes sparkles has one spectral value per
// wavelength node and a positive, finite angular size.
inline void check_light(const Light& light, std::size_t nodes) {
  if (light.kind == Light::Kind::diffuse) return;
  if (light.spectral.size() != nodes) {
    throw std::runtime_error("flake light: spectral has " + std::to_string(light.spectral.size()) +
                             " values, expected " + std::to_string(nodes) +
                             " (one per wavelength node)");
  }
  if (!(light.angular_diameter_rad > 0.0) || !std::isfinite(light.angular_diameter_rad)) {
    throw std::runtime_error("flake light: angular_diameter_rad must be positive and finite");
  }
}

}  // namespace impasto::flakes
