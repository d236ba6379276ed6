// Gouffé's series and closed form: sums, limits and monotonicity, for every shape.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "impasto/cracks/gouffe.hpp"

namespace impasto::cracks {
namespace {

TEST(GouffeSeries, PartialSumsConvergeToTheClosedForm) {
  for (double rho0 : {0.05, 0.35, 0.8, 0.95}) {
    for (ViewFactors vf :
         {ViewFactors{0.9, 0.8}, ViewFactors{0.2, 0.05}, ViewFactors{0.01, 0.02}}) {
      const double closed = apparent_reflectance(rho0, vf);
      double previous_gap = INFINITY;
      for (int n = 1; n <= 2000; n *= 2) {
        const double gap = closed - gouffe_partial_sum(n, rho0, vf);
        // Terms are positive, so partial sums rise monotonically towards the limit, and the
        // tail after n terms is the geometric rest rho_{n+1} / (1 - rho0 (1 - G)).
        EXPECT_GE(gap, -1e-15);
        EXPECT_LE(gap, previous_gap);
        const double tail = gouffe_term(n + 1, rho0, vf) / (1.0 - rho0 * (1.0 - vf.G));
        EXPECT_NEAR(gap, tail, 1e-12 + 1e-9 * closed);
        previous_gap = gap;
      }
      EXPECT_NEAR(gouffe_partial_sum(5000, rho0, vf), closed, 1e-12);
    }
  }
}

TEST(GouffeSeries, TermsAreTheDocumentedOnes) {
  const ViewFactors vf{0.3, 0.2};
  const double rho0 = 0.6;
  EXPECT_DOUBLE_EQ(gouffe_term(1, rho0, vf), rho0 * 0.3);
  EXPECT_DOUBLE_EQ(gouffe_term(2, rho0, vf), rho0 * rho0 * 0.7 * 0.2);
  EXPECT_DOUBLE_EQ(gouffe_term(3, rho0, vf), std::pow(rho0, 3) * 0.7 * 0.2 * 0.8);
  EXPECT_DOUBLE_EQ(gouffe_partial_sum(1, rho0, vf), apparent_reflectance_first_order(rho0, vf));
  EXPECT_DOUBLE_EQ(gouffe_partial_sum(2, rho0, vf), apparent_reflectance_second_order(rho0, vf));
  EXPECT_EQ(gouffe_term(0, rho0, vf), 0.0);
}

TEST(GouffeSeries, ClosedFormIsOneMinusGouffesEmissivity) {
  for (double rho0 = 0.0; rho0 <= 1.0; rho0 += 0.05) {
    for (double F = 0.0; F <= 1.0; F += 0.1) {
      for (double G = 0.05; G <= 1.0; G += 0.1) {
        EXPECT_NEAR(apparent_reflectance(rho0, {F, G}), 1.0 - apparent_emissivity(rho0, {F, G}),
                    1e-12);
      }
    }
  }
}

TEST(GouffeSeries, ShallowCavityReflectsLikeItsWalls) {
  for (CavityShape shape : kAllShapes) {
    for (double rho0 : {0.05, 0.5, 0.95}) {
      const double rho = apparent_reflectance(rho0, view_factors(shape, {1e-7, 1.0}));
      EXPECT_NEAR(rho, rho0, 1e-6) << shape_name(shape);
      EXPECT_NEAR(apparent_reflectance(rho0, view_factors(shape, {0.0, 1.0})), rho0, 1e-12);
    }
  }
}

TEST(GouffeSeries, DeepCavityIsBlack) {
  for (CavityShape shape : kAllShapes) {
    double last_eps = 0.0;
    for (double depth : {1e2, 1e4, 1e6}) {
      const double eps = apparent_emissivity(0.9, view_factors(shape, {depth, 1.0}));
      EXPECT_GT(eps, last_eps) << shape_name(shape);  // closer to 1 each time
      last_eps = eps;
    }
    EXPECT_NEAR(apparent_emissivity(0.9, view_factors(shape, {1e6, 1.0})), 1.0, 1e-4)
        << shape_name(shape);
  }
}

TEST(GouffeSeries, DeeperIsDarkerAndWiderIsBrighter) {
  for (CavityShape shape : kAllShapes) {
    for (double rho0 : {0.2, 0.6, 0.95}) {
      double last = 2.0;
      for (double depth = 0.05; depth < 40.0; depth *= 1.3) {
        const double rho = apparent_reflectance(rho0, view_factors(shape, {depth, 1.0}));
        EXPECT_LT(rho, last) << shape_name(shape) << " depth " << depth;
        last = rho;
      }
      last = -1.0;
      for (double half_width = 0.02; half_width < 20.0; half_width *= 1.3) {
        const double rho = apparent_reflectance(rho0, view_factors(shape, {1.0, half_width}));
        EXPECT_GT(rho, last) << shape_name(shape) << " half-width " << half_width;
        last = rho;
      }
    }
  }
}

TEST(GouffeSeries, ViewFactorsStayInTheUnitInterval) {
  for (CavityShape shape : kAllShapes) {
    for (double depth = 1e-6; depth < 1e6; depth *= 1.7) {
      for (double half_width : {1e-3, 0.1, 1.0, 30.0}) {
        const ViewFactors vf = view_factors(shape, {depth, half_width});
        EXPECT_GE(vf.F, 0.0);
        EXPECT_LE(vf.F, 1.0);
        EXPECT_GE(vf.G, 0.0);
        EXPECT_LE(vf.G, 1.0) << shape_name(shape) << " L " << depth << " R " << half_width;
      }
    }
  }
}

TEST(GouffeSeries, SphereHasEqualFactors) {
  // Every point of a sphere sees any part of it in proportion to that part's area, so the
  // deepest point's F equals the walls' mean G: R^2 / (R^2 + L^2).
  for (double depth : {0.1, 1.0, 7.0}) {
    const ViewFactors vf = view_factors(CavityShape::SpherePit, {depth, 1.0});
    EXPECT_NEAR(vf.F, vf.G, 1e-14);
    EXPECT_NEAR(vf.G, 1.0 / (1.0 + depth * depth), 1e-14);
  }
}

TEST(GouffeSeries, KnownAreaRatios) {
  const CavityDims d{2.0, 0.5};
  EXPECT_NEAR(view_factors(CavityShape::CylinderPit, d).G, 0.5 / (0.5 + 4.0), 1e-14);
  EXPECT_NEAR(view_factors(CavityShape::BoxGroove, d).G, 0.5 / 2.5, 1e-14);
  EXPECT_NEAR(view_factors(CavityShape::ConePit, d).G, 0.5 / std::sqrt(4.25), 1e-14);
  // Semicircular groove (L = R): chord 2R over half circumference pi R.
  EXPECT_NEAR(view_factors(CavityShape::ArcGroove, {1.0, 1.0}).G, 2.0 / std::numbers::pi, 1e-14);
}

TEST(GouffeSeries, BadSizesAreRejected) {
  EXPECT_THROW(view_factors(CavityShape::VGroove, {NAN, 1.0}), std::runtime_error);
  EXPECT_THROW(view_factors(CavityShape::VGroove, {1.0, 0.0}), std::runtime_error);
  EXPECT_THROW(view_factors(CavityShape::VGroove, {-1.0, 1.0}), std::runtime_error);
  EXPECT_THROW(view_factors(CavityShape::VGroove, {INFINITY, 1.0}), std::runtime_error);
  EXPECT_THROW(shape_from_name("hexagon"), std::runtime_error);
  for (CavityShape shape : kAllShapes) EXPECT_EQ(shape_from_name(shape_name(shape)), shape);
}

}  // namespace
}  // namespace impasto::cracks
