#pragma once
// Kubelka–Munk per-cell maths at one wavelength: the reference that the GLSL shaders mirror
// line by line. Plain inline functions on floats, no containers, no branches that a shader
// could not take. Stages follow IMPaSTo Fig. 6:
//   1. mix:        K, S of a paint layer from pigment concentrations (Eq. 5)
//   2. layer:      reflectance R and transmittance T of a layer of thickness d (Eqs. 7–9,
//                  with the published typo corrected: coth and csch, not tanh and sinh)
//   3. composite:  the layer over whatever lies beneath it (Eq. 10)
// Units: K and S per unit of optical thickness; d in the same unit (see docs/rendering.md
// for the thickness scale that maps millimetres of paint to it).
#include <cmath>

#include "impasto/data/kubelka_munk.hpp"

namespace impasto::render::km {

// A layer's diffuse reflectance and transmittance, both in [0, 1] with R + T <= 1.
struct LayerRT {
  float reflectance;
  float transmittance;
};

// (1 − e^(−x)) / x for x >= 0, accurate also where x is tiny (no cancellation) and equal to
// 1 at x = 0. GLSL has no expm1, so the small-x branch is a short series instead.
inline float one_minus_exp_neg_over_x(float x) {
  if (x < 1e-3f) {
    return 1.0f - x * (0.5f - x * (1.0f / 6.0f));  // error below x³/24 < 5e-11
  }
  return (1.0f - std::exp(-x)) / x;
}

// Stage 2: R and T of a layer with absorption K >= 0, scattering S >= 0 and thickness d >= 0.
//
// With α = K + S and β = sqrt(K (K + 2S)) (that is S·a and S·b of the paper, where
// a = 1 + K/S, b = sqrt(a² − 1)), the corrected Eqs. 8–9
//     R = 1 / (a + b coth(bSd)),  T = b R csch(bSd)
// multiplied through by S and by 2e^(−βd) / β become
//     R = S f / (α f + 1 + e²),   T = 2e / (α f + 1 + e²)
// with e = e^(−βd) and f = (1 − e²) / β = 2d · one_minus_exp_neg_over_x(2βd).
// Nothing here divides by S or by β, so the limits are exact rather than special cases:
//   S = 0 (pure absorber):  β = K, R = 0, T = e^(−Kd)
//   K = 0 (pure scatterer): β = 0, f = 2d, R = Sd / (1 + Sd), T = 1 / (1 + Sd)
//   d = 0:                  R = 0, T = 1
//   βd → ∞:                 e → 0, R → S / (α + β) = a − b, T → 0 (no overflow)
inline LayerRT layer(float absorption, float scattering, float thickness) {
  const float K = absorption;
  const float S = scattering;
  const float alpha = K + S;
  // sqrt(K) sqrt(K + 2S) rather than sqrt(K² + 2KS): K² overflows floats from K ≈ 1.8e19.
  const float beta = std::sqrt(K) * std::sqrt(K + 2.0f * S);
  const float e = std::exp(-beta * thickness);
  const float f = 2.0f * thickness * one_minus_exp_neg_over_x(2.0f * beta * thickness);
  const float denominator = alpha * f + 1.0f + e * e;
  return {S * f / denominator, 2.0f * e / denominator};
}

// Reflectance of an infinitely thick layer (hiding power): R∞ = a − b = S / (α + β), 0 for
// K = S = 0. The formula is data::reflectance_infinite (data/kubelka_munk.hpp), the one the
// K/S fit uses, here on floats.
inline float reflectance_infinite(float absorption, float scattering) {
  return data::reflectance_infinite(absorption, scattering);
}

// Stage 3 (Eq. 10): a layer (R, T) over a substrate of reflectance R_prev, counting every
// inter-reflection between them: R_tot = R + T² R_prev / (1 − R R_prev).
// The denominator vanishes only for R = R_prev = 1, where T = 0: the layer alone is seen.
inline float composite(LayerRT layer, float reflectance_below) {
  const float denominator = 1.0f - layer.reflectance * reflectance_below;
  if (!(denominator > 0.0f)) {
    return layer.reflectance;
  }
  return layer.reflectance +
         layer.transmittance * layer.transmittance * reflectance_below / denominator;
}

// Stage 1 (Eq. 5) is a weighted sum of the pigments' K and S by concentration (pigment
// amount per unit volume): K_mix = Σ c_i K_i, S_mix = Σ c_i S_i. One term of it:
inline void accumulate_pigment(float concentration, float pigment_absorption,
                               float pigment_scattering, float& absorption, float& scattering) {
  absorption += concentration * pigment_absorption;
  scattering += concentration * pigment_scattering;
}

// The paint's surface over its body (Saunderson), k1 the external (front-surface) and k2 the
// internal reflection coefficient: the body's light as it leaves through the surface,
//   (1 − k1)(1 − k2) R / (1 − k2 R),
// without the surface's own reflection k1, which the shading's specular term draws (an
// instrument that includes the surface reads k1 + this: data::saunderson_to_measured, the K/S
// fit's). The K and S in data/ were fitted through this interface; data::kSaundersonK1 and
// K2 are its coefficients. docs/rendering.md, "The paint's surface". Here on floats.
inline float saunderson(float reflectance, float k1, float k2) {
  return data::saunderson_body(reflectance, k1, k2);
}

}  // namespace impasto::render::km
