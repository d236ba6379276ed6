#pragma once
// Everything about a flake paint that does not depend on the pixel, tabulated once per paint
// and wavelength set so that the per-pixel work is table look-ups (mirrored as GLSL
// textures): the orientation density P(cos β), the mean projected area ⟨s⟩(cos ϑ) and
// transmitted part ⟨t_p⟩(cos ϑ) of a unit flake, and r_p(cos α) per wavelength.
#include <cstddef>
#include <span>
#include <vector>

#include "impasto/flakes/flake_paint.hpp"

namespace impasto::flakes {

class FlakeTables {
 public:
  FlakeTables(const FlakePaint& paint, std::span<const double> wavelengths_nm);

  const FlakePaint& paint() const { return paint_; }
  std::size_t wavelength_count() const { return wavelengths_nm_.size(); }
  std::span<const double> wavelengths_nm() const { return wavelengths_nm_; }

  // P(β), normalised so ∫₀^{π/2} P(β) sin β dβ = 1 (per unit solid angle it is P / 2π).
  // Tabulated uniformly in sin(β/2) = sqrt((1 − cos β) / 2), which resolves narrow
  // distributions near β = 0 without an arccos.
  double orientation_density(double cos_beta) const;

  // ⟨s⟩: mean of |cos| between a ray at polar angle ϑ and a flake normal, over the
  // orientation distribution (the projected area of a unit flake; cos ϑ for flat flakes).
  double projected_area(double cos_theta) const;

  // ⟨t_p⟩: the same mean weighted by the flake's transmittance (wavelength-averaged over
  // 400–700 nm), the part of the projected area that lets light through.
  double projected_transmittance(double cos_theta) const;

  // r_p(cos α) at wavelength node `index`.
  double flake_reflectance(std::size_t index, double cos_alpha) const;

  // Wavelength-averaged transmittance of one flake at incidence cosine cos_alpha.
  double flake_transmittance(double cos_alpha) const;

  static constexpr int kOrientationSamples = 1024;
  static constexpr int kAngleSamples = 129;
  // sin(β/2) at β = π/2: the orientation table spans sin(β/2) in [0, this].
  static double max_half_sin();

  // The samples themselves, for upload to the GPU (which interpolates them the same way).
  const std::vector<double>& orientation_samples() const { return orientation_; }
  const std::vector<double>& projected_area_samples() const { return projected_area_; }
  const std::vector<double>& projected_transmittance_samples() const {
    return projected_transmittance_;
  }
  // r_p at cos α = i / (kAngleSamples − 1) for wavelength node `index`.
  std::span<const double> reflectance_samples(std::size_t index) const {
    return {reflectance_.data() + index * kAngleSamples, static_cast<std::size_t>(kAngleSamples)};
  }

 private:
  FlakePaint paint_;
  std::vector<double> wavelengths_nm_;
  std::vector<double> orientation_;     // P at sin(β/2) = i · max / (samples − 1)
  std::vector<double> projected_area_;  // ⟨s⟩ at cos ϑ = i / (samples − 1)
  std::vector<double> projected_transmittance_;
  std::vector<double> reflectance_;    // [wavelength][cos α]
  std::vector<double> transmittance_;  // [cos α], wavelength-averaged
};

// Linear interpolation in a table sampled uniformly over [0, x_max]; clamps outside.
inline double lerp_table(const std::vector<double>& table, double x, double x_max) {
  const double last = static_cast<double>(table.size() - 1);
  double u = x / x_max * last;
  if (!(u > 0.0)) return table.front();  // also catches NaN
  if (u >= last) return table.back();
  const auto i = static_cast<std::size_t>(u);
  const double f = u - static_cast<double>(i);
  return table[i] + f * (table[i + 1] - table[i]);
}

}  // namespace impasto::flakes
