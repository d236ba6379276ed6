// Spectral sampling for a light: the rule integrates smooth reflectances like the full sum.
#include "impasto/render/spectral_sampling.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

#include "impasto/data/cie.hpp"
#include "impasto/data/lights.hpp"

using impasto::data::Spectrum;
using impasto::render::make_spectral_sampling;
using impasto::render::reflectance_to_xyz;
using impasto::render::SpectralSampling;

namespace {

std::vector<float> reflectance_at(const SpectralSampling& s, double (*r)(double)) {
  std::vector<float> values;
  for (float nm : s.wavelengths_nm) values.push_back(static_cast<float>(r(nm)));
  return values;
}

double cubic_reflectance(double nm) {
  const double t = (nm - 555.0) / 195.0;
  return 0.5 + 0.2 * t - 0.15 * t * t + 0.1 * t * t * t;
}

}  // namespace

TEST(SpectralSampling, WhiteHasUnitLuminanceAndMatchesTheFullSum) {
  const auto& cmf = impasto::data::cie1931_2deg();
  for (const char* light : {"D65", "A", "F11"}) {
    const Spectrum e = impasto::data::light_from_spec(light);
    const SpectralSampling full = make_spectral_sampling(e, cmf, 0);
    for (int n : {1, 3, 8, 16}) {
      const SpectralSampling rule = make_spectral_sampling(e, cmf, n);
      ASSERT_EQ(rule.size(), n);
      EXPECT_NEAR(rule.white_xyz[1], 1.0, 1e-6) << light << " N=" << n;
      // Chromaticity of the white: the rule's own white is close to the true one.
      const double x_rule = rule.white_xyz[0] / (rule.white_xyz[0] + 1.0 + rule.white_xyz[2]);
      const double x_full = full.white_xyz[0] / (full.white_xyz[0] + 1.0 + full.white_xyz[2]);
      if (n >= 8) {
        EXPECT_NEAR(x_rule, x_full, 2e-3) << light << " N=" << n;
      }
    }
  }
}

TEST(SpectralSampling, D65WhiteMatchesTheStandardWhitePoint) {
  const SpectralSampling full = make_spectral_sampling(impasto::data::cie_illuminant("D65"),
                                                       impasto::data::cie1931_2deg(), 0);
  EXPECT_NEAR(full.white_xyz[0], 0.95047, 1.5e-3);
  EXPECT_NEAR(full.white_xyz[2], 1.08883, 1.5e-3);
}

TEST(SpectralSampling, SmoothReflectanceConvergesWithNodes) {
  const auto& cmf = impasto::data::cie1931_2deg();
  const Spectrum d65 = impasto::data::cie_illuminant("D65");
  const SpectralSampling full = make_spectral_sampling(d65, cmf, 0);
  const auto full_values = reflectance_at(full, cubic_reflectance);
  const auto reference = reflectance_to_xyz(full, full_values.data());
  double previous_error = 1.0;
  for (int n : {2, 4, 8, 16}) {
    const SpectralSampling rule = make_spectral_sampling(d65, cmf, n);
    const auto values = reflectance_at(rule, cubic_reflectance);
    const auto xyz = reflectance_to_xyz(rule, values.data());
    const double error = std::abs(xyz[1] - reference[1]) / reference[1];
    EXPECT_LT(error, 0.05) << "N=" << n;
    if (n >= 8) {
      EXPECT_LT(error, 5e-3) << "N=" << n;
    }
    EXPECT_LE(error, previous_error * 1.5) << "N=" << n;
    previous_error = error;
  }
}

TEST(SpectralSampling, NodesFollowTheLight) {
  // A bluish light (high colour temperature) pulls the nodes toward short wavelengths.
  const auto& cmf = impasto::data::cie1931_2deg();
  const auto warm =
      make_spectral_sampling(impasto::data::light_from_spec("blackbody:2500"), cmf, 8);
  const auto cool =
      make_spectral_sampling(impasto::data::light_from_spec("blackbody:12000"), cmf, 8);
  double warm_mean = 0.0, cool_mean = 0.0;
  for (int i = 0; i < 8; ++i) {
    warm_mean += warm.wavelengths_nm[static_cast<std::size_t>(i)];
    cool_mean += cool.wavelengths_nm[static_cast<std::size_t>(i)];
  }
  EXPECT_LT(cool_mean, warm_mean);
}

