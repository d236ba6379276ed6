#pragma once
// The per-pixel maths of sparkles (Ershov, Khodulev, Kolchin §5.3), as small inline functions
// that the GLSL port mirrors line by line. Angles are cosines; lengths mm; areas mm².
#include <algorithm>
#include <cmath>
#include <numbers>

#include "impasto/flakes/vec3.hpp"

namespace impasto::flakes {

// Eq. 8: the direction v inside a binder of relative index eta of a unit direction V
// outside (both pointing away from the surface, same side as the normal n, n·V > 0).
inline Vec3 refract_into_binder(Vec3 V, Vec3 n, double eta) {
  const double cos_out = dot(n, V);
  const double sin2_out = 1.0 - cos_out * cos_out;
  const double cos_in = std::sqrt(std::max(0.0, eta * eta - sin2_out)) / eta;
  return (1.0 / eta) * V + (cos_in - cos_out / eta) * n;
}

// Snell's law for the polar cosine inside the binder.
inline double cos_inside_binder(double cos_out, double eta) {
  const double sin2_out = 1.0 - cos_out * cos_out;
  return std::sqrt(std::max(0.0, 1.0 - sin2_out / (eta * eta)));
}

// Eq. 7: angular (or linear) size of a round object seen from inside the binder, from its
// size outside, along a ray with polar cosines cos_out (outside) and cos_in (inside).
inline double binder_angular_size(double size_outside, double cos_out, double cos_in, double eta) {
  return size_outside / eta * std::sqrt(cos_out / cos_in);
}

// The flake orientation that mirrors the light v_light into the view v_view (inside the
// binder), and the two cosines the statistics need.
struct SpecularFlake {
  Vec3 normal;       // n_f = (v + v′) / ‖v + v′‖
  double cos_alpha;  // incidence on the flake, n_f · v′
  double cos_beta;   // tilt of the flake, n_f · n
};

inline SpecularFlake specular_flake(Vec3 v_view, Vec3 v_light, Vec3 n) {
  const Vec3 nf = normalized(v_view + v_light);
  return {nf, dot(nf, v_light), dot(nf, n)};
}

// Optical thickness per unit depth (1/mm) along one ray of polar cosine cos_in inside the
// binder, τ(ϑ) / cos ϑ with τ = D⟨S⟩(⟨s⟩ − ⟨t_p⟩) + κ + (16π/3) c₁ (§5.3.3).
inline double optical_thickness_per_depth(double flake_area_density, double projected_area,
                                          double projected_transmittance, double absorption,
                                          double rayleigh_weight, double cos_in) {
  const double tau = flake_area_density * (projected_area - projected_transmittance) + absorption +
                     16.0 * std::numbers::pi / 3.0 * rayleigh_weight;
  return tau / cos_in;
}

// Fraction of the flakes in a layer of depth H that are seen directly, (1 − e^{−tH}) / (tH),
// stable for tH → 0.
inline double direct_fraction(double t_per_depth, double depth) {
  const double x = t_per_depth * depth;
  if (x < 1e-6) return 1.0 - 0.5 * x;
  return -std::expm1(-x) / x;
}

// Eq. 4: probability that a flake has the orientation mirroring a light of angular radius
// delta_in (inside the binder) into the eye: P(β) Δ² / (8 cos α).
inline double mirror_probability(double orientation_density, double delta_in, double cos_alpha) {
  return orientation_density * delta_in * delta_in / (8.0 * cos_alpha);
}

// Eqs. 5–6: expected number of sparkles among `flake_count` flakes (D·Σ·H) in a cell. With
// masking/shadowing every depth holds sparkles and their light is attenuated; without it
// only the directly visible fraction holds sparkles, unattenuated.
inline double expected_sparkles_with_masking(double flake_count, double mirror_prob) {
  return flake_count * mirror_prob;
}
inline double expected_sparkles_without_masking(double flake_count, double mirror_prob,
                                                double t_per_depth, double depth) {
  return direct_fraction(t_per_depth, depth) * flake_count * mirror_prob;
}

// Eqs. 9–10 without the flake area and depth factor: power reflected by a flake of unit area
// into the view, per unit illuminance `irradiance` of the cell (flux per surface area):
// (I / cos ϑ′_p)(1 − r_η(ϑ))(1 − r_η(ϑ′)) r_p(cos α) cos α.
inline double sparkle_energy_per_area(double irradiance, double cos_light_in,
                                      double transmission_in, double transmission_out,
                                      double flake_reflectance, double cos_alpha) {
  return irradiance / cos_light_in * transmission_in * transmission_out * flake_reflectance *
         cos_alpha;
}

// §5.3.5 step 5: the visible radiance of energy E spread over a surface area Σ seen at
// polar cosine cos_view. The mirror returns the light's cone (radius delta_in inside the
// binder) which leaves the surface widened by η² cos ϑ_p / cos ϑ, so the solid angle is
// Ω = πΔᵢ² η² cos ϑ_p / cos ϑ and L = E / (Ω Σ cos ϑ).
inline double visible_radiance(double energy, double delta_in, double eta, double cos_view_in,
                               double surface_area) {
  return energy / (std::numbers::pi * delta_in * delta_in * eta * eta * cos_view_in * surface_area);
}

}  // namespace impasto::flakes
