#include "impasto/data/colorimetry.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace impasto::data {
namespace {

Spectrum flat(double value) {
  return {"flat", {300, 900}, {value, value}};
}

TEST(Colorimetry, PerfectWhiteHasY100AndGreyScalesLinearly) {
  const Spectrum d65 = cie_illuminant("D65");
  const Xyz white = white_point(d65);
  EXPECT_NEAR(white.Y, 100.0, 1e-9);
  const Xyz grey = reflectance_to_xyz(flat(0.5), d65);
  EXPECT_NEAR(grey.X, 0.5 * white.X, 1e-9);
  EXPECT_NEAR(grey.Y, 50.0, 1e-9);
  EXPECT_NEAR(grey.Z, 0.5 * white.Z, 1e-9);
  const Xyz black = reflectance_to_xyz(flat(0.0), d65);
  EXPECT_EQ(black.Y, 0.0);
}

TEST(Colorimetry, LabOfGreysIsNeutralWithKnownLightness) {
  const Xyz white{95.047, 100.0, 108.883};
  const Lab w = xyz_to_lab(white, white);
  EXPECT_NEAR(w.L, 100.0, 1e-12);
  EXPECT_NEAR(w.a, 0.0, 1e-12);
  EXPECT_NEAR(w.b, 0.0, 1e-12);
  // Y = 50: L* = 116·0.5^(1/3) − 16.
  const Lab grey = xyz_to_lab({0.5 * white.X, 50.0, 0.5 * white.Z}, white);
  EXPECT_NEAR(grey.L, 116.0 * std::cbrt(0.5) - 16.0, 1e-12);
  EXPECT_NEAR(grey.a, 0.0, 1e-12);
  // The linear segment below (6/29)^3: L* = (29/3)^3 · Y/Yn.
  const Lab dark = xyz_to_lab({0.001 * white.X, 0.1, 0.001 * white.Z}, white);
  EXPECT_NEAR(dark.L, std::pow(29.0 / 3.0, 3) * 0.001, 1e-9);
}

TEST(Colorimetry, ChromaticityOfEqualEnergyIsOneThird) {
  const auto xy = chromaticity(white_point(cie_illuminant("E")));
  EXPECT_NEAR(xy.x, 1.0 / 3.0, 2e-4);
  EXPECT_NEAR(xy.y, 1.0 / 3.0, 2e-4);
  EXPECT_EQ(chromaticity({}).x, 0.0);
}

// Test pairs from Sharma, Wu, Dalal, "The CIEDE2000 color-difference formula", Color
// Research & Application 30(1), 2005, Table 1 (pair number in the comment).
struct Pair {
  Lab first, second;
  double delta_e;
};
const Pair kSharmaPairs[] = {
    {{50.0000, 2.6772, -79.7751}, {50.0000, 0.0000, -82.7485}, 2.0425},    // 1
    {{50.0000, 3.1571, -77.2803}, {50.0000, 0.0000, -82.7485}, 2.8615},    // 2
    {{50.0000, 2.8361, -74.0200}, {50.0000, 0.0000, -82.7485}, 3.4412},    // 3
    {{50.0000, -1.3802, -84.2814}, {50.0000, 0.0000, -82.7485}, 1.0000},   // 4
    {{50.0000, 0.0000, 0.0000}, {50.0000, -1.0000, 2.0000}, 2.3669},       // 7
    {{50.0000, 2.4900, -0.0010}, {50.0000, -2.4900, 0.0009}, 7.1792},      // 9
    {{50.0000, 2.4900, -0.0010}, {50.0000, -2.4900, 0.0011}, 7.2195},      // 11
    {{50.0000, -0.0010, 2.4900}, {50.0000, 0.0009, -2.4900}, 4.8045},      // 13
    {{50.0000, -0.0010, 2.4900}, {50.0000, 0.0011, -2.4900}, 4.7461},      // 15
    {{50.0000, 2.5000, 0.0000}, {50.0000, 0.0000, -2.5000}, 4.3065},       // 16
    {{50.0000, 2.5000, 0.0000}, {73.0000, 25.0000, -18.0000}, 27.1492},    // 17
    {{50.0000, 2.5000, 0.0000}, {61.0000, -5.0000, 29.0000}, 22.8977},     // 18
    {{50.0000, 2.5000, 0.0000}, {56.0000, -27.0000, -3.0000}, 31.9030},    // 19
    {{50.0000, 2.5000, 0.0000}, {58.0000, 24.0000, 15.0000}, 19.4535},     // 20
    {{50.0000, 2.5000, 0.0000}, {50.0000, 3.1736, 0.5854}, 1.0000},        // 21
    {{60.2574, -34.0099, 36.2677}, {60.4626, -34.1751, 39.4387}, 1.2644},  // 25
};

TEST(Ciede2000, MatchesSharmaTestPairs) {
  for (const Pair& p : kSharmaPairs) {
    EXPECT_NEAR(ciede2000(p.first, p.second), p.delta_e, 1e-4)
        << p.first.L << " " << p.first.a << " " << p.first.b;
    EXPECT_NEAR(ciede2000(p.second, p.first), p.delta_e, 1e-4) << "symmetric";
  }
}

TEST(Ciede2000, IsZeroForEqualColours) {
  EXPECT_EQ(ciede2000({40, 10, -20}, {40, 10, -20}), 0.0);
  EXPECT_EQ(ciede2000({0, 0, 0}, {0, 0, 0}), 0.0);
}

// Two neutral greys differ in lightness alone: CIEDE2000 is dL / S_L, with L* of Y = 100 R and
// S_L = 1 + 0.015 (Lm - 50)^2 / sqrt(20 + (Lm - 50)^2) (Sharma, Wu and Dalal 2005).
TEST(ReflectanceDeltaE, OfTwoGreysIsTheirLightnessDifferenceWeighted) {
  const Spectrum d65 = cie_illuminant("D65");
  const auto lightness = [](double y) { return 116.0 * std::cbrt(y) - 16.0; };
  const double l1 = lightness(0.5), l2 = lightness(0.25), mean = 0.5 * (l1 + l2);
  const double s_l =
      1.0 + 0.015 * (mean - 50) * (mean - 50) / std::sqrt(20.0 + (mean - 50) * (mean - 50));
  EXPECT_NEAR(reflectance_delta_e(flat(0.5), flat(0.25), d65), (l1 - l2) / s_l, 1e-6);
  EXPECT_EQ(reflectance_delta_e(flat(0.3), flat(0.3), d65), 0.0);
}

}  // namespace
}  // namespace impasto::data
