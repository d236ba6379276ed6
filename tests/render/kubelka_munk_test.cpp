// The per-cell Kubelka–Munk maths against closed forms and limits, at the extremes.
#include "impasto/render/kubelka_munk_cell.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

namespace km = impasto::render::km;

namespace {

// R and T straight from the corrected Eqs. 8–9 in double: the textbook form.
km::LayerRT textbook_layer(double K, double S, double d) {
  const double a = 1.0 + K / S;
  const double b = std::sqrt(a * a - 1.0);
  const double x = b * S * d;
  const double R = 1.0 / (a + b / std::tanh(x));
  const double T = b * R / std::sinh(x);
  return {static_cast<float>(R), static_cast<float>(T)};
}

void expect_physical(km::LayerRT rt, const char* what) {
  SCOPED_TRACE(what);
  EXPECT_TRUE(std::isfinite(rt.reflectance));
  EXPECT_TRUE(std::isfinite(rt.transmittance));
  EXPECT_GE(rt.reflectance, 0.0f);
  EXPECT_LE(rt.reflectance, 1.0f);
  EXPECT_GE(rt.transmittance, 0.0f);
  EXPECT_LE(rt.transmittance, 1.0f);
  // Energy: a few float roundings may push a lossless layer (K = 0) a hair over 1.
  EXPECT_LE(rt.reflectance + rt.transmittance, 1.0f + 4e-7f);
}

}  // namespace

TEST(KubelkaMunkLayer, MatchesTextbookFormulaInTheOrdinaryRange) {
  for (double K : {0.01, 0.3, 1.0, 4.0}) {
    for (double S : {0.05, 0.5, 1.0, 3.0}) {
      for (double d : {0.01, 0.1, 1.0, 5.0}) {
        const km::LayerRT expected = textbook_layer(K, S, d);
        const km::LayerRT got =
            km::layer(static_cast<float>(K), static_cast<float>(S), static_cast<float>(d));
        EXPECT_NEAR(got.reflectance, expected.reflectance, 2e-6f) << K << " " << S << " " << d;
        EXPECT_NEAR(got.transmittance, expected.transmittance, 2e-6f) << K << " " << S << " " << d;
      }
    }
  }
}

TEST(KubelkaMunkLayer, PureAbsorberIsBeerLambert) {
  for (float K : {0.0f, 1e-6f, 0.5f, 3.0f, 40.0f}) {
    for (float d : {0.0f, 1e-9f, 0.2f, 1.0f, 7.5f}) {
      const km::LayerRT rt = km::layer(K, 0.0f, d);
      EXPECT_EQ(rt.reflectance, 0.0f);
      EXPECT_NEAR(rt.transmittance, std::exp(-K * d), 1e-6f * std::exp(-K * d) + 1e-30f);
    }
  }
}

TEST(KubelkaMunkLayer, PureScattererMatchesClosedForm) {
  for (float S : {1e-6f, 0.1f, 1.0f, 10.0f}) {
    for (float d : {0.0f, 1e-9f, 0.05f, 1.0f, 100.0f, 1e6f}) {
      const km::LayerRT rt = km::layer(0.0f, S, d);
      const double Sd = static_cast<double>(S) * d;
      EXPECT_NEAR(rt.reflectance, Sd / (1.0 + Sd), 1e-6);
      EXPECT_NEAR(rt.transmittance, 1.0 / (1.0 + Sd), 1e-6);
    }
  }
}

TEST(KubelkaMunkLayer, ZeroThicknessIsInvisible) {
  for (float K : {0.0f, 1e-9f, 1.0f, 1e9f}) {
    for (float S : {0.0f, 1e-9f, 1.0f, 1e9f}) {
      const km::LayerRT rt = km::layer(K, S, 0.0f);
      EXPECT_EQ(rt.reflectance, 0.0f);
      EXPECT_EQ(rt.transmittance, 1.0f);
    }
  }
}

TEST(KubelkaMunkLayer, ThinLimitTendsToTransparent) {
  const km::LayerRT rt = km::layer(2.0f, 1.0f, 1e-9f);
  EXPECT_NEAR(rt.reflectance, 0.0f, 1e-8f);
  EXPECT_NEAR(rt.transmittance, 1.0f, 1e-7f);
}

TEST(KubelkaMunkLayer, ThickLimitIsHidingReflectance) {
  for (double ratio : {1e-4, 0.01, 0.5, 1.0, 10.0, 1e4}) {
    const double a = 1.0 + ratio;
    const double b = std::sqrt(a * a - 1.0);
    for (float d : {1e3f, 1e6f}) {
      const km::LayerRT rt = km::layer(static_cast<float>(ratio), 1.0f, d);
      EXPECT_NEAR(rt.reflectance, a - b, 2e-6 * (a - b) + 1e-7) << ratio;
      EXPECT_NEAR(rt.transmittance, 0.0f, 1e-7f);  // e^(−βd) with βd >= 14
      EXPECT_NEAR(km::reflectance_infinite(static_cast<float>(ratio), 1.0f), a - b,
                  2e-6 * (a - b) + 1e-7);
    }
  }
}

