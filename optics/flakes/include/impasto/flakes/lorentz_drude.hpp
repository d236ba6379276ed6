#pragma once
// Lorentz–Drude model of a metal's dielectric function, used to derive the n, k table of
// the aluminium shipped in data/flakes/.
#include <complex>
#include <vector>

namespace impasto::flakes {

// One interband (Lorentz) oscillator: strength f, damping and resonance energies in eV.
struct LorentzOscillator {
  double strength = 0;
  double damping_ev = 0;
  double resonance_ev = 0;
};

// ε(ω) = 1 − f₀ωp² / (ω(ω + iΓ₀)) + Σ_j f_j ωp² / (ω_j² − ω² − iωΓ_j), energies in eV.
struct LorentzDrudeMetal {
  double plasma_ev = 0;         // ωp
  double drude_strength = 0;    // f₀
  double drude_damping_ev = 0;  // Γ₀
  std::vector<LorentzOscillator> oscillators;
};

// Aluminium, Lorentz–Drude parameters of Rakić, Djurišić, Elazar, Majewski, "Optical
// properties of metallic films for vertical-cavity optoelectronic devices", Appl. Opt. 37,
// 5271 (1998), Table 2 (valid from about 0.1 to 250 µm).
LorentzDrudeMetal rakic_aluminium();

// Relative permittivity at a vacuum wavelength (nm); Im ε ≥ 0 (absorbing).
std::complex<double> permittivity(const LorentzDrudeMetal& metal, double wavelength_nm);

// Complex refractive index n + ik = sqrt(ε), k ≥ 0.
std::complex<double> refractive_index(const LorentzDrudeMetal& metal, double wavelength_nm);

}  // namespace impasto::flakes
