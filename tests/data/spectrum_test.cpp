#include "impasto/data/spectrum.hpp"

#include <gtest/gtest.h>

#include <stdexcept>

namespace impasto::data {
namespace {

Spectrum line(double slope, double offset, const std::vector<double>& grid) {
  Spectrum s{"line", grid, {}};
  for (double nm : grid) s.values.push_back(slope * nm + offset);
  return s;
}

TEST(Spectrum, InterpolatesLinearlyBetweenSamples) {
  const Spectrum s{"s", {400, 410, 430}, {1.0, 3.0, 2.0}};
  EXPECT_DOUBLE_EQ(s.at(400), 1.0);
  EXPECT_DOUBLE_EQ(s.at(405), 2.0);
  EXPECT_DOUBLE_EQ(s.at(410), 3.0);
  EXPECT_DOUBLE_EQ(s.at(425), 2.25);
  EXPECT_DOUBLE_EQ(s.at(430), 2.0);
}

TEST(Spectrum, IsZeroOutsideItsRange) {
  const Spectrum s{"s", {400, 500}, {1.0, 1.0}};
  EXPECT_EQ(s.at(399.999), 0.0);
  EXPECT_EQ(s.at(500.001), 0.0);
  EXPECT_EQ(Spectrum{}.at(450), 0.0);
}

TEST(Spectrum, ResamplingLinearDataIsExact) {
  const Spectrum coarse = line(0.25, -3.0, wavelength_grid(360, 830, 10));
  const Spectrum fine = coarse.resampled(wavelength_grid(361.5, 828.5, 0.7));
  ASSERT_FALSE(fine.values.empty());
  for (std::size_t i = 0; i < fine.values.size(); ++i) {
    EXPECT_NEAR(fine.values[i], 0.25 * fine.wavelengths_nm[i] - 3.0, 1e-12);
  }
  EXPECT_EQ(fine.name, "line");
}

TEST(WavelengthGrid, IncludesLastWhenOnAStep) {
  const auto grid = wavelength_grid(360, 830, 5);
  ASSERT_EQ(grid.size(), 95u);
  EXPECT_EQ(grid.front(), 360.0);
  EXPECT_EQ(grid.back(), 830.0);
  EXPECT_EQ(wavelength_grid(400, 409, 5).size(), 2u);
  EXPECT_EQ(wavelength_grid(400, 400, 5).size(), 1u);
  EXPECT_EQ(wavelength_grid(380, 780, 0.1).back(), 380 + 4000 * 0.1);
}

TEST(WavelengthGrid, RejectsBadArguments) {
  EXPECT_THROW(wavelength_grid(400, 300, 5), std::runtime_error);
  EXPECT_THROW(wavelength_grid(400, 700, 0), std::runtime_error);
  EXPECT_THROW(wavelength_grid(400, 700, -1), std::runtime_error);
  EXPECT_THROW(wavelength_grid(400, 1e300, 1), std::runtime_error);
}

}  // namespace
}  // namespace impasto::data