TEST(KubelkaMunkLayer, StaysPhysicalAcrossExtremes) {
  const std::vector<float> thicknesses{0.0f, 1e-9f, 1e-4f, 0.1f, 1.0f, 1e3f, 1e6f};
  const std::vector<float> scatterings{0.0f, 1e-9f, 1e-3f, 1.0f, 1e3f, 1e9f};
  for (float d : thicknesses) {
    for (float S : scatterings) {
      for (double ratio = 1e-9; ratio <= 1e9; ratio *= 10.0) {
        const auto K = static_cast<float>(ratio * S);
        expect_physical(km::layer(K, S, d), "K/S sweep");
      }
      expect_physical(km::layer(0.0f, S, d), "K = 0");
      expect_physical(km::layer(S, 0.0f, d), "S = 0");
    }
  }
  expect_physical(km::layer(0.0f, 0.0f, 1.0f), "empty");
  expect_physical(km::layer(3e38f, 1.0f, 1.0f), "huge K");
  expect_physical(km::layer(1.0f, 3e38f, 1.0f), "huge S");
}

TEST(KubelkaMunkComposite, OverBlackGroundIsTheLayerAlone) {
  const km::LayerRT rt = km::layer(0.4f, 1.3f, 0.7f);
  EXPECT_EQ(km::composite(rt, 0.0f), rt.reflectance);
}

TEST(KubelkaMunkComposite, ZeroThicknessLayerLeavesTheSubstrate) {
  for (float below : {0.0f, 0.2f, 0.97f, 1.0f}) {
    EXPECT_FLOAT_EQ(km::composite(km::layer(5.0f, 2.0f, 0.0f), below), below);
  }
}

TEST(KubelkaMunkComposite, OpaqueLayerHidesTheSubstrate) {
  const km::LayerRT rt = km::layer(0.2f, 1.0f, 1e6f);
  EXPECT_EQ(km::composite(rt, 1.0f), rt.reflectance);
  EXPECT_EQ(km::composite(rt, 0.0f), rt.reflectance);
}

TEST(KubelkaMunkComposite, LosslessLayerOverPerfectWhiteStaysWhite) {
  // T = 1 − R when K = 0, so the series sums to exactly 1; R·R_prev < 1 for finite d.
  for (float d : {0.01f, 1.0f, 50.0f}) {
    EXPECT_NEAR(km::composite(km::layer(0.0f, 1.0f, d), 1.0f), 1.0f, 1e-5f);
  }
  // R = R_prev = 1: the guarded denominator returns the layer's own reflectance.
  EXPECT_EQ(km::composite({1.0f, 0.0f}, 1.0f), 1.0f);
}

TEST(KubelkaMunkComposite, TwoHalvesEqualTheWholeLayer) {
  // Stacking two layers of thickness d/2 of one paint must give the layer of thickness d:
  // the K-M differential equations are linear in depth.
  const float K = 0.6f, S = 1.7f, below = 0.35f;
  const km::LayerRT half = km::layer(K, S, 0.4f);
  const float stacked = km::composite(half, km::composite(half, below));
  EXPECT_NEAR(stacked, km::composite(km::layer(K, S, 0.8f), below), 2e-6f);
}

TEST(KubelkaMunkMix, ConcentrationsWeightCoefficients) {
  float K = 0.0f, S = 0.0f;
  km::accumulate_pigment(0.25f, 4.0f, 1.0f, K, S);
  km::accumulate_pigment(0.75f, 0.0f, 2.0f, K, S);
  EXPECT_FLOAT_EQ(K, 1.0f);
  EXPECT_FLOAT_EQ(S, 1.75f);
}

TEST(KubelkaMunkSaunderson, FixesBlackAndWhiteEnds) {
  // The body alone: black stays black (the surface's k1 is the specular term's), a perfect
  // white loses only what the surface reflects, and no interface changes nothing.
  EXPECT_FLOAT_EQ(km::saunderson(0.0f, 0.03f, 0.65f), 0.0f);
  EXPECT_FLOAT_EQ(km::saunderson(1.0f, 0.03f, 0.65f), 0.97f);
  EXPECT_EQ(km::saunderson(0.4f, 0.0f, 0.0f), 0.4f);
  // With the surface's reflection it is what an instrument reads, and the fit's inverse
  // undoes it.
  for (double r : {0.0, 0.05, 0.3, 0.9}) {
    const double measured = impasto::data::saunderson_to_measured(r, 0.03, 0.65);
    EXPECT_NEAR(measured, 0.03 + impasto::data::saunderson_body(r, 0.03, 0.65), 1e-15);
    EXPECT_NEAR(impasto::data::saunderson_to_internal(measured, 0.03, 0.65), r, 1e-15);
  }
}
