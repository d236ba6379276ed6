#pragma once
// Reflectance and transmittance of a stack of thin films (interference), for pearlescent
// flakes: a mica platelet coated with TiO₂, embedded in the binder.
#include <complex>
#include <span>

namespace impasto::flakes {

struct FilmLayer {
  std::complex<double> index;  // complex refractive index n + ik at the wavelength
  double thickness_nm = 0;
};

struct FilmOptics {
  double reflectance = 0;    // unpolarised, fraction of the incident power
  double transmittance = 0;  // into the exit medium
};

// Coherent stack of layers (listed in the order the light meets them) on a substrate of
// real index exit_index, lit from a medium of real index ambient_index at incidence cosine
// cos_i. Characteristic-matrix method, s and p averaged. Without absorption
// reflectance + transmittance = 1.
FilmOptics thin_film_optics(std::span<const FilmLayer> layers, double ambient_index,
                            double exit_index, double wavelength_nm, double cos_i);

// A flake whose thick core (mica, thicker than the coherence length of daylight and varying
// from flake to flake, so its own fringes average out) carries the same coating on both
// faces: the two faces add incoherently, R = R₁ + T₁²R₁ / (1 − R₁²), T = T₁² / (1 − R₁²),
// where `one_face` is the coating lit from the binder onto the core.
FilmOptics coated_core_optics(FilmOptics one_face);

// Ordinary index of rutile TiO₂ from Devore's dispersion formula (J. Opt. Soc. Am. 41, 416,
// 1951): n² = 5.913 + 0.2441 / (λ² − 0.0803), λ in µm.
double rutile_index(double wavelength_nm);

}  // namespace impasto::flakes
