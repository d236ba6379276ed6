#pragma once
// Kubelka–Munk relations of an opaque (infinitely thick) layer and the paint–air interface:
// the one definition of each, written once on the scalar type. The K/S fit calls them in
// double; the renderer's float reference (render/kubelka_munk_cell.hpp) and its vectorised
// kernels (render/src/spectral_kernels.cpp) in float, inlined into their loops (plain
// arithmetic, no branch a vector cannot select). The layer formulas of finite thickness live
// in render/.
#include <cmath>
#include <concepts>

namespace impasto::data {

// K/S of an opaque layer of reflectance R∞ (IMPaSTo Eq. 5): (1 − R∞)² / (2·R∞), R∞ in (0, 1].
template <std::floating_point Real>
constexpr Real ks_from_reflectance(Real reflectance) {
  const Real absorbed = Real(1) - reflectance;
  return absorbed * absorbed / (Real(2) * reflectance);
}

// Reflectance of an infinitely thick layer (hiding power) of absorption K and scattering S:
// R∞ = a − b with a = 1 + K/S, b = sqrt(a² − 1), written as S / (K + S + sqrt(K (K + 2S))),
// which neither cancels for large K/S nor divides by S; 0 for K = S = 0 (nothing reflects).
// sqrt(K) sqrt(K + 2S) rather than sqrt(K² + 2KS): K² overflows floats from K ≈ 1.8e19.
template <std::floating_point Real>
Real reflectance_infinite(Real absorption, Real scattering) {
  const Real K = absorption;
  const Real S = scattering;
  const Real denominator = K + S + std::sqrt(K) * std::sqrt(K + Real(2) * S);
  return denominator > Real(0) ? S / denominator : Real(0);
}

// The inverse of ks_from_reflectance: R∞ of a layer whose K/S is `ks` >= 0.
template <std::floating_point Real>
Real reflectance_from_ks(Real ks) {
  return reflectance_infinite(ks, Real(1));
}

// The body's share of what is seen from the air (Saunderson, below),
// (1 − k1)(1 − k2) R / (1 − k2 R): the light that crossed the surface into the paint and back
// out, without the surface's own reflection k1. A renderer
// whose surface model draws that reflection (a specular term, a Fresnel) adds this, so k1
// is not counted twice; an instrument that includes the surface reads the two summed.
template <std::floating_point Real>
constexpr Real saunderson_body(Real internal, Real k1, Real k2) {
  return (Real(1) - k1) * (Real(1) - k2) * internal / (Real(1) - k2 * internal);
}

// Saunderson's correction for the paint–air interface, k1 the external (front-surface,
// specular) and k2 the internal reflection coefficient. Body reflectance seen from the air:
//   R_measured = k1 + (1 − k1)(1 − k2) R / (1 − k2 R),
// or with only `seen` of k1 read (an instrument that excludes part of the specular
// reflection; Saunderson::surface_seen): seen·k1 + the body (saunderson_body, above).
template <std::floating_point Real>
constexpr Real saunderson_to_measured(Real internal, Real k1, Real k2, Real seen = Real(1)) {
  return seen * k1 + saunderson_body(internal, k1, k2);
}

// The inverse of saunderson_to_measured, measured → body reflectance.
template <std::floating_point Real>
constexpr Real saunderson_to_internal(Real measured, Real k1, Real k2, Real seen = Real(1)) {
  const Real body = measured - seen * k1;
  return body / ((Real(1) - k1) * (Real(1) - k2) + k2 * body);
}

// The interface of an oil or acrylic film in air, the one default of the K/S fit and the
// renderer (RenderSettings): the bundled pigments in data/pigments are fitted with these.
inline constexpr double kSaundersonK1 = 0.03;
inline constexpr double kSaundersonK2 = 0.65;

// The one range check of a Saunderson coefficient, k1 or k2: [0, 1) (k2 = 1 divides by zero in
// saunderson_to_measured at R = 1; k1 = 1 leaves no light to enter the paint). NaN fails.
constexpr bool saunderson_coefficient_valid(double k) {
  return k >= 0.0 && k < 1.0;
}
inline constexpr const char* kSaundersonCoefficientRange = "in [0, 1)";

// One interface's coefficients, measured → body reflectance and back. surface_seen is the
// share of the surface's own reflection k1 the instrument read: 1 with the specular component
// included (an integrating sphere), 0 with it excluded (45°/0° geometry), between for a probe
// that catches part of it. The light crossing the surface, (1 − k1)(1 − k2), is the same
// whatever the instrument sees, so a paint fitted from any geometry renders the same.
struct Saunderson {
  double k1 = kSaundersonK1, k2 = kSaundersonK2;
  double surface_seen = 1.0;
  double to_internal(double measured) const {
    return saunderson_to_internal(measured, k1, k2, surface_seen);
  }
  double to_measured(double internal) const {
    return saunderson_to_measured(internal, k1, k2, surface_seen);
  }
};

}  // namespace impasto::data
