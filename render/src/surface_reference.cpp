#include "impasto/render/surface_reference.hpp"

#include <unsupported/Eigen/FFT>

#include <algorithm>
#include <cmath>
#include <complex>
#include <numbers>
#include <random>

namespace impasto::render::surface_reference {
namespace {

constexpr double kPi = std::numbers::pi;
using Complex = std::complex<double>;

// In-place 2D FFT of an n×n row-major grid (rows, then columns).
void fft_2d(Eigen::FFT<double>& fft, std::vector<Complex>& grid, int n, bool inverse) {
  std::vector<Complex> line(static_cast<std::size_t>(n)), out(static_cast<std::size_t>(n));
  for (int pass = 0; pass < 2; ++pass) {
    for (int a = 0; a < n; ++a) {
      for (int b = 0; b < n; ++b) {
        line[static_cast<std::size_t>(b)] =
            grid[static_cast<std::size_t>(pass == 0 ? a * n + b : b * n + a)];
      }
      if (inverse) {
        fft.inv(out, line);
      } else {
        fft.fwd(out, line);
      }
      for (int b = 0; b < n; ++b) {
        grid[static_cast<std::size_t>(pass == 0 ? a * n + b : b * n + a)] =
            out[static_cast<std::size_t>(b)];
      }
    }
  }
}

// Signed frequency index of DFT bin k of n.
int signed_bin(int k, int n) {
  return k < n / 2 ? k : k - n;
}

}  // namespace

KernelProfile wave_optics_kernel(const surface::GhsParams& p, double gamma_sum, int realisations,
                                 std::uint64_t seed) {
  const double lambda = p.wavelength_nm * 1e-3;  // µm
  const double sigma = p.roughness.rms_um, ell = p.roughness.correlation_um;
  // The window whose |FT|² has per-axis spread source_sigma in direction cosines.
  const double window = lambda / (2.0 * std::numbers::sqrt2 * kPi * p.source_sigma);
  // Direction cosines reach |t| <= λ / (2Δ): cover the lobe (slopes √2σ/ℓ times γ-sum) twice.
  const double lobe = std::max(2.0, 4.0 * std::numbers::sqrt2 * sigma / ell * gamma_sum + 1.0);
  const double spacing = std::min(lambda / (2.0 * lobe), ell / 4.0);
  int n = 64;
  while (n < 1024 && n * spacing < 8.0 * window) n *= 2;
  const double length = n * spacing;
  KernelProfile profile;
  profile.rho_step = 0.005;
  const int bins = 400;
  profile.kernel.assign(bins, 0.0);
  std::vector<double> counts(bins, 0.0);
  Eigen::FFT<double> fft;
  std::mt19937_64 random(seed);
  std::normal_distribution<double> normal(0.0, 1.0);
  std::vector<Complex> grid(static_cast<std::size_t>(n) * n);
  double window_area = 0.0;  // A_c = ∫ |w|² ds
  for (int y = 0; y < n; ++y) {
    for (int x = 0; x < n; ++x) {
      const double sx = (x - n / 2) * spacing, sy = (y - n / 2) * spacing;
      const double w = std::exp(-(sx * sx + sy * sy) / (2.0 * window * window));
      window_area += w * w * spacing * spacing;
    }
  }
  const double k = 2.0 * kPi / lambda;
  for (int r = 0; r < realisations; ++r) {
    // Heights: white noise through the filter sqrt(PSD) of the Gaussian ACV σ² e^(−r²/ℓ²),
    // PSD(f) = σ² π ℓ² e^(−π² ℓ² f²), then scaled to the RMS σ of this very sample.
    for (auto& value : grid) value = Complex(normal(random), 0.0);
    fft_2d(fft, grid, n, false);
    for (int y = 0; y < n; ++y) {
      for (int x = 0; x < n; ++x) {
        const double fx = signed_bin(x, n) / length, fy = signed_bin(y, n) / length;
        grid[static_cast<std::size_t>(y * n + x)] *=
            std::exp(-0.5 * kPi * kPi * ell * ell * (fx * fx + fy * fy));
      }
    }
    fft_2d(fft, grid, n, true);
    double sum2 = 0.0, sum = 0.0;
    for (const auto& value : grid) {
      sum += value.real();
      sum2 += value.real() * value.real();
    }
    const double mean = sum / grid.size();
    const double scale = sigma / std::sqrt(std::max(1e-300, sum2 / grid.size() - mean * mean));
    // The reflected field under the window (the seed's Eq. 5, the tilt left out: the mirror
    // direction is at t = 0).
    for (int y = 0; y < n; ++y) {
      for (int x = 0; x < n; ++x) {
        const double sx = (x - n / 2) * spacing, sy = (y - n / 2) * spacing;
        const double w = std::exp(-(sx * sx + sy * sy) / (2.0 * window * window));
        auto& value = grid[static_cast<std::size_t>(y * n + x)];
        const double h = (value.real() - mean) * scale;
        value = w * std::polar(1.0, -k * gamma_sum * h);
      }
    }
    fft_2d(fft, grid, n, false);
    // |U|² Δ⁴ / (λ² A_c): a density in direction cosines t = λ f (integrates to 1).
    const double norm = std::pow(spacing, 4) / (lambda * lambda * window_area);
    for (int y = 0; y < n; ++y) {
      for (int x = 0; x < n; ++x) {
        const double tx = lambda * signed_bin(x, n) / length;
        const double ty = lambda * signed_bin(y, n) / length;
        const int bin = static_cast<int>(std::hypot(tx, ty) / profile.rho_step);
        if (bin >= bins) continue;
        profile.kernel[static_cast<std::size_t>(bin)] +=
            std::norm(grid[static_cast<std::size_t>(y * n + x)]) * norm;
        counts[static_cast<std::size_t>(bin)] += 1.0;
      }
    }
  }
  for (int b = 0; b < bins; ++b) {
    const auto i = static_cast<std::size_t>(b);
    profile.kernel[i] = counts[i] > 0.0 ? profile.kernel[i] / counts[i] : 0.0;
  }
  // Empty bins (finer than the FFT's grid near ρ = 0) take their neighbour's value.
  for (int b = 1; b < bins; ++b) {
    const auto i = static_cast<std::size_t>(b);
    if (counts[i] == 0.0) profile.kernel[i] = profile.kernel[i - 1];
  }
  return profile;
}

LayerWalk random_walk_layer(const dipole::Medium& m, double thickness_mm, double ground_albedo,
                            double radius_mm, int photons, std::uint64_t seed) {
  std::mt19937_64 random(seed);
  std::uniform_real_distribution<double> uniform(0.0, 1.0);
  const double extinction = m.absorption_per_mm + m.reduced_scattering_per_mm;
  const double albedo = extinction > 0.0 ? m.reduced_scattering_per_mm / extinction : 0.0;
  LayerWalk walk;
  double exits = 0.0, beyond = 0.0, radius_sum = 0.0;
  for (int i = 0; i < photons; ++i) {
    // Enters at the origin straight down (refracted light head on), weight 1.
    double x = 0.0, y = 0.0, z = 0.0;  // z: depth below the surface
    double dx = 0.0, dy = 0.0, dz = 1.0;
    double weight = 1.0;
    for (int event = 0; event < 100000 && weight > 1e-4; ++event) {
      const double step = extinction > 0.0 ? -std::log(1.0 - uniform(random)) / extinction
                                           : std::numeric_limits<double>::infinity();
      const double to_boundary = dz > 0.0   ? (thickness_mm - z) / dz
                                 : dz < 0.0 ? -z / dz
                                            : std::numeric_limits<double>::infinity();
      if (step < to_boundary) {
        x += step * dx;
        y += step * dy;
        z += step * dz;
        weight *= albedo;
        // Isotropic scattering (the reduced coefficients absorb the anisotropy).
        const double cz = 2.0 * uniform(random) - 1.0;
        const double phi = 2.0 * kPi * uniform(random);
        const double s = std::sqrt(1.0 - cz * cz);
        dx = s * std::cos(phi);
        dy = s * std::sin(phi);
        dz = cz;
        continue;
      }
      x += to_boundary * dx;
      y += to_boundary * dy;
      if (dz > 0.0) {
        // The ground: absorbed, or reflected diffusely (cosine-weighted) upward.
        z = thickness_mm;
        weight *= ground_albedo;
        const double u = uniform(random), phi = 2.0 * kPi * uniform(random);
        const double s = std::sqrt(u);
        dx = s * std::cos(phi);
        dy = s * std::sin(phi);
        dz = -std::sqrt(1.0 - u);
        continue;
      }
      // The top: leaves with 1 − F (seen from inside), else is reflected back down.
      z = 0.0;
      const double cos_inside = -dz;
      const double sin_out = m.eta * std::sqrt(std::max(0.0, 1.0 - cos_inside * cos_inside));
      double reflect = 1.0;
      if (sin_out < 1.0) {
        reflect = surface::fresnel_dielectric(std::sqrt(1.0 - sin_out * sin_out), m.eta);
      }
      if (uniform(random) >= reflect) {
        const double r = std::hypot(x, y);
        exits += weight;
        radius_sum += weight * r;
        if (r > radius_mm) beyond += weight;
        break;
      }
      dz = -dz;
    }
  }
  walk.reflectance = exits / photons;
  walk.beyond_share = exits > 0.0 ? beyond / exits : 0.0;
  walk.mean_exit_radius_mm = exits > 0.0 ? radius_sum / exits : 0.0;
  return walk;
}

}  // namespace impasto::render::surface_reference
