#include "impasto/render/surface_brdf.hpp"

#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

namespace impasto::render::surface {
namespace {

constexpr double kPi = std::numbers::pi;

// 9-point Gauss–Hermite rule (∫ e^(−x²) f(x) dx), for the Poisson mixture at large g.
constexpr std::array<double, 5> kHermiteNodes{0.0, 0.7235510187528376, 1.468553289216668,
                                              2.266580584531843, 3.190993201781528};
constexpr std::array<double, 5> kHermiteWeights{0.7202352156060510, 0.4326515590025558,
                                                0.08847452739437657, 0.004943624275536947,
                                                0.00003960697726326438};
// Above this phase variance the mixture is summed as m ~ Normal(g, g) (the Poisson's normal
// limit; every node then has m > 0). Below it, term by term.
constexpr double kPoissonNormalFrom = 25.0;

double gaussian_2d(double rho_squared, double variance) {
  return std::exp(-rho_squared / (2.0 * variance)) / (2.0 * kPi * variance);
}

}  // namespace

double binder_index(double wavelength_nm, double n_d) {
  const double um = wavelength_nm * 1e-3;
  constexpr double kCauchyB = 0.0042;  // µm²
  return n_d + kCauchyB * (1.0 / (um * um) - 1.0 / (0.5893 * 0.5893));
}

double smith_shadowing(double cos_theta, double slope_rms) {
  const double mu = std::clamp(cos_theta, 0.0, 1.0);
  if (!(slope_rms > 0.0)) return 1.0;
  if (mu <= 0.0) return 0.0;
  // Beckmann's α = √2 × the RMS slope per axis; a = 1 / (α tan θ).
  const double a = mu / (std::sqrt(2.0) * slope_rms * std::sqrt(std::max(1e-300, 1.0 - mu * mu)));
  if (a > 8.0) return 1.0;  // Λ below 1e-28
  const double lambda = 0.5 * (std::exp(-a * a) / (a * std::sqrt(kPi)) - std::erfc(a));
  return 1.0 / (1.0 + lambda);
}

double ghs_kernel(const GhsParams& p, double cos_i, double cos_o, double rho) {
  const double lambda_um = p.wavelength_nm * 1e-3;
  const double phase = 2.0 * kPi * p.roughness.rms_um / lambda_um * (cos_i + cos_o);
  const double g = phase * phase;
  const double l_hat = p.roughness.correlation_um / lambda_um;
  const double per_m = 1.0 / (2.0 * kPi * kPi * l_hat * l_hat);
  const double tilt = (cos_i + cos_o) * p.subcell_slope_rms;
  const double source2 = p.source_sigma * p.source_sigma + tilt * tilt;
  const double rho2 = rho * rho;
  if (g <= kPoissonNormalFrom) {
    // Term by term until what is left of the Poisson mass is below 1e-9; terms that weigh
    // less than that are skipped (their Gaussians are bounded by the first one's peak).
    double weight = std::exp(-g);
    double left = 1.0 - weight;
    double sum = weight * gaussian_2d(rho2, source2);
    for (int m = 1; left > 1e-9 && m < 200; ++m) {
      weight *= g / m;
      left -= weight;
      if (weight > 1e-9) sum += weight * gaussian_2d(rho2, per_m * m + source2);
    }
    return sum;
  }
  const double spread = std::sqrt(2.0 * g);
  double sum = kHermiteWeights[0] * gaussian_2d(rho2, per_m * g + source2);
  for (std::size_t k = 1; k < kHermiteNodes.size(); ++k) {
    for (double sign : {-1.0, 1.0}) {
      const double m = g + sign * spread * kHermiteNodes[k];
      sum += kHermiteWeights[k] * gaussian_2d(rho2, per_m * m + source2);
    }
  }
  return sum / std::sqrt(kPi);
}

GhsBrdf::GhsBrdf(const GhsParams& params) : params_(params) {
  const auto& r = params_.roughness;
  if (!(r.rms_um >= 0.0 && std::isfinite(r.rms_um)) ||
      !(r.correlation_um > 0.0 && std::isfinite(r.correlation_um)) ||
      !(params_.wavelength_nm > 0.0) || !(params_.index >= 1.0) ||
      !(params_.source_sigma > 0.0 && params_.source_sigma < 1.0)) {
    throw std::runtime_error(
        "surface: GHS parameters out of range (rms_um >= 0, correlation_um > 0, wavelength > 0, "
        "index >= 1, 0 < source_sigma < 1): rms_um = " +
        std::to_string(r.rms_um) + ", correlation_um = " + std::to_string(r.correlation_um));
  }
  const double lambda_um = params_.wavelength_nm * 1e-3;
  const double l_hat = r.correlation_um / lambda_um;
  const double first_width = std::sqrt(1.0 / (2.0 * kPi * kPi * l_hat * l_hat));
  const double inner = 0.125 * std::min(params_.source_sigma, first_width);
  // Pass 1: what share of the kernel lands on real (non-evanescent) directions; with g
  // varying over the disc it may also exceed 1 a little, and is scaled back the same way.
  for (int k = 0; k < kTableSize; ++k) {
    const double mu = static_cast<double>(k) / (kTableSize - 1);
    const double sin_i = std::sqrt(1.0 - mu * mu);
    const double kept = integrate_disc(mu, inner, [&](double x, double y) {
      const double cos_o = std::sqrt(std::max(0.0, 1.0 - x * x - y * y));
      return ghs_kernel(params_, mu, cos_o, std::hypot(x + sin_i, y));
    });
    renormalisation_[static_cast<std::size_t>(k)] = kept > 1e-12 ? 1.0 / kept : 1.0;
  }
  for (int k = 0; k < kTableSize; ++k) {
    const double mu = static_cast<double>(k) / (kTableSize - 1);
    shadowing_[static_cast<std::size_t>(k)] = smith_shadowing(mu, slope_rms());
  }
  // Pass 2: what single scattering returns of a perfect reflector's light (F = 1), E₁; the
  // rest is scattered again (multiple_, surface_brdf.hpp).
  const auto trapezoid = [](const std::array<double, kTableSize>& table) {  // 2 ∫ t(μ) μ dμ
    double sum = 0.0;
    for (int k = 1; k < kTableSize; ++k) {
      const double a = static_cast<double>(k - 1) / (kTableSize - 1);
      const double b = static_cast<double>(k) / (kTableSize - 1);
      sum += (table[static_cast<std::size_t>(k - 1)] * a + table[static_cast<std::size_t>(k)] * b) *
             (b - a);
    }
    return sum;
  };
  std::array<double, kTableSize> single{};
  for (int k = 0; k < kTableSize; ++k) {
    const double mu = static_cast<double>(k) / (kTableSize - 1);
    const double sin_i = std::sqrt(1.0 - mu * mu);
    single[static_cast<std::size_t>(k)] =
        std::min(1.0, integrate_disc(mu, inner, [&](double x, double y) {
                   const double cos_o = std::sqrt(std::max(0.0, 1.0 - x * x - y * y));
                   return single_scattering(mu, cos_o, std::hypot(x + sin_i, y), 1.0, false);
                 }));
  }
  // 1 − Ē₁ by the quadrature that integrates the lobe in pass 3 (over the interpolated
  // table), so that with F = 1 the two add up to 1 at every incidence.
  const double missed = std::max(0.0, integrate_disc(1.0, inner, [&](double x, double y) {
                                        const double cos_o =
                                            std::sqrt(std::max(0.0, 1.0 - x * x - y * y));
                                        return 1.0 - table_lookup(single, cos_o);
                                      }) / kPi);
  const double single_hemispherical = 1.0 - missed;
  double fresnel_mean = 1.0;  // F̄ = 2 ∫ F(μ) μ dμ
  if (params_.fresnel) {
    constexpr int kSteps = 512;
    fresnel_mean = 0.0;
    for (int k = 0; k < kSteps; ++k) {
      const double mu = (k + 0.5) / kSteps;
      fresnel_mean += 2.0 * fresnel_dielectric(mu, params_.index) * mu / kSteps;
    }
  }
  if (missed > 1e-9) {
    const double fresnel_multiple = fresnel_mean * fresnel_mean * single_hemispherical /
                                    std::max(1e-12, 1.0 - fresnel_mean * missed);
    const double scale = std::sqrt((params_.fresnel ? fresnel_multiple : 1.0) / (kPi * missed));
    for (int k = 0; k < kTableSize; ++k) {
      multiple_[static_cast<std::size_t>(k)] = (1.0 - single[static_cast<std::size_t>(k)]) * scale;
    }
  }
  // Pass 3: the directional albedo of the finished BRDF (dα dβ = cos θ_o dω_o).
  for (int k = 0; k < kTableSize; ++k) {
    const double mu = static_cast<double>(k) / (kTableSize - 1);
    const double sin_i = std::sqrt(1.0 - mu * mu);
    albedo_[static_cast<std::size_t>(k)] = integrate_disc(mu, inner, [&](double x, double y) {
      const double cos_o = std::sqrt(std::max(0.0, 1.0 - x * x - y * y));
      return eval({sin_i, 0.0, mu}, {x, y, cos_o});
    });
  }
  hemispherical_albedo_ = trapezoid(albedo_);
}

double GhsBrdf::table_lookup(const std::array<double, kTableSize>& table, double cos_i) const {
  const double u = std::clamp(cos_i, 0.0, 1.0) * (kTableSize - 1);
  const int k = std::min(static_cast<int>(u), kTableSize - 2);
  const double f = u - k;
  return table[static_cast<std::size_t>(k)] * (1.0 - f) +
         table[static_cast<std::size_t>(k + 1)] * f;
}

double GhsBrdf::renormalisation(double cos_i) const {
  return table_lookup(renormalisation_, cos_i);
}

double GhsBrdf::albedo(double cos_i) const {
  return table_lookup(albedo_, cos_i);
}

double GhsBrdf::shadowing(double cos_i) const {
  return table_lookup(shadowing_, cos_i);
}

double GhsBrdf::multiple(double cos_i) const {
  return table_lookup(multiple_, cos_i);
}

double GhsBrdf::slope_rms() const {
  const double own = std::sqrt(2.0) * params_.roughness.rms_um / params_.roughness.correlation_um;
  return std::hypot(own, params_.subcell_slope_rms);
}

double GhsBrdf::single_scattering(double cos_i, double cos_o, double rho, double cos_half,
                                  bool fresnel) const {
  if (cos_i <= 0.0 || cos_o <= 0.0) return 0.0;
  const double f = fresnel ? fresnel_dielectric(cos_half, params_.index) : 1.0;
  const double renorm = std::min(renormalisation(cos_i), renormalisation(cos_o));
  return f * renorm * shadowing(cos_i) * shadowing(cos_o) * ghs_kernel(params_, cos_i, cos_o, rho);
}

double GhsBrdf::eval(double cos_i, double cos_o, double rho, double cos_half) const {
  if (cos_i <= 0.0 || cos_o <= 0.0) return 0.0;
  return single_scattering(cos_i, cos_o, rho, cos_half, params_.fresnel) +
         multiple(cos_i) * multiple(cos_o);
}

double GhsBrdf::eval(const std::array<double, 3>& l, const std::array<double, 3>& v) const {
  const std::array<double, 3> sum{l[0] + v[0], l[1] + v[1], l[2] + v[2]};
  const double length = std::sqrt(sum[0] * sum[0] + sum[1] * sum[1] + sum[2] * sum[2]);
  const double cos_half =
      length > 0.0 ? (l[0] * sum[0] + l[1] * sum[1] + l[2] * sum[2]) / length : 0.0;
  return eval(l[2], v[2], std::hypot(sum[0], sum[1]), cos_half);
}

Roughness finish_roughness(Finish finish) {
  const paintcore::FinishRoughness r = paintcore::film_roughness(finish);
  return {r.rms_um, r.correlation_um};
}

Roughness roughness_at_log_rms(double log_rms) {
  const paintcore::FinishRoughness r = paintcore::roughness_at_log_rms(log_rms);
  return {r.rms_um, r.correlation_um};
}

}  // namespace impasto::render::surface
