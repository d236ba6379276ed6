#include "impasto/data/colorimetry.hpp"

#include <cmath>
#include <numbers>
#include <stdexcept>

namespace impasto::data {
namespace {

constexpr double kStep_nm = 1.0;

// R(λ), holding the end values outside the sampled range.
double held_at(const Spectrum& s, double nm) {
  if (s.wavelengths_nm.empty()) return 0.0;
  if (nm <= s.wavelengths_nm.front()) return s.values.front();
  if (nm >= s.wavelengths_nm.back()) return s.values.back();
  return s.at(nm);
}

// Σ R E x̄, Σ R E ȳ, Σ R E z̄ and Σ E ȳ over the observer's range.
struct Sums {
  Xyz weighted;
  double light_y = 0;
};

Sums integrate(const Spectrum* reflectance, const Spectrum& light,
               const ColorMatchingFunctions& observer) {
  const auto& grid = observer.y.wavelengths_nm;
  if (grid.empty()) throw std::runtime_error("colorimetry: empty colour-matching functions");
  Sums sums;
  const auto count = static_cast<std::size_t>((grid.back() - grid.front()) / kStep_nm + 1e-9) + 1;
  for (std::size_t i = 0; i < count; ++i) {
    const double nm = grid.front() + static_cast<double>(i) * kStep_nm;
    const double e = light.at(nm);
    const double r = reflectance ? held_at(*reflectance, nm) : 1.0;
    const double y = observer.y.at(nm);
    sums.weighted.X += r * e * observer.x.at(nm);
    sums.weighted.Y += r * e * y;
    sums.weighted.Z += r * e * observer.z.at(nm);
    sums.light_y += e * y;
  }
  if (!(sums.light_y > 0.0)) {
    throw std::runtime_error("colorimetry: light '" + light.name +
                             "' has no power where the observer sees");
  }
  return sums;
}

Xyz scaled(const Sums& sums) {
  const double k = 100.0 / sums.light_y;
  return {k * sums.weighted.X, k * sums.weighted.Y, k * sums.weighted.Z};
}

double degrees(double radians) {
  return radians * 180.0 / std::numbers::pi;
}
double radians(double degrees) {
  return degrees * std::numbers::pi / 180.0;
}

// The CIELAB companding function f(t).
double lab_f(double t) {
  constexpr double delta = 6.0 / 29.0;
  return t > delta * delta * delta ? std::cbrt(t) : t / (3.0 * delta * delta) + 4.0 / 29.0;
}

}  // namespace

Xyz reflectance_to_xyz(const Spectrum& reflectance, const Spectrum& light,
                       const ColorMatchingFunctions& observer) {
  return scaled(integrate(&reflectance, light, observer));
}

Xyz white_point(const Spectrum& light, const ColorMatchingFunctions& observer) {
  return scaled(integrate(nullptr, light, observer));
}

Chromaticity chromaticity(const Xyz& xyz) {
  const double sum = xyz.X + xyz.Y + xyz.Z;
  if (sum == 0.0) return {0.0, 0.0};
  return {xyz.X / sum, xyz.Y / sum};
}

Lab xyz_to_lab(const Xyz& xyz, const Xyz& white) {
  const double fx = lab_f(xyz.X / white.X);
  const double fy = lab_f(xyz.Y / white.Y);
  const double fz = lab_f(xyz.Z / white.Z);
  return {116.0 * fy - 16.0, 500.0 * (fx - fy), 200.0 * (fy - fz)};
}

double ciede2000(const Lab& first, const Lab& second) {
  // Notation of Sharma, Wu, Dalal (2005), Eqs. 2–22; hue angles in degrees as there.
  const double c1 = std::hypot(first.a, first.b);
  const double c2 = std::hypot(second.a, second.b);
  const double c_mean = 0.5 * (c1 + c2);
  const double c_mean7 = std::pow(c_mean, 7.0);
  const double g = 0.5 * (1.0 - std::sqrt(c_mean7 / (c_mean7 + std::pow(25.0, 7.0))));
  const double a1 = (1.0 + g) * first.a;
  const double a2 = (1.0 + g) * second.a;
  const double cp1 = std::hypot(a1, first.b);
  const double cp2 = std::hypot(a2, second.b);
  auto hue = [](double b, double a) {
    if (a == 0.0 && b == 0.0) return 0.0;
    const double h = degrees(std::atan2(b, a));
    return h < 0.0 ? h + 360.0 : h;
  };
  const double h1 = hue(first.b, a1);
  const double h2 = hue(second.b, a2);

  const double dL = second.L - first.L;
  const double dC = cp2 - cp1;
  double dh = 0.0;
  if (cp1 * cp2 != 0.0) {
    dh = h2 - h1;
    if (dh > 180.0) dh -= 360.0;
    if (dh < -180.0) dh += 360.0;
  }
  const double dH = 2.0 * std::sqrt(cp1 * cp2) * std::sin(radians(dh / 2.0));

  const double L_mean = 0.5 * (first.L + second.L);
  const double cp_mean = 0.5 * (cp1 + cp2);
  double h_mean = h1 + h2;
  if (cp1 * cp2 != 0.0) {
    if (std::abs(h1 - h2) <= 180.0) {
      h_mean *= 0.5;
    } else {
      h_mean = h_mean < 360.0 ? 0.5 * (h_mean + 360.0) : 0.5 * (h_mean - 360.0);
    }
  }
  const double t =
      1.0 - 0.17 * std::cos(radians(h_mean - 30.0)) + 0.24 * std::cos(radians(2.0 * h_mean)) +
      0.32 * std::cos(radians(3.0 * h_mean + 6.0)) - 0.20 * std::cos(radians(4.0 * h_mean - 63.0));
  const double d_theta = 30.0 * std::exp(-std::pow((h_mean - 275.0) / 25.0, 2.0));
  const double cp_mean7 = std::pow(cp_mean, 7.0);
  const double r_c = 2.0 * std::sqrt(cp_mean7 / (cp_mean7 + std::pow(25.0, 7.0)));
  const double l50 = (L_mean - 50.0) * (L_mean - 50.0);
  const double s_l = 1.0 + 0.015 * l50 / std::sqrt(20.0 + l50);
  const double s_c = 1.0 + 0.045 * cp_mean;
  const double s_h = 1.0 + 0.015 * cp_mean * t;
  const double r_t = -std::sin(radians(2.0 * d_theta)) * r_c;

  const double l_term = dL / s_l;
  const double c_term = dC / s_c;
  const double h_term = dH / s_h;
  return std::sqrt(l_term * l_term + c_term * c_term + h_term * h_term + r_t * c_term * h_term);
}

double reflectance_delta_e(const Spectrum& first, const Spectrum& second, const Spectrum& light) {
  const Xyz white = white_point(light);
  return ciede2000(xyz_to_lab(reflectance_to_xyz(first, light), white),
                   xyz_to_lab(reflectance_to_xyz(second, light), white));
}

}  // namespace impasto::data
