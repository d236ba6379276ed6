// The measured correction of Gouffé's closed form (cavity_table.hpp): it agrees with fresh
// Monte Carlo runs off the table's grid, keeps the limits L -> 0 and L -> inf, darkens
// monotonically with depth, and its file reader rejects bad input by file and line.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>

#include "impasto/cracks/cavity_table.hpp"
#include "impasto/cracks/monte_carlo.hpp"

namespace impasto::cracks {
namespace {

double corrected(CavityShape shape, double ratio, double rho0) {
  const CavityDims dims{ratio, 1.0};
  return cavity_reflectance(CavityModel::Corrected, shape, dims, view_factors(shape, dims), rho0);
}

TEST(CavityTable, ShippedTableCoversEveryShape) {
  const CavityTable& table = shipped_cavity_table();
  EXPECT_EQ(table.values().size(), kAllShapes.size() * 13u * 41u);
  for (CavityShape shape : kAllShapes) {
    for (int j = 0; j < table.grid().rho0_count; ++j) {
      // The shallowest row (L/R = 0.05) is nearly the closed form, for every shape (its
      // largest error there is the cylinder pit's, 0.015).
      const double rho0 = table.rho0(j);
      EXPECT_NEAR(table.reflectance_at(shape, 0, j),
                  apparent_reflectance(rho0, view_factors(shape, {table.ratio(0), 1.0})), 0.02)
          << shape_name(shape);
    }
  }
}

// Fresh runs (another seed) at L/R and rho0 between the grid's nodes. Tolerance: the
// model's error against an independent 200,000-path reference (at most 0.0083 over every
// shape, L/R and rho0 of `impasto bench cracks --seed 2`, normal light) rounded up to 0.01,
// plus 4.5 standard errors of this 20,000-path check.
TEST(CavityTable, CorrectedAgreesWithFreshMonteCarloOffTheGrid) {
  const MonteCarloSettings settings{20000, 4242, 600};
  for (CavityShape shape : kAllShapes) {
    for (double ratio : {0.3, 3.3, 15.0}) {
      const CavityDims dims{ratio, 1.0};
      const EscapeHistogram h = trace_cavity(shape, dims, Illumination::directional(0.0), settings);
      for (double rho0 : {0.33, 0.62, 0.9}) {
        const double reference = h.apparent_reflectance(rho0);
        const double tol = 0.01 + 4.5 * h.standard_error(rho0);
        EXPECT_NEAR(corrected(shape, ratio, rho0), reference, tol)
            << shape_name(shape) << " L/R " << ratio << " rho0 " << rho0;
      }
    }
  }
}

// Where Gouffé is worst (deep, bright walls) the correction removes most of the error.
TEST(CavityTable, CorrectionFixesDeepCavities) {
  const MonteCarloSettings settings{20000, 77, 600};
  for (CavityShape shape : {CavityShape::VGroove, CavityShape::CylinderPit}) {
    const CavityDims dims{12.0, 1.0};
    const ViewFactors vf = view_factors(shape, dims);
    const double reference = trace_cavity(shape, dims, Illumination::directional(0.0), settings)
                                 .apparent_reflectance(0.95);
    const double gouffe_error = std::abs(apparent_reflectance(0.95, vf) - reference);
    EXPECT_GT(gouffe_error, 0.1) << shape_name(shape);
    EXPECT_LT(std::abs(corrected(shape, 12.0, 0.95) - reference), 0.2 * gouffe_error)
        << shape_name(shape);
  }
}

TEST(CavityTable, LimitsHold) {
  for (CavityShape shape : kAllShapes) {
    for (double rho0 : {0.0, 0.3, 0.7, 0.95}) {
      EXPECT_NEAR(corrected(shape, 1e-9, rho0), rho0, 1e-6) << shape_name(shape);  // L -> 0
      EXPECT_DOUBLE_EQ(corrected(shape, 0.0, rho0), rho0);
      EXPECT_LT(corrected(shape, 1e7, rho0), 1e-3) << shape_name(shape);  // L -> inf: eps -> 1
      EXPECT_GE(corrected(shape, 1e7, rho0), 0.0);
    }
  }
}

// The table is non-increasing in depth at its nodes; between them the closed form plus the
// linearly interpolated difference can rise by a few 1e-4 where the cavity is nearly black
// (the cylinder pit beyond L/R = 25, rho < 0.001): far below 1/255.
TEST(CavityTable, DeeperIsDarker) {
  for (CavityShape shape : kAllShapes) {
    for (double rho0 : {0.1, 0.4, 0.7, 0.9, 0.97}) {
      double previous = rho0;
      for (int i = 0; i <= 400; ++i) {
        const double ratio = std::pow(10.0, -3.0 + 6.0 * i / 400.0);  // 0.001 .. 1000
        const double rho = corrected(shape, ratio, rho0);
        EXPECT_LE(rho, previous + (shape == CavityShape::CylinderPit ? 5e-4 : 1e-9))
            << shape_name(shape) << " rho0 " << rho0 << " L/R " << ratio;
        previous = rho;
      }
    }
  }
}

TEST(CavityTable, WriteThenReadGivesTheSameTable) {
  const CavityTableGrid grid{0.5, 1, 2, 3};
  const CavityTable measured = CavityTable::measure(grid, 500, 3);
  const auto path = std::filesystem::temp_directory_path() / "impasto_cavity_table_test.csv";
  {
    std::ofstream out(path);
    measured.write_csv(out);
  }
  const CavityTable read = CavityTable::read_csv(path);
  ASSERT_EQ(read.values().size(), measured.values().size());
  for (std::size_t i = 0; i < read.values().size(); ++i) {
    EXPECT_NEAR(read.values()[i], measured.values()[i], 1e-6);
  }
  std::filesystem::remove(path);
}

TEST(CavityTable, BadFilesNameFileAndLine) {
  const auto path = std::filesystem::temp_directory_path() / "impasto_cavity_table_bad.csv";
  const auto expect_error = [&](const std::string& text, const std::string& what) {
    {
      std::ofstream out(path);
      out << text;
    }
    try {
      CavityTable::read_csv(path);
      ADD_FAILURE() << "no error for: " << text;
    } catch (const std::runtime_error& e) {
      EXPECT_NE(std::string(e.what()).find(path.string() + what), std::string::npos) << e.what();
    }
  };
  const std::string head =
      "# grid: ratio_min 0.5 ratios_per_decade 1 ratio_count 2 rho0_count 2\n"
      "shape,L_over_R,rho0,rho\n";
  expect_error(head + "arc-groove,0.5,0,nan\n", ":3");
  expect_error(head + "v-groove,0.5,0,1\n", ":3");
  expect_error(head + "arc-groove,0.7,0,1\n", ":3");
  expect_error(head + "arc-groove,0.5,0\n", ":3");
  expect_error("# grid: ratio_min -1 ratios_per_decade 1 ratio_count 2 rho0_count 2\n", ":1");
  expect_error(head + "arc-groove,0.5,0,1\n", ": cavity table incomplete");
  std::filesystem::remove(path);
  EXPECT_THROW(CavityTable::read_csv(path), std::runtime_error);
}

}  // namespace
}  // namespace impasto::cracks
