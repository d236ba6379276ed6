// XYZ to the display through OpenColorIO, and Bradford adaptation.
#include "impasto/render/display.hpp"

#include <gtest/gtest.h>

#include <stdexcept>

#include "impasto/render/chromatic_adaptation.hpp"

using namespace impasto::render;

TEST(DisplayTransform, D65WhiteIsDisplayWhiteForEveryEncoding) {
  for (const auto& name : display_encoding_names()) {
    const DisplayTransform display(parse_display_encoding(name));
    float rgb[3] = {static_cast<float>(kD65WhiteXyz[0]), static_cast<float>(kD65WhiteXyz[1]),
                    static_cast<float>(kD65WhiteXyz[2])};
    display.apply(rgb, 1);
    for (float v : rgb) EXPECT_NEAR(v, 1.0f, 1e-3f) << name;
  }
}

TEST(DisplayTransform, SrgbMatchesTheStandardForPrimariesAndMidGrey) {
  const DisplayTransform display(DisplayEncoding::srgb);
  // 18% grey at D65: linear 0.18 encodes to 0.4614 by the sRGB curve.
  float grey[3] = {0.18f * 0.95047f, 0.18f, 0.18f * 1.08883f};
  display.apply(grey, 1);
  for (float v : grey) EXPECT_NEAR(v, 0.4614f, 1e-3f);
  // The sRGB red primary's XYZ (IEC 61966-2-1).
  float red[3] = {0.4124f, 0.2126f, 0.0193f};
  display.apply(red, 1);
  EXPECT_NEAR(red[0], 1.0f, 2e-3f);
  EXPECT_NEAR(red[1], 0.0f, 2e-3f);
  EXPECT_NEAR(red[2], 0.0f, 2e-3f);
}

TEST(DisplayTransform, LinearKeepsFullRange) {
  const DisplayTransform display(DisplayEncoding::linear_srgb);
  float bright[3] = {4.0f * 0.95047f, 4.0f, 4.0f * 1.08883f};
  display.apply(bright, 1);
  for (float v : bright) EXPECT_NEAR(v, 4.0f, 4e-3f);
}

TEST(DisplayTransform, RejectsUnknownNames) {
  EXPECT_THROW(parse_display_encoding("adobe-rgb"), std::runtime_error);
}

TEST(ChromaticAdaptation, BradfordMapsSourceWhiteToTargetWhite) {
  const Xyz illuminant_a{1.09850, 1.0, 0.35585};
  const Matrix3 m = bradford_matrix(illuminant_a, kD65WhiteXyz);
  const Xyz adapted = apply(m, illuminant_a);
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(adapted[c], kD65WhiteXyz[c], 1e-12);
  // Lindbloom's tabulated Bradford A → D65 matrix, first row.
  EXPECT_NEAR(m[0][0], 0.8446965, 2e-4);
  EXPECT_NEAR(m[0][1], -0.1179225, 2e-4);
  EXPECT_NEAR(m[0][2], 0.3948108, 2e-4);
}

TEST(ChromaticAdaptation, SameWhiteIsIdentity) {
  const Matrix3 m = bradford_matrix(kD65WhiteXyz, kD65WhiteXyz);
  for (int r = 0; r < 3; ++r) {
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(m[r][c], r == c ? 1.0 : 0.0, 1e-12);
  }
  EXPECT_THROW(bradford_matrix({0.0, 0.0, 0.0}, kD65WhiteXyz), std::runtime_error);
  EXPECT_THROW(parse_chromatic_adaptation("cat02"), std::runtime_error);
}
