// The Monte Carlo reference: its generator, determinism, energy, and how close Gouffé's
// formula comes to it (the tolerances measured by `impasto bench cracks`, docs/cracks.md).
#include <gtest/gtest.h>
#include <tbb/task_arena.h>

#include <cmath>

#include "impasto/cracks/gouffe.hpp"
#include "impasto/cracks/monte_carlo.hpp"
#include "impasto/cracks/philox_rng.hpp"

namespace impasto::cracks {
namespace {

TEST(CounterRng, PhiloxKnownAnswers) {
  // Random123's kat_vectors for philox4x32-10.
  EXPECT_EQ(philox4x32_10({0, 0, 0, 0}, {0, 0}),
            (PhiloxCounter{0x6627e8d5, 0xe169c58d, 0xbc57ac4c, 0x9b00dbd8}));
  EXPECT_EQ(philox4x32_10({~0u, ~0u, ~0u, ~0u}, {~0u, ~0u}),
            (PhiloxCounter{0x408f276d, 0x41c83b0e, 0xa20bc7c6, 0x6d5451fd}));
  EXPECT_EQ(
      philox4x32_10({0x243f6a88, 0x85a308d3, 0x13198a2e, 0x03707344}, {0xa4093822, 0x299f31d0}),
      (PhiloxCounter{0xd16cfe09, 0x94fdcceb, 0x5001e420, 0x24126ea1}));
}

TEST(CounterRng, UniformsAreOpenAndBalanced) {
  double sum = 0.0;
  for (std::uint64_t i = 0; i < 10000; ++i) {
    for (double u : uniforms(3, 1, i, 0).u) {
      ASSERT_GT(u, 0.0);
      ASSERT_LT(u, 1.0);
      sum += u;
    }
  }
  EXPECT_NEAR(sum / 40000.0, 0.5, 0.005);  // 3.5 standard errors of a uniform mean
}

MonteCarloSettings small(std::uint64_t paths) {
  MonteCarloSettings s;
  s.paths = paths;
  s.seed = 11;
  return s;
}

TEST(MonteCarlo, SameSeedSameResultOnAnyThreadCount) {
  const CavityDims dims{2.0, 1.0};
  const EscapeHistogram many =
      trace_cavity(CavityShape::CylinderPit, dims, Illumination::diffuse(), small(9000));
  tbb::task_arena one_thread(1);
  EscapeHistogram single;
  one_thread.execute([&] {
    single = trace_cavity(CavityShape::CylinderPit, dims, Illumination::diffuse(), small(9000));
  });
  EXPECT_EQ(many.escaped_after, single.escaped_after);
  MonteCarloSettings other = small(9000);
  other.seed = 12;
  EXPECT_NE(
      trace_cavity(CavityShape::CylinderPit, dims, Illumination::diffuse(), other).escaped_after,
      many.escaped_after);
}

TEST(MonteCarlo, WhiteWallsReturnAllLight) {
  // With rho0 = 1 nothing is absorbed: every path leaves, after at least one reflection.
  for (CavityShape shape : kAllShapes) {
    const EscapeHistogram h =
        trace_cavity(shape, {1.5, 1.0}, Illumination::directional(0.3), small(4000));
    EXPECT_EQ(h.unfinished, 0u) << shape_name(shape);
    EXPECT_EQ(h.escaped_after[0], 0u);
    EXPECT_DOUBLE_EQ(h.apparent_reflectance(1.0), 1.0);
    EXPECT_DOUBLE_EQ(h.apparent_reflectance(0.0), 0.0);
  }
}

TEST(MonteCarlo, GouffeIsExactForTheSphere) {
  // In a sphere every wall point sees the opening with the same F = G, so the uniform-
  // spreading assumption holds exactly and the closed form must match to noise.
  for (double depth : {0.5, 2.0}) {
    const CavityDims dims{depth, 1.0};
    const ViewFactors vf = view_factors(CavityShape::SpherePit, dims);
    for (const Illumination& light : {Illumination::diffuse(), Illumination::directional(0.7)}) {
      const EscapeHistogram h = trace_cavity(CavityShape::SpherePit, dims, light, small(20000));
      for (double rho0 : {0.2, 0.5, 0.8, 0.95}) {
        EXPECT_NEAR(h.apparent_reflectance(rho0), apparent_reflectance(rho0, vf),
                    4.5 * h.standard_error(rho0) + 1e-4)
            << "L/R " << depth << " rho0 " << rho0;
      }
    }
  }
}

// Largest |Gouffé - reference| measured by `impasto bench cracks` (200000 paths) for
// L/R <= 2 under a normal beam, plus 0.01 for this test's smaller Monte Carlo run.
struct Tolerance {
  CavityShape shape;
  double gouffe;        // F of the deepest element
  double gouffe_first;  // F averaged over the first reflections
};
constexpr Tolerance kMeasured[] = {
    {CavityShape::ArcGroove, 0.014, 0.006}, {CavityShape::VGroove, 0.017, 0.017},
    {CavityShape::BoxGroove, 0.043, 0.016}, {CavityShape::SpherePit, 0.001, 0.001},
    {CavityShape::ConePit, 0.077, 0.021},   {CavityShape::CylinderPit, 0.075, 0.033}};

TEST(MonteCarlo, GouffeWithinTheMeasuredToleranceForModerateDepths) {
  for (const Tolerance& tol : kMeasured) {
    for (double depth : {0.5, 2.0}) {
      const CavityDims dims{depth, 1.0};
      const ViewFactors vf = view_factors(tol.shape, dims);
      ViewFactors vf_first = vf;
      vf_first.F = first_reflection_view_factor(tol.shape, dims, 0.0);
      const EscapeHistogram h =
          trace_cavity(tol.shape, dims, Illumination::directional(0.0), small(20000));
      for (double rho0 : {0.05, 0.35, 0.65, 0.95}) {
        const double reference = h.apparent_reflectance(rho0);
        EXPECT_NEAR(apparent_reflectance(rho0, vf), reference, tol.gouffe + 0.01)
            << shape_name(tol.shape) << " L/R " << depth << " rho0 " << rho0;
        EXPECT_NEAR(apparent_reflectance(rho0, vf_first), reference, tol.gouffe_first + 0.01)
            << shape_name(tol.shape) << " L/R " << depth << " rho0 " << rho0;
      }
    }
  }
}

TEST(MonteCarlo, ClosedFormBeatsTheFirstOrderTerm) {
  for (CavityShape shape : kAllShapes) {
    const CavityDims dims{1.0, 1.0};
    const ViewFactors vf = view_factors(shape, dims);
    const EscapeHistogram h =
        trace_cavity(shape, dims, Illumination::directional(0.0), small(20000));
    const double rho0 = 0.8;
    const double reference = h.apparent_reflectance(rho0);
    EXPECT_LT(std::abs(apparent_reflectance(rho0, vf) - reference),
              std::abs(apparent_reflectance_first_order(rho0, vf) - reference))
        << shape_name(shape);
  }
}

TEST(MonteCarlo, BadSettingsAreRejected) {
  MonteCarloSettings s = small(10);
  s.max_bounces = 0;
  EXPECT_THROW(trace_cavity(CavityShape::VGroove, {1, 1}, Illumination::diffuse(), s),
               std::runtime_error);
  EXPECT_THROW(
      trace_cavity(CavityShape::VGroove, {1, 1}, Illumination::directional(2.0), small(10)),
      std::runtime_error);
  EXPECT_THROW(trace_cavity(CavityShape::VGroove, {0, 1}, Illumination::diffuse(), small(10)),
               std::runtime_error);
}

}  // namespace
}  // namespace impasto::cracks
