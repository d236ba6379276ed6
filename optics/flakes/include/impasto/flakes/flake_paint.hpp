#pragma once
// What a flake paint is made of: the flakes (how many, how big, how they lie, what their
// surface reflects) and the binder they float in. Read from data/flakes/*.flake.
#include <string>
#include <vector>

#include "impasto/flakes/thin_film.hpp"

namespace impasto::flakes {

// Distribution of the polar angle β (radians) between a flake's normal and the paint's
// normal. Densities are relative; FlakeTables normalises them so ∫₀^{π/2} P(β) sin β dβ = 1.
struct OrientationDistribution {
  enum class Kind { gaussian, table };
  Kind kind = Kind::gaussian;
  double gaussian_sd_rad = 0.15;       // gaussian: P(β) ∝ exp(−β² / 2σ²)
  std::vector<double> table_beta_rad;  // table: increasing angles from 0
  std::vector<double> table_density;   // table: relative density at those angles (linear between)

  // Relative (unnormalised) density at β; zero past the table's last angle.
  double relative_density(double beta_rad) const;
  // The largest β with non-negligible density (where integrals can stop).
  double support_rad() const;
};

// A named material of a film layer: a constant real index or a built-in dispersion.
struct FilmMaterial {
  std::string name;  // "rutile" (Devore 1951) or empty for a constant index
  double constant_index = 1.0;
  double index_at(double wavelength_nm) const;
};

struct FilmLayerSpec {
  FilmMaterial material;
  double thickness_nm = 0;
};

// The reflecting coating of a flake: an opaque metal (complex index per wavelength) or a
// transparent thin-film stack (pearlescent: TiO₂ on mica), which also transmits.
struct FlakeCoating {
  enum class Kind { metal, thin_film };
  Kind kind = Kind::metal;
  std::string source;                  // where the optical constants come from (metadata)
  std::vector<double> wavelengths_nm;  // metal: increasing
  std::vector<double> n, k;            // metal: complex index n + ik at those wavelengths
  std::vector<FilmLayerSpec> layers;   // thin_film: in the order the light meets them
  // thin_film: index of a thick core (mica) coated with `layers` on both faces; 0 for a
  // free-standing coherent stack with binder on both sides.
  double core_index = 0;

  // Reflectance r_p and transmittance t_p of the coating seen from a binder of index
  // binder_index, at incidence cosine cos_alpha on the flake. Metal n, k are interpolated
  // linearly and held constant past the table's ends.
  FilmOptics optics(double wavelength_nm, double cos_alpha, double binder_index) const;
};

struct FlakePaint {
  std::string name;
  double area_density_per_mm = 0;  // D⟨S⟩: flake area (one side) per paint volume, mm²/mm³
  double flake_area_mean_mm2 = 0;  // ⟨S⟩
  double flake_area_sd_mm2 = 0;    // deviation of S
  OrientationDistribution orientation;
  FlakeCoating coating;
  double binder_index = 1.5;            // η of the binder relative to air
  double binder_absorption_per_mm = 0;  // κ
  double rayleigh_weight_per_mm = 0;    // c₁: pigment scattering per steradian, σ = 16π/3 c₁
};

// Throws std::runtime_error naming the first field of a paint built in code (not read from
// a file, which is checked as it is read) that is not finite or out of its range.
void validate(const FlakePaint& paint);

}  // namespace impasto::flakes
