#include "impasto/flakes/thin_film.hpp"

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

// Reflectance and transmittance for one polarisation. `admittance(index, cos)` gives the
// tilted optical admittance of a medium: n cos θ for s, n / cos θ for p.
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
  for (const FilmLayer& layer : layers) {
    const C cos_t = cos_in(layer.index);
    const C phase =
        2.0 * std::numbers::pi * layer.index * layer.thickness_nm * cos_t / wavelength_nm;
    const C y = admittance(layer.index, cos_t);
    const C c = std::cos(phase), s = std::sin(phase);
    m = multiply(m, Matrix2{c, C(0, 1) * s / y, C(0, 1) * y * s, c});
  }
  const C b = m[0] + m[1] * y_exit;
  const C cc = m[2] + m[3] * y_exit;
  const C denominator = y_ambient * b + cc;
  const C r = (y_ambient * b - cc) / denominator;
  const double t = 4.0 * y_ambient.real() * y_exit.real() / std::norm(denominator);
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
