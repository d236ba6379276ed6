#include "impasto/flakes/thin_film.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>

namespace impasto::flakes {

namespace {
using C = std::complex<double>;

// 2×2 characteristic matrix of a stack, [[m00, m01], [m10, m11]].
using Matrix2 = std::array<C, 4>;

Matrix2 multiply(const Matrix2& a, const Matrix2& b) {
  return {a[0] * b[0] + a[1] * b[2], a[0] * b[1] + a[1] * b[3], a[2] * b[0] + a[3] * b[2],
          a[2] * b[1] + a[3] * b[3]};
}

// cos and sin of a complex phase, both divided by e^|Im phase|, and that exponent: in a thick
// layer where the light is evanescent (or absorbed) |Im phase| reaches thousands, and cos and
// sin themselves overflow.
struct ScaledTrig {
  C cos, sin;
  double log_scale = 0;
};

ScaledTrig scaled_trig(C phase) {
  const double a = phase.real(), b = phase.imag(), g = std::abs(b);
  const C plus = std::polar(std::exp(-b - g), a);   // e^(i phase) e^-g
  const C minus = std::polar(std::exp(b - g), -a);  // e^(-i phase) e^-g
  return {0.5 * (plus + minus), (plus - minus) / C(0, 2), g};
}

// Reflectance and transmittance for one polarisation. `admittance(index, cos)` gives the
// tilted optical admittance of a medium: n cos θ for s, n / cos θ for p. The characteristic
// matrix is kept as m e^log_scale with m's largest entry 1, so a stack of any number and
// thickness of layers stays finite: r does not depend on the scale, and t falls as e^-2 scale.
template <class Admittance>
FilmOptics polarised(std::span<const FilmLayer> layers, double ambient, double exit,
                     double wavelength_nm, double cos_i, Admittance admittance) {
  const double sin_i = std::sqrt(std::fmax(0.0, 1.0 - cos_i * cos_i));
  const C y_ambient = admittance(C(ambient), C(cos_i));
  auto cos_in = [&](C index) {
    const C sin_t = ambient * sin_i / index;  // Snell: n₀ sin θ₀ = n_j sin θ_j
    C cos_t = std::sqrt(C(1) - sin_t * sin_t);
    return cos_t.imag() < 0 ? -cos_t : cos_t;  // the branch that decays into the medium
  };
  const C y_exit = admittance(C(exit), cos_in(C(exit)));
  Matrix2 m{C(1), C(0), C(0), C(1)};
  double log_scale = 0.0;
  for (const FilmLayer& layer : layers) {
    const C cos_t = cos_in(layer.index);
    const C phase =
        2.0 * std::numbers::pi * layer.index * layer.thickness_nm * cos_t / wavelength_nm;
    const C y = admittance(layer.index, cos_t);
    const ScaledTrig trig = scaled_trig(phase);
    m = multiply(m, Matrix2{trig.cos, C(0, 1) * trig.sin / y, C(0, 1) * y * trig.sin, trig.cos});
    double largest = 0.0;
    for (const C& entry : m) largest = std::max(largest, std::abs(entry));
    if (largest > 0.0) {
      for (C& entry : m) entry /= largest;
      log_scale += trig.log_scale + std::log(largest);
    }
  }
  const C b = m[0] + m[1] * y_exit;
  const C cc = m[2] + m[3] * y_exit;
  const C denominator = y_ambient * b + cc;
  const C r = (y_ambient * b - cc) / denominator;
  const double t =
      4.0 * y_ambient.real() * y_exit.real() / std::norm(denominator) * std::exp(-2.0 * log_scale);
  return {std::norm(r), t};
}
}  // namespace

FilmOptics thin_film_optics(std::span<const FilmLayer> layers, double ambient_index,
                            double exit_index, double wavelength_nm, double cos_i) {
  const FilmOptics s = polarised(layers, ambient_index, exit_index, wavelength_nm, cos_i,
                                 [](C n, C cos_t) { return n * cos_t; });
  const FilmOptics p = polarised(layers, ambient_index, exit_index, wavelength_nm, cos_i,
                                 [](C n, C cos_t) { return n / cos_t; });
  return {0.5 * (s.reflectance + p.reflectance), 0.5 * (s.transmittance + p.transmittance)};
}

FilmOptics coated_core_optics(FilmOptics one_face) {
  const double r = one_face.reflectance, t = one_face.transmittance;
  const double bounces = 1.0 / (1.0 - r * r);  // light going back and forth in the core
  return {r + t * t * r * bounces, t * t * bounces};
}

double rutile_index(double wavelength_nm) {
  const double um = wavelength_nm * 1e-3;
  return std::sqrt(5.913 + 0.2441 / (um * um - 0.0803));
}

}  // namespace impasto::flakes
