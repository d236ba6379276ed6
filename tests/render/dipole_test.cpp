// Jensen's dipole (dipole.hpp): its profile carries exactly the closed-form total diffuse
// reflectance, the K-M mapping, and where the diffusion picture meets K-M's.
#include "impasto/render/dipole.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "impasto/render/kubelka_munk_cell.hpp"

using namespace impasto::render;

namespace {

// ∫ 2πr R_d(r) dr by the substitution r = z·u/(1−u) (midpoints): the profile spans
// decades, from the mean free path to many diffusion lengths.
double integrated_profile(const dipole::Medium& m) {
  const double scale = 1.0 / (m.absorption_per_mm + m.reduced_scattering_per_mm);
  constexpr int kSteps = 200000;
  double total = 0.0;
  for (int k = 0; k < kSteps; ++k) {
    const double u = (k + 0.5) / kSteps;
    const double r = scale * u / (1.0 - u);
    const double dr = scale / ((1.0 - u) * (1.0 - u)) / kSteps;
    total += 2.0 * 3.14159265358979323846 * r * dipole::profile(m, r) * dr;
  }
  return total;
}

}  // namespace

TEST(Dipole, ProfileIntegratesToTheClosedForm) {
  for (double eta : {1.0, 1.33, 1.48}) {
    for (double albedo : {0.3, 0.8, 0.95, 0.99, 0.999}) {
      dipole::Medium m;
      m.reduced_scattering_per_mm = 100.0 * albedo;
      m.absorption_per_mm = 100.0 * (1.0 - albedo);
      m.eta = eta;
      EXPECT_NEAR(dipole::reduced_albedo(m), albedo, 1e-12);
      const double closed = dipole::total_reflectance(m);
      EXPECT_NEAR(integrated_profile(m), closed, 2e-4 * closed + 1e-7)
          << "eta " << eta << ", albedo " << albedo;
    }
  }
}

TEST(Dipole, ConservesEnergy) {
  // Never more out than in, and a boundary that reflects more inside keeps more light in
  // (for the same medium: the image source is further off).
  dipole::Medium m{0.01, 50.0, 1.0};
  double last = 1.0;
  for (double eta : {1.0, 1.2, 1.4, 1.6}) {
    m.eta = eta;
    const double r = dipole::total_reflectance(m);
    EXPECT_LE(r, 1.0);
    EXPECT_GT(r, 0.0);
    EXPECT_LT(r, last + 1e-12);
    last = r;
  }
  EXPECT_EQ(dipole::total_reflectance({1.0, 0.0, 1.48}), 0.0);  // pure absorber
}

TEST(Dipole, DiffuseFresnelAtAMatchedBoundaryIsNearZero) {
  EXPECT_NEAR(dipole::diffuse_fresnel_reflectance(1.0), 0.0, 0.005);
  EXPECT_GT(dipole::diffuse_fresnel_reflectance(1.48), 0.5);  // oil: most diffuse light stays in
}

TEST(Dipole, KubelkaMunkMappingRoundTrips) {
  // σ_a = K/2, σ_s' = (4/3)(S + K/8), per mm at thickness_scale mm per K-M unit.
  const double K = 0.3, S = 2.0, scale = 0.005;
  const dipole::Medium m = dipole::from_kubelka_munk(K, S, scale);
  EXPECT_NEAR(2.0 * m.absorption_per_mm * scale, K, 1e-12);
  EXPECT_NEAR((0.75 * m.reduced_scattering_per_mm - 0.25 * m.absorption_per_mm) * scale, S, 1e-12);
  EXPECT_NEAR(dipole::diffusion_length_mm(m),
              1.0 / std::sqrt(3.0 * m.absorption_per_mm *
                              (m.absorption_per_mm + m.reduced_scattering_per_mm)),
              1e-15);
}

TEST(Dipole, AgreesWithKubelkaMunkForScatteringPaint) {
  // Two diffusion models of the same paint: at a matched boundary and high albedo (where the
  // diffusion approximation holds) the dipole's total reflectance and K-M's R∞ agree.
  for (double k_over_s : {0.001, 0.003, 0.01, 0.03}) {
    const dipole::Medium m = dipole::from_kubelka_munk(k_over_s, 1.0, 0.005, 1.0);
    const double km_r = km::reflectance_infinite(static_cast<float>(k_over_s), 1.0f);
    std::printf("K/S %g: dipole %.4f, K-M %.4f\n", k_over_s, dipole::total_reflectance(m), km_r);
    EXPECT_NEAR(dipole::total_reflectance(m), km_r, 0.05) << "K/S " << k_over_s;
  }
}
