#pragma once
// Gouffé's series for the apparent reflectance of a grey-body cavity with diffuse walls of
// reflectance rho0 (per wavelength), given its view factors F and G.
//
//   rho_1 = rho0 F                                  light out after the first reflection
//   rho_n = rho0^n (1-F) G (1-G)^(n-2),  n >= 2     after the n-th (the rest spreads evenly)
//   rho   = sum rho_n = rho0 F + rho0^2 (1-F) G / (1 - rho0 (1-G))
//   eps   = 1 - rho   = (1-rho0)(1 + rho0 (G-F)) / (1 - rho0 (1-G))
#include "impasto/cracks/cavity.hpp"

namespace impasto::cracks {

// The n-th term rho_n of the series (n >= 1); 0 for n < 1.
double gouffe_term(int n, double rho0, const ViewFactors& vf);

// rho_1 + ... + rho_n: the apparent reflectance counting n reflections.
double gouffe_partial_sum(int n, double rho0, const ViewFactors& vf);

// The first-order (rho0 F) and second-order (rho0 F + rho0^2 (1-F) G) approximations.
inline double apparent_reflectance_first_order(double rho0, const ViewFactors& vf) {
  return rho0 * vf.F;
}
inline double apparent_reflectance_second_order(double rho0, const ViewFactors& vf) {
  return rho0 * vf.F + rho0 * rho0 * (1.0 - vf.F) * vf.G;
}

// The closed form, written as rho (not 1 - eps) so that it keeps full precision when the
// cavity is nearly black. Valid for rho0 in [0, 1]; at rho0 = 1 and G = 0 returns F.
inline double apparent_reflectance(double rho0, const ViewFactors& vf) {
  const double denom = 1.0 - rho0 * (1.0 - vf.G);
  const double multiple = denom > 0.0 ? rho0 * rho0 * (1.0 - vf.F) * vf.G / denom : 0.0;
  return rho0 * vf.F + multiple;
}

// Gouffé's effective emissivity eps = 1 - rho, in his form (the seed's Eq. 14).
inline double apparent_emissivity(double rho0, const ViewFactors& vf) {
  return (1.0 - rho0) * (1.0 + rho0 * (vf.G - vf.F)) / (1.0 - rho0 * (1.0 - vf.G));
}

}  // namespace impasto::cracks
