#include "impasto/data/cie.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <stdexcept>

#include "impasto/data/colorimetry.hpp"

namespace impasto::data {
namespace {

double trapezoid(const Spectrum& s) {
  double sum = 0;
  for (std::size_t i = 1; i < s.values.size(); ++i) {
    sum += 0.5 * (s.values[i] + s.values[i - 1]) * (s.wavelengths_nm[i] - s.wavelengths_nm[i - 1]);
  }
  return sum;
}

TEST(Cie1931, ColourMatchingFunctionsCoverTheVisibleRange) {
  const auto& cmf = cie1931_2deg();
  ASSERT_EQ(cmf.y.wavelengths_nm.size(), 95u);
  EXPECT_EQ(cmf.y.wavelengths_nm.front(), 360.0);
  EXPECT_EQ(cmf.y.wavelengths_nm.back(), 830.0);
  EXPECT_EQ(cmf.x.wavelengths_nm, cmf.y.wavelengths_nm);
  EXPECT_EQ(cmf.z.wavelengths_nm, cmf.y.wavelengths_nm);
  EXPECT_EQ(&cie1931_2deg(), &cmf) << "loaded once";
}

TEST(Cie1931, LuminosityPeaksAt555nmWithValueOne) {
  const Spectrum& y = cie1931_2deg().y;
  const auto peak = std::max_element(y.values.begin(), y.values.end());
  EXPECT_EQ(y.wavelengths_nm[static_cast<std::size_t>(peak - y.values.begin())], 555.0);
  EXPECT_NEAR(*peak, 1.0, 1e-6);
}

TEST(Cie1931, EqualEnergyWhiteHasEqualIntegrals) {
  // The 1931 functions are normalised so that illuminant E has X = Y = Z.
  const auto& cmf = cie1931_2deg();
  const double y = trapezoid(cmf.y);
  EXPECT_NEAR(trapezoid(cmf.x) / y, 1.0, 1e-3);
  EXPECT_NEAR(trapezoid(cmf.z) / y, 1.0, 1e-3);
}

TEST(CieIlluminants, IncludesTheStandardOnes) {
  const auto names = illuminant_names();
  for (const char* name : {"A", "D50", "D65", "F2", "F7", "F11", "E"}) {
    EXPECT_NE(std::find(names.begin(), names.end(), name), names.end()) << name;
  }
  const auto f2 = std::find(names.begin(), names.end(), "F2");
  const auto f10 = std::find(names.begin(), names.end(), "F10");
  EXPECT_LT(f2, f10) << "natural order";
  EXPECT_EQ(names.front(), "A");
}

TEST(CieIlluminants, D65WhitePoint) {
  const auto xy = chromaticity(white_point(cie_illuminant("D65")));
  EXPECT_NEAR(xy.x, 0.3127, 2e-4);
  EXPECT_NEAR(xy.y, 0.3290, 2e-4);
}

TEST(CieIlluminants, AWhitePoint) {
  const auto xy = chromaticity(white_point(cie_illuminant("A")));
  EXPECT_NEAR(xy.x, 0.4476, 2e-4);
  EXPECT_NEAR(xy.y, 0.4074, 2e-4);
}

TEST(CieIlluminants, D50AndF11WhitePoints) {
  const auto d50 = chromaticity(white_point(cie_illuminant("D50")));
  EXPECT_NEAR(d50.x, 0.3457, 3e-4);
  EXPECT_NEAR(d50.y, 0.3585, 3e-4);
  const auto f11 = chromaticity(white_point(cie_illuminant("F11")));
  EXPECT_NEAR(f11.x, 0.3805, 1e-3);
  EXPECT_NEAR(f11.y, 0.3769, 1e-3);
}

TEST(CieIlluminants, NamesAreCaseInsensitiveAndUnknownOnesListTheKnown) {
  const Spectrum d65 = cie_illuminant("d65");
  EXPECT_EQ(d65.name, "D65");
  EXPECT_DOUBLE_EQ(d65.at(560), 1.0);
  try {
    cie_illuminant("D66");
    FAIL() << "D66 accepted";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("D65"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("D66"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace impasto::data
