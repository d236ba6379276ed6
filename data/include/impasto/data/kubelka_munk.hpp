#pragma once
// Kubelka–Munk relations for an opaque (infinitely thick) layer, used by the K/S fit.
// The layer formulas of finite thickness live in render/.

namespace impasto::data {

// K/S of an opaque layer of reflectance R∞ (IMPaSTo Eq. 5): (1 − R∞)² / (2·R∞), R∞ in (0, 1].
double ks_from_reflectance(double reflectance);

// The inverse: R∞ = 1 + K/S − sqrt((K/S)² + 2·K/S), for K/S >= 0.
double reflectance_from_ks(double ks);

// Saunderson's correction for the paint–air interface: k1 is the external (specular)
// reflectance, k2 the internal one. Measured → body reflectance, and back.
struct Saunderson {
  double k1 = 0.03, k2 = 0.65;
  double to_internal(double measured) const;
  double to_measured(double internal) const;
};

}  // namespace impasto::data