TEST(SpectralSampling, RejectsBadRequests) {
  const auto& cmf = impasto::data::cie1931_2deg();
  const Spectrum d65 = impasto::data::cie_illuminant("D65");
  EXPECT_THROW(make_spectral_sampling(d65, cmf, 17), std::runtime_error);
  EXPECT_THROW(make_spectral_sampling(d65, cmf, -1), std::runtime_error);
  Spectrum black{"black", {300.0, 900.0}, {0.0, 0.0}};
  EXPECT_THROW(make_spectral_sampling(black, cmf, 8), std::runtime_error);
  Spectrum broken{"broken", {300.0, 900.0}, {1.0, NAN}};
  EXPECT_THROW(make_spectral_sampling(broken, cmf, 8), std::runtime_error);
}

TEST(SpectralSampling, ParsesNodeWeightNames) {
  using impasto::render::NodeWeights;
  EXPECT_EQ(impasto::render::parse_node_weights("impasto"), NodeWeights::impasto);
  EXPECT_EQ(impasto::render::parse_node_weights("interpolatory"), NodeWeights::interpolatory);
  EXPECT_EQ(impasto::render::parse_node_weights("fitted"), NodeWeights::fitted);
  EXPECT_THROW(impasto::render::parse_node_weights("chebyshev"), std::runtime_error);
}

TEST(SpectralSampling, InterpolatoryWeightsAreExactForLowDegreeReflectance) {
  // A cubic reflectance is interpolated exactly by 4 or more nodes, so its XYZ is exact.
  const auto& cmf = impasto::data::cie1931_2deg();
  const Spectrum a = impasto::data::cie_illuminant("A");
  const SpectralSampling full = make_spectral_sampling(a, cmf, 0);
  const auto full_values = reflectance_at(full, cubic_reflectance);
  const auto reference = reflectance_to_xyz(full, full_values.data());
  for (int n : {4, 8}) {
    const SpectralSampling rule = make_spectral_sampling(a, cmf, n);
    const auto values = reflectance_at(rule, cubic_reflectance);
    const auto xyz = reflectance_to_xyz(rule, values.data());
    for (std::size_t c = 0; c < 3; ++c) EXPECT_NEAR(xyz[c], reference[c], 1e-5) << "N=" << n;
  }
}

// A light of fewer visible lines than nodes (three 1 nm lines): its own wavelengths are the
// exact rule, the other nodes weightless, for every kind of weights (the default render once
// failed with "gauss_rule: 8 nodes requested but the measure has 3 points of positive mass").
TEST(SpectralSampling, ALightOfFewLinesUsesItsOwnWavelengths) {
  const auto& cmf = impasto::data::cie1931_2deg();
  Spectrum lines{"three lines", {}, {}};
  for (int nm = 360; nm <= 830; ++nm) {
    lines.wavelengths_nm.push_back(nm);
    lines.values.push_back(nm == 450 || nm == 545 || nm == 610 ? 1.0 : 0.0);
  }
  const SpectralSampling full = make_spectral_sampling(lines, cmf, 0);
  const std::vector<float> full_r = reflectance_at(full, cubic_reflectance);
  const auto expected = reflectance_to_xyz(full, full_r.data());
  for (auto weights :
       {impasto::render::NodeWeights::interpolatory, impasto::render::NodeWeights::impasto}) {
    for (int n : {3, 8, 16}) {
      const SpectralSampling rule = make_spectral_sampling(lines, cmf, n, {}, weights);
      ASSERT_EQ(rule.size(), n);
      int lit = 0;
      for (std::size_t i = 0; i < rule.wavelengths_nm.size(); ++i) {
        const bool on_a_line = rule.wavelengths_nm[i] == 450.0f ||
                               rule.wavelengths_nm[i] == 545.0f || rule.wavelengths_nm[i] == 610.0f;
        lit += on_a_line ? 1 : 0;
        if (!on_a_line) {
          EXPECT_EQ(rule.to_xyz[i][1], 0.0f) << rule.wavelengths_nm[i];
        }
        if (i > 0) {
          EXPECT_LT(rule.wavelengths_nm[i - 1], rule.wavelengths_nm[i]);
        }
      }
      EXPECT_EQ(lit, 3) << "N=" << n;
      const std::vector<float> r = reflectance_at(rule, cubic_reflectance);
      const auto xyz = reflectance_to_xyz(rule, r.data());
      for (int c = 0; c < 3; ++c) EXPECT_NEAR(xyz[c], expected[c], 1e-6) << "N=" << n;
    }
  }
  EXPECT_EQ(make_spectral_sampling(lines, cmf, 2).size(), 2);  // fewer nodes than lines: Gauss
}
