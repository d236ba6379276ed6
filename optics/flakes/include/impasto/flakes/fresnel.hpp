#pragma once
// Fresnel reflectance of smooth interfaces: the air–binder surface (the surface models and
// the flakes; mirrored in render/gl/shaders/optics_lib.glsl) and a metal flake inside the
// binder (tabulated once per paint). The one home of both formulas.
#include <algorithm>
#include <cmath>
#include <complex>

namespace impasto::flakes {

// Unpolarised reflectance (the exact s and p average) of a ray entering a dielectric of
// relative index eta (> 0) from outside, at incidence cosine cos_i measured outside (clamped
// to [0, 1]): ((eta − 1)/(eta + 1))² head on, 1 at grazing. By reciprocity it is also the
// reflectance of the ray leaving the dielectric along the same pair of directions. Total
// internal reflection (eta < 1, grazing) gives 1.
inline double fresnel_dielectric(double cos_i, double eta) {
  const double c = std::clamp(cos_i, 0.0, 1.0);
  const double sin2_t = (1.0 - c * c) / (eta * eta);
  if (sin2_t >= 1.0) return 1.0;
  const double cos_t = std::sqrt(1.0 - sin2_t);
  const double rs = (c - eta * cos_t) / (c + eta * cos_t);
  const double rp = (eta * c - cos_t) / (eta * c + cos_t);
  return 0.5 * (rs * rs + rp * rp);
}

// Reflectances for s- and p-polarised light at a conductor of complex index n + ik,
// relative to the (real) index of the medium the light comes from.
struct PolarisedReflectance {
  double s = 0, p = 0;
  double unpolarised() const { return 0.5 * (s + p); }
};

inline PolarisedReflectance fresnel_conductor(double cos_i, std::complex<double> relative_index) {
  using C = std::complex<double>;
  const double sin2_i = 1.0 - cos_i * cos_i;
  const C m = relative_index;
  const C cos_t = std::sqrt(C(1.0) - C(sin2_i) / (m * m));  // complex refraction angle
  const C rs = (C(cos_i) - m * cos_t) / (C(cos_i) + m * cos_t);
  const C rp = (m * C(cos_i) - cos_t) / (m * C(cos_i) + cos_t);
  return {std::norm(rs), std::norm(rp)};
}

}  // namespace impasto::flakes
