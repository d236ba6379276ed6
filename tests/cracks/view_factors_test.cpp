// The analytic view factors against Monte Carlo estimates and closed forms.
#include <gtest/gtest.h>

#include <cmath>

#include "impasto/cracks/close_up.hpp"
#include "impasto/cracks/monte_carlo.hpp"

namespace impasto::cracks {
namespace {

// Within 4.5 standard errors plus a little for the quadrature: a wrong formula is off by
// far more than this (F and G differ by 0.05 to 0.5 between shapes at these sizes).
constexpr double kSigmas = 4.5;

TEST(ViewFactors, AnalyticFAndGMatchMonteCarlo) {
  for (CavityShape shape : kAllShapes) {
    for (double depth : {0.3, 1.0, 4.0}) {
      const CavityDims dims{depth, 1.0};
      const ViewFactors analytic = view_factors(shape, dims);
      const ViewFactorEstimate mc = estimate_view_factors(shape, dims, 20000, 17);
      EXPECT_NEAR(mc.value.F, analytic.F, kSigmas * mc.standard_error.F + 1e-6)
          << shape_name(shape) << " L/R " << depth;
      EXPECT_NEAR(mc.value.G, analytic.G, kSigmas * mc.standard_error.G + 1e-6)
          << shape_name(shape) << " L/R " << depth;
    }
  }
}

TEST(ViewFactors, WallPointsMatchMonteCarlo) {
  for (CavityShape shape : kAllShapes) {
    for (double depth : {0.4, 2.5}) {
      const CavityDims dims{depth, 1.0};
      for (double s : {0.2, 0.55, 0.9}) {
        const CavityWallPoint p = cavity_wall_point(shape, dims, s, 0.7);
        const double analytic = opening_view_factor(shape, dims, p);
        const auto mc = estimate_opening_view_factor(shape, dims, p, 20000, 5);
        EXPECT_NEAR(mc[0], analytic, kSigmas * mc[1] + 2e-4)
            << shape_name(shape) << " L/R " << depth << " s " << s;
      }
    }
  }
}

TEST(ViewFactors, ApexElementsFollowTheDerivation) {
  // At an apex the wall element's plane is tangent to the opening's rim, so it sees the
  // opening (half-angle a, sin a = R / sqrt(R^2 + L^2)) with view factor sin^2 a for a V
  // groove (2-D: (1 - cos 2a) / 2) and sin^3 a for a cone (pi sin^2 a cos(pi/2 - a) / pi).
  for (double depth : {0.5, 2.0, 6.0}) {
    const CavityDims dims{depth, 1.0};
    const double sin_a = 1.0 / std::sqrt(1.0 + depth * depth);
    const CavityWallPoint v = cavity_wall_point(CavityShape::VGroove, dims, 0.0, 1.0);
    EXPECT_NEAR(opening_view_factor(CavityShape::VGroove, dims, v), sin_a * sin_a, 1e-12);
    const CavityWallPoint cone = cavity_wall_point(CavityShape::ConePit, dims, 0.0, 0.3);
    EXPECT_NEAR(opening_view_factor(CavityShape::ConePit, dims, cone), std::pow(sin_a, 3), 1e-6);
  }
}

TEST(ViewFactors, WallAverageOfPointFactorsIsG) {
  // Reciprocity: the area-weighted mean of the wall points' view factors is A / S = G.
  for (CavityShape shape : {CavityShape::ArcGroove, CavityShape::BoxGroove, CavityShape::VGroove}) {
    const CavityDims dims{1.7, 1.0};
    // The profile parameter s is an arc-length fraction, so a plain midpoint rule is
    // area-weighted for grooves.
    constexpr int n = 4000;
    double sum = 0.0;
    for (int i = 0; i < n; ++i) {
      const double s = (i + 0.5) / n;
      sum += opening_view_factor(shape, dims, cavity_wall_point(shape, dims, s, 1.0));
    }
    EXPECT_NEAR(sum / n, view_factors(shape, dims).G, 2e-4) << shape_name(shape);
  }
}

TEST(ViewFactors, FirstReflectionFactorMatchesFirstEscapes) {
  MonteCarloSettings settings;
  settings.paths = 20000;
  for (CavityShape shape : kAllShapes) {
    for (double zenith : {0.0, 0.6}) {
      const CavityDims dims{2.0, 1.0};
      const EscapeHistogram h =
          trace_cavity(shape, dims, Illumination::directional(zenith), settings);
      const double p1 = h.escape_probability(1);
      const double sigma = std::sqrt(p1 * (1.0 - p1) / 20000.0);
      EXPECT_NEAR(first_reflection_view_factor(shape, dims, zenith), p1, kSigmas * sigma + 1e-3)
          << shape_name(shape) << " zenith " << zenith;
    }
  }
}

TEST(ViewFactors, SeedBoundsMissTheExactFactors) {
  // The seed's F = sin^2(theta2) - sin^2(theta1) integrates a band of a cone about the
  // normal, not the opening: at the bottom centre (theta1 = theta2) it gives 0 where the
  // exact value is R^2 / (R^2 + L^2), and at the top of the wall 1 where it is 1/2.
  const CavityDims dims{1.0, 1.0};
  const CavityWallPoint centre = cavity_wall_point(CavityShape::CylinderPit, dims, 0.0, 0.0);
  EXPECT_NEAR(opening_view_factor(CavityShape::CylinderPit, dims, centre), 0.5, 1e-12);
  EXPECT_NEAR(seed_view_factor_cylinder_bottom(dims, 0.0), 0.0, 1e-12);
  const CavityWallPoint rim = cavity_wall_point(CavityShape::CylinderPit, dims, 1.0, 0.0);
  EXPECT_NEAR(opening_view_factor(CavityShape::CylinderPit, dims, rim), 0.5, 1e-12);
  EXPECT_NEAR(seed_view_factor_cylinder_wall(dims, 0.0), 1.0, 1e-12);
}

}  // namespace
}  // namespace impasto::cracks
