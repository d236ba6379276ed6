// The per-paint tables: normalised orientation density and the projected-area integrals
// against their analytic limits.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <stdexcept>
#include <vector>

#include "flake_test_geometry.hpp"
#include "impasto/flakes/flake_tables.hpp"
#include "test_paints.hpp"

namespace impasto::flakes {
namespace {

using test::kNodes;
using test::kPi;

// ∫₀^{π/2} P(β) sin β dβ through the table look-up.
double orientation_integral(const FlakeTables& tables) {
  const int steps = 200000;
  double sum = 0;
  for (int i = 0; i < steps; ++i) {
    const double beta = (i + 0.5) * (kPi / 2) / steps;
    sum += tables.orientation_density(std::cos(beta)) * std::sin(beta);
  }
  return sum * (kPi / 2) / steps;
}

TEST(FlakeTables, OrientationDensityIsNormalised) {
  for (double sd : {2.0, 10.0, 30.0}) {
    const FlakeTables tables(test::grey_metal_paint(1.5, sd), kNodes);
    EXPECT_NEAR(orientation_integral(tables), 1.0, 2e-3) << sd;
  }
}

TEST(FlakeTables, NarrowGaussianPeaksAtOneOverSigmaSquared) {
  // For small σ, ∫ e^{−β²/2σ²} sin β dβ → σ², so P(0) → 1/σ².
  const double sd = 2.0 * kPi / 180.0;
  const FlakeTables tables(test::grey_metal_paint(1.5, 2.0), kNodes);
  EXPECT_NEAR(tables.orientation_density(1.0) * sd * sd, 1.0, 2e-3);
  const double at_one_sigma = tables.orientation_density(std::cos(sd)) * sd * sd;
  EXPECT_NEAR(at_one_sigma, std::exp(-0.5), 5e-3);
  EXPECT_EQ(tables.orientation_density(std::cos(60.0 * kPi / 180.0)), 0.0);
}

TEST(FlakeTables, FlatFlakesProjectAsTheCosine) {
  const FlakeTables tables(test::grey_metal_paint(1.5, 0.5), kNodes);
  for (double c : {0.1, 0.4, 0.7, 1.0}) EXPECT_NEAR(tables.projected_area(c), c, 2e-3) << c;
}

TEST(FlakeTables, RandomlyOrientedFlakesProjectAHalf) {
  // A density uniform over the hemisphere: the mean |cos| with any ray is 1/2.
  FlakePaint paint = test::grey_metal_paint(1.5);
  paint.orientation.kind = OrientationDistribution::Kind::table;
  paint.orientation.table_beta_rad = {0.0, kPi / 2};
  paint.orientation.table_density = {1.0, 1.0};
  const FlakeTables tables(paint, kNodes);
  EXPECT_NEAR(tables.orientation_density(0.3), 1.0, 1e-6);  // ∫ sin β dβ = 1 already
  for (double c : {0.0, 0.3, 0.8, 1.0}) EXPECT_NEAR(tables.projected_area(c), 0.5, 1e-4) << c;
}

TEST(FlakeTables, MetalFlakesTransmitNothing) {
  const FlakeTables tables(test::shipped_aluminium(), kNodes);
  for (double c : {0.2, 1.0}) {
    EXPECT_EQ(tables.projected_transmittance(c), 0.0);
    EXPECT_GT(tables.flake_reflectance(1, c), 0.8);
  }
}

TEST(FlakeTables, PearlFlakesTransmitPartOfTheirProjectedArea) {
  const FlakeTables tables(test::shipped_pearl(), kNodes);
  for (double c : {0.3, 0.7, 1.0}) {
    const double tp = tables.projected_transmittance(c);
    EXPECT_GT(tp, 0.3 * tables.projected_area(c)) << c;
    EXPECT_LT(tp, tables.projected_area(c)) << c;
  }
  // The flake transmittance is the wavelength average of 1 − r_p for a lossless coating.
  double mean_reflectance = 0;
  for (int w = 0; w < 31; ++w) {
    const FlakePaint& p = tables.paint();
    mean_reflectance += p.coating.optics(400.0 + 10 * w, 1.0, p.binder_index).reflectance / 31;
  }
  EXPECT_NEAR(tables.flake_transmittance(1.0), 1.0 - mean_reflectance, 1e-9);
  EXPECT_GT(tables.flake_reflectance(0, 1.0), tables.flake_reflectance(2, 1.0));  // blue pearl
}

TEST(FlakeTables, PaintsBuiltInCodeAreValidated) {
  FlakePaint paint = test::grey_metal_paint(1.5);
  paint.flake_area_mean_mm2 = std::nan("");
  try {
    FlakeTables tables(paint, kNodes);
    FAIL() << "no error";
  } catch (const std::runtime_error& e) {
    EXPECT_STREQ(e.what(), "flake paint 'grey': bad flake_area_mean_mm2");
  }
  const std::vector<double> bad_nodes{450.0, -1.0};
  EXPECT_THROW(FlakeTables(test::grey_metal_paint(1.5), bad_nodes), std::runtime_error);
}

}  // namespace
}  // namespace impasto::flakes
