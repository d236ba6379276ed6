#include "impasto/flakes/lorentz_drude.hpp"

namespace impasto::flakes {

namespace {
// hc in eV·nm: photon energy of a vacuum wavelength.
constexpr double kEvNm = 1239.841984;
}  // namespace

LorentzDrudeMetal rakic_aluminium() {
  return {
      14.98,
      0.523,
      0.047,
      {{0.227, 0.333, 0.162}, {0.050, 0.312, 1.544}, {0.166, 1.351, 1.808}, {0.030, 3.382, 3.473}}};
}

std::complex<double> permittivity(const LorentzDrudeMetal& metal, double wavelength_nm) {
  using C = std::complex<double>;
  const double w = kEvNm / wavelength_nm;
  const double wp2 = metal.plasma_ev * metal.plasma_ev;
  C eps = 1.0 - metal.drude_strength * wp2 / (w * C(w, metal.drude_damping_ev));
  for (const LorentzOscillator& o : metal.oscillators) {
    eps += o.strength * wp2 / C(o.resonance_ev * o.resonance_ev - w * w, -w * o.damping_ev);
  }
  return eps;
}

std::complex<double> refractive_index(const LorentzDrudeMetal& metal, double wavelength_nm) {
  return std::sqrt(permittivity(metal, wavelength_nm));  // principal root: k ≥ 0 for Im ε ≥ 0
}

}  // namespace impasto::flakes
