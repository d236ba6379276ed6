#include "impasto/flakes/flake_tables.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

namespace impasto::flakes {

namespace {
const double kMaxHalfSin = std::sin(std::numbers::pi / 4);  // sin(β/2) at β = π/2
constexpr int kBetaSteps = 4096;       // midpoint rule over the orientation's support
constexpr int kCoarseBetaSteps = 256;  // the same for ⟨t_p⟩, whose integrand is costlier
constexpr int kPsiSteps = 64;          // midpoint rule over the azimuth, ⟨t_p⟩ only
constexpr double kMinCos = 1e-6;       // grazing incidence, kept off 0 for the p admittance

// Mean over the azimuth ψ of |a + b cos ψ| (b ≥ 0): the projected area of a unit flake of
// tilt β seen along a ray at ϑ, with a = cos β cos ϑ and b = sin β sin ϑ.
double mean_abs_cos(double a, double b) {
  if (b <= std::fabs(a)) return std::fabs(a);
  return 2.0 / std::numbers::pi * (std::sqrt(b * b - a * a) + a * std::asin(a / b));
}

double cos_at(int i, int samples) {
  return static_cast<double>(i) / (samples - 1);
}
}  // namespace

FlakeTables::FlakeTables(const FlakePaint& paint, std::span<const double> wavelengths_nm)
    : paint_(paint), wavelengths_nm_(wavelengths_nm.begin(), wavelengths_nm.end()) {
  validate(paint);
  for (double nm : wavelengths_nm_) {
    if (!(nm > 0.0) || !std::isfinite(nm)) {
      throw std::runtime_error("flake tables: wavelength node " + std::to_string(nm) +
                               " nm is not a positive, finite wavelength");
    }
  }
  const OrientationDistribution& orientation = paint.orientation;
  const double support = orientation.support_rad();
  if (!(support > 0.0)) throw std::runtime_error("flake orientation distribution is empty");

  // P(β) sin β dβ on a midpoint grid of `steps` over the support, normalised to sum 1.
  struct Quadrature {
    std::vector<double> beta, weight;
    double total = 0;  // ∫ relative density · sin β dβ
  };
  auto quadrature = [&](int steps) {
    Quadrature q;
    const double d_beta = support / steps;
    for (int i = 0; i < steps; ++i) {
      const double b = (i + 0.5) * d_beta;
      q.beta.push_back(b);
      q.weight.push_back(orientation.relative_density(b) * std::sin(b) * d_beta);
      q.total += q.weight.back();
    }
    if (!(q.total > 0.0)) throw std::runtime_error("flake orientation density is zero everywhere");
    for (double& w : q.weight) w /= q.total;
    return q;
  };
  const Quadrature fine = quadrature(kBetaSteps);
  const double total = fine.total;

  orientation_.resize(kOrientationSamples);
  for (int i = 0; i < kOrientationSamples; ++i) {
    const double half_sin = kMaxHalfSin * i / (kOrientationSamples - 1);
    const double b = 2.0 * std::asin(half_sin);
    orientation_[i] = b <= support ? orientation.relative_density(b) / total : 0.0;
  }

  // Flake transmittance, averaged over 400–700 nm (the optical thickness is one number per
  // ray; the colour of the light passing flakes is left to the K-M layers).
  transmittance_.assign(kAngleSamples, 0.0);
  const bool transmits = paint.coating.kind == FlakeCoating::Kind::thin_film;
  if (transmits) {
    constexpr int kGreyNodes = 31;
    for (int j = 0; j < kAngleSamples; ++j) {
      const double c = std::max(kMinCos, cos_at(j, kAngleSamples));
      double sum = 0;
      for (int w = 0; w < kGreyNodes; ++w) {
        sum += paint.coating.optics(400.0 + 10.0 * w, c, paint.binder_index).transmittance;
      }
      transmittance_[j] = sum / kGreyNodes;
    }
  }

  const Quadrature coarse = quadrature(kCoarseBetaSteps);
  projected_area_.resize(kAngleSamples);
  projected_transmittance_.assign(kAngleSamples, 0.0);
  for (int j = 0; j < kAngleSamples; ++j) {
    const double cos_t = cos_at(j, kAngleSamples);
    const double sin_t = std::sqrt(1.0 - cos_t * cos_t);
    double area = 0;
    for (int i = 0; i < kBetaSteps; ++i) {
      if (fine.weight[i] == 0.0) continue;
      area += fine.weight[i] *
              mean_abs_cos(std::cos(fine.beta[i]) * cos_t, std::sin(fine.beta[i]) * sin_t);
    }
    projected_area_[j] = area;
    if (!transmits) continue;
    double transmitted = 0;
    for (int i = 0; i < kCoarseBetaSteps; ++i) {
      if (coarse.weight[i] == 0.0) continue;
      const double a = std::cos(coarse.beta[i]) * cos_t, b = std::sin(coarse.beta[i]) * sin_t;
      double mean = 0;  // over ψ in [0, π], the other half is its mirror image
      for (int k = 0; k < kPsiSteps; ++k) {
        const double c = std::fabs(a + b * std::cos((k + 0.5) * std::numbers::pi / kPsiSteps));
        mean += c * flake_transmittance(c);
      }
      transmitted += coarse.weight[i] * mean / kPsiSteps;
    }
    projected_transmittance_[j] = transmitted;
  }

  reflectance_.resize(wavelengths_nm_.size() * kAngleSamples);
  for (std::size_t w = 0; w < wavelengths_nm_.size(); ++w) {
    for (int j = 0; j < kAngleSamples; ++j) {
      const double c = std::max(kMinCos, cos_at(j, kAngleSamples));
      reflectance_[w * kAngleSamples + j] =
          paint.coating.optics(wavelengths_nm_[w], c, paint.binder_index).reflectance;
    }
  }
}

double FlakeTables::max_half_sin() {
  return kMaxHalfSin;
}

double FlakeTables::orientation_density(double cos_beta) const {
  const double half_sin = std::sqrt(std::max(0.0, 0.5 * (1.0 - cos_beta)));
  if (half_sin > kMaxHalfSin) return 0.0;
  return lerp_table(orientation_, half_sin, kMaxHalfSin);
}

double FlakeTables::projected_area(double cos_theta) const {
  return lerp_table(projected_area_, cos_theta, 1.0);
}

double FlakeTables::projected_transmittance(double cos_theta) const {
  return lerp_table(projected_transmittance_, cos_theta, 1.0);
}

double FlakeTables::flake_reflectance(std::size_t index, double cos_alpha) const {
  const double* row = reflectance_.data() + index * kAngleSamples;
  double u = cos_alpha * (kAngleSamples - 1);
  if (!(u > 0.0)) return row[0];
  if (u >= kAngleSamples - 1) return row[kAngleSamples - 1];
  const int i = static_cast<int>(u);
  const double f = u - i;
  return row[i] + f * (row[i + 1] - row[i]);
}

double FlakeTables::flake_transmittance(double cos_alpha) const {
  return lerp_table(transmittance_, cos_alpha, 1.0);
}

}  // namespace impasto::flakes
