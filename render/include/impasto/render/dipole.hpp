#pragma once
// Light that travels sideways inside paint: the dipole diffusion approximation of Jensen,
// Marschner, Levoy & Hanrahan (2001), "A practical model for subsurface light transport"
// (ref. 21 of the seed of docs/surface.md), for a semi-infinite medium of reduced
// scattering σ_s', absorption σ_a and relative index η. The CPU reference; derivation and
// the mapping from Kubelka–Munk's K and S in docs/surface.md.
namespace impasto::render::dipole {

// Transport coefficients, per millimetre.
struct Medium {
  double absorption_per_mm = 0.0;          // σ_a
  double reduced_scattering_per_mm = 0.0;  // σ_s' = σ_s (1 − g)
  double eta = 1.48;                       // paint binder over air
};

// K-M coefficients (per unit of K-M optical thickness, thickness_scale_mm of paint) to
// transport coefficients, after van Gemert & Star (1987), "Relations between the
// Kubelka–Munk and the transport equation models for anisotropic scattering", Lasers Life
// Sci. 1:287: K = 2σ_a and S = (3/4)σ_s' − (1/4)σ_a, so σ_a = K/2, σ_s' = (4/3)(S + K/8).
Medium from_kubelka_munk(double absorption, double scattering, double thickness_scale_mm,
                         double eta = 1.48);

// Diffuse Fresnel reflectance F_dr of the boundary seen from inside (Egan & Hilgeman's fit,
// as Jensen et al. Eq. 5 use it), and A = (1 + F_dr)/(1 − F_dr).
double diffuse_fresnel_reflectance(double eta);

// σ_tr = sqrt(3 σ_a σ_t'), the effective extinction; its inverse is the diffusion length.
double effective_extinction_per_mm(const Medium& medium);
// 1 / σ_tr in mm; infinite for a medium that absorbs nothing.
double diffusion_length_mm(const Medium& medium);
// The reduced albedo α' = σ_s' / (σ_a + σ_s').
double reduced_albedo(const Medium& medium);

// R_d(r), the diffuse reflectance profile (per mm²) at distance r (mm) from where a narrow
// beam enters: Jensen et al. Eq. 4, the real source at z_r = 1/σ_t' and its image at
// z_v = z_r (1 + 4A/3).
double profile(const Medium& medium, double r_mm);

// Total diffuse reflectance ∫ 2πr R_d(r) dr in closed form (Jensen et al. Eq. 6):
//   (α'/2) (1 + e^(−(4/3) A sqrt(3(1 − α')))) e^(−sqrt(3(1 − α'))).
double total_reflectance(const Medium& medium);

}  // namespace impasto::render::dipole
