#include "impasto/data/lights.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <stdexcept>

#include "impasto/data/colorimetry.hpp"

namespace impasto::data {
namespace {

TEST(Blackbody, IsOneAt560nm) {
  for (double kelvin : {1000.0, 2856.0, 6504.0, 20000.0}) {
    EXPECT_NEAR(blackbody(kelvin, {560.0}).values[0], 1.0, 1e-12) << kelvin;
  }
}

TEST(Blackbody, PeaksWhereWiensLawSays) {
  constexpr double kWien_nmK = 2.897771955e6;  // Wien's displacement constant b
  const auto grid = wavelength_grid(200, 1500, 0.01);
  for (double kelvin : {3000.0, 5000.0, 8000.0}) {
    const Spectrum spd = blackbody(kelvin, grid);
    const auto peak = std::max_element(spd.values.begin(), spd.values.end());
    const double peak_nm = grid[static_cast<std::size_t>(peak - spd.values.begin())];
    EXPECT_NEAR(peak_nm, kWien_nmK / kelvin, 0.011) << kelvin;
  }
}

TEST(Blackbody, FollowsWiensApproximationWhenHcOverLambdaKTIsLarge) {
  // For c2/(λT) >> 1, Planck → λ^-5 exp(−c2/(λT)); here the relative error is < 1e-12.
  constexpr double c2 = 1.438776877e7;  // nm·K
  const double kelvin = 500.0;
  const Spectrum spd = blackbody(kelvin, {400.0});
  const double wien =
      std::pow(560.0 / 400.0, 5) * std::exp(c2 / (560 * kelvin) - c2 / (400 * kelvin));
  EXPECT_NEAR(spd.values[0] / wien, 1.0, 1e-12);
}

TEST(Blackbody, Near6504KMatchesD65Chromaticity) {
  const auto bb = chromaticity(white_point(blackbody(6504, wavelength_grid(300, 830, 1))));
  const auto d65 = chromaticity(white_point(cie_illuminant("D65")));
  EXPECT_LT(std::hypot(bb.x - d65.x, bb.y - d65.y), 0.01);
}

TEST(Blackbody, ExtremeTemperaturesStayFiniteAndBadOnesThrow) {
  for (double kelvin : {100.0, 1e6, 1e9}) {
    for (double v : blackbody(kelvin, wavelength_grid(360, 830, 10)).values) {
      EXPECT_TRUE(std::isfinite(v) && v >= 0.0) << kelvin;
    }
  }
  EXPECT_THROW(blackbody(0, {500}), std::runtime_error);
  EXPECT_THROW(blackbody(99, {500}), std::runtime_error);
  EXPECT_THROW(blackbody(-5, {500}), std::runtime_error);
  EXPECT_THROW(blackbody(NAN, {500}), std::runtime_error);
  EXPECT_THROW(blackbody(5000, {-1}), std::runtime_error);
}

TEST(LightFromSpec, NamesBlackbodiesAndFiles) {
  EXPECT_EQ(light_from_spec("D65").values, cie_illuminant("D65").values);
  EXPECT_EQ(light_from_spec("a").name, "A");
  const Spectrum bb = light_from_spec("blackbody:5600");
  EXPECT_EQ(bb.values, blackbody(5600, wavelength_grid(300, 830, 1)).values);

  const auto path = std::filesystem::path(testing::TempDir()) / "impasto_light_test.csv";
  std::ofstream(path) << "# quantity: spectral_power\nwavelength_nm,lamp\n400,1\n700,3\n";
  const Spectrum lamp = light_from_spec(path.string());
  EXPECT_EQ(lamp.name, "lamp");
  EXPECT_DOUBLE_EQ(lamp.at(550), 2.0);
  std::ofstream(path) << "# quantity: reflectance\nwavelength_nm,r\n400,1\n700,1\n";
  EXPECT_THROW(light_from_spec(path.string()), std::runtime_error);
  std::ofstream(path) << "wavelength_nm,a,b\n400,1,1\n";
  EXPECT_THROW(light_from_spec(path.string()), std::runtime_error);
  std::filesystem::remove(path);
}

TEST(LightFromSpec, AMissingCsvIsNamedInTheError) {
  try {
    light_from_spec("no_such_lamp.csv");
    FAIL() << "a missing file was accepted";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("no_such_lamp.csv"), std::string::npos) << e.what();
  }
}

TEST(LightFromSpec, RejectsUnknownSpecsWithTheChoices) {
  for (const char* spec :
       {"blackbody:", "blackbody:-3", "blackbody:50", "blackbody:5k", "sunlight"}) {
    try {
      light_from_spec(spec);
      ADD_FAILURE() << spec << " accepted";
    } catch (const std::runtime_error& e) {
      EXPECT_NE(std::string(e.what()).find("blackbody:KELVIN"), std::string::npos) << e.what();
    }
  }
}

}  // namespace
}  // namespace impasto::data
