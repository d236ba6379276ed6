// The brute-force references (surface_reference.hpp) against the models they check, in
// small runs: the wave-optics Monte Carlo against the GHS kernel's closed-form statistics,
// the random walk against the dipole's total reflectance and the clear layer's escape cone.
#include "impasto/render/surface_reference.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>

#include "impasto/render/subsurface.hpp"

using namespace impasto::render;

namespace {

// Shares of a radial kernel profile within and beyond a radius.
struct Shares {
  double within = 0.0, beyond = 0.0;
};

template <typename Kernel>
Shares shares(double rho_step, std::size_t bins, double r_in, double r_out, const Kernel& at) {
  Shares s;
  for (std::size_t b = 0; b < bins; ++b) {
    const double rho = (b + 0.5) * rho_step;
    const double mass = at(b, rho) * 2.0 * std::numbers::pi * rho * rho_step;
    if (rho < r_in) s.within += mass;
    if (rho > r_out) s.beyond += mass;
  }
  return s;
}

}  // namespace

TEST(SurfaceReference, WaveOpticsMatchesTheGhsKernel) {
  for (surface::Finish finish : {surface::Finish::satin, surface::Finish::matte}) {
    surface::GhsParams p;
    p.roughness = surface::finish_roughness(finish);
    p.wavelength_nm = 550.0;
    p.source_sigma = 0.013;
    const double gamma_sum = 1.5;
    const auto mc = surface_reference::wave_optics_kernel(p, gamma_sum, 2, 1);
    const auto ref = shares(mc.rho_step, mc.kernel.size(), 0.02, 0.1,
                            [&](std::size_t b, double) { return mc.kernel[b]; });
    const auto ghs = shares(mc.rho_step, mc.kernel.size(), 0.02, 0.1, [&](std::size_t, double rho) {
      return surface::ghs_kernel(p, gamma_sum / 2, gamma_sum / 2, rho);
    });
    std::printf("%d: within 0.02 ghs %.3f mc %.3f; beyond 0.1 ghs %.3f mc %.3f\n",
                static_cast<int>(finish), ghs.within, ref.within, ghs.beyond, ref.beyond);
    EXPECT_NEAR(ref.within, ghs.within, 0.04);
    EXPECT_NEAR(ref.beyond, ghs.beyond, 0.04);
  }
}

TEST(SurfaceReference, RandomWalkMatchesTheDipoleInThickWhitePaint) {
  // Thick, highly scattering paint, where diffusion theory holds.
  const dipole::Medium white = dipole::from_kubelka_munk(0.01, 1.0, 0.005);
  const auto walk = surface_reference::random_walk_layer(white, 2.0, 0.0, 0.05, 8000, 3);
  std::printf("thick white: walk %.3f, dipole %.3f\n", walk.reflectance,
              dipole::total_reflectance(white));
  EXPECT_NEAR(walk.reflectance, dipole::total_reflectance(white), 0.05);
}

TEST(SurfaceReference, ClearLayerReturnsTheGroundsLightWithinAboutItsThickness) {
  // A clear film (no absorption, no scattering) over a white Lambertian ground at a matched
  // boundary (η = 1): everything comes back; half of it within r = d (P(r) = d²/π(r² + d²)²).
  const dipole::Medium clear{0.0, 0.0, 1.0};
  const double d = 0.1;
  const auto walk = surface_reference::random_walk_layer(clear, d, 1.0, d, 20000, 4);
  EXPECT_NEAR(walk.reflectance, 1.0, 1e-9);
  EXPECT_NEAR(walk.beyond_share, 0.5, 0.02);
}
