// Kubelka–Munk per-cell maths at one wavelength: a line-by-line port of
// render/include/impasto/render/kubelka_munk_cell.hpp (the CPU reference; see its comments for
// the derivation and the limits these forms keep exact). Included after #version.

// (1 - e^-x) / x, with a short series where x is tiny (GLSL has no expm1).
float km_one_minus_exp_neg_over_x(float x) {
  if (x < 1e-3) return 1.0 - x * (0.5 - x * (1.0 / 6.0));
  return (1.0 - exp(-x)) / x;
}

// R (x) and T (y) of a layer with absorption K, scattering S and optical thickness d.
vec2 km_layer(float K, float S, float d) {
  float alpha = K + S;
  float beta = sqrt(K) * sqrt(K + 2.0 * S);
  float e = exp(-beta * d);
  float f = 2.0 * d * km_one_minus_exp_neg_over_x(2.0 * beta * d);
  float denominator = alpha * f + 1.0 + e * e;
  return vec2(S * f / denominator, 2.0 * e / denominator);
}

// Eq. 10: the layer (R, T) over a substrate of reflectance below.
float km_composite(vec2 layer, float below) {
  float denominator = 1.0 - layer.x * below;
  if (!(denominator > 0.0)) return layer.x;
  return layer.x + layer.y * layer.y * below / denominator;
}

// The body's light leaving through the paint's surface: k1 external, k2 internal surface
// reflection; the surface's own reflection (k1) is the shading's specular term. The C++
// reference is data::saunderson_body (data/include/impasto/data/kubelka_munk.hpp), which
// km::saunderson and the CPU kernels call.
float km_saunderson(float R, float k1, float k2) {
  return (1.0 - k1) * (1.0 - k2) * R / (1.0 - k2 * R);
}
