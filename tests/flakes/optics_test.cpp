// Fresnel, the Lorentz–Drude aluminium and thin-film interference against closed forms.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <vector>

#include "impasto/flakes/flake_file.hpp"
#include "impasto/flakes/fresnel.hpp"
#include "impasto/flakes/lorentz_drude.hpp"
#include "impasto/flakes/thin_film.hpp"
#include "test_paints.hpp"

namespace impasto::flakes {
namespace {

TEST(Fresnel, DielectricNormalIncidenceAndGrazing) {
  for (double eta : {1.33, 1.5, 2.4}) {
    const double r0 = (eta - 1) * (eta - 1) / ((eta + 1) * (eta + 1));
    EXPECT_NEAR(fresnel_dielectric(1.0, eta), r0, 1e-12);
    EXPECT_GT(fresnel_dielectric(1e-5, eta), 0.999);
  }
  for (double c : {0.1, 0.5, 1.0}) EXPECT_NEAR(fresnel_dielectric(c, 1.0), 0.0, 1e-15);
  EXPECT_EQ(fresnel_dielectric(0.3, 1.0 / 1.5), 1.0);  // total internal reflection
}

TEST(Fresnel, ConductorWithoutAbsorptionIsTheDielectric) {
  const double eta = 1.6;
  for (double c : {0.05, 0.3, 0.7, 1.0}) {
    EXPECT_NEAR(fresnel_conductor(c, {eta, 0.0}).unpolarised(), fresnel_dielectric(c, eta), 1e-12);
  }
  // Brewster's angle: p-polarised light is not reflected at tan θ = η.
  const double brewster = std::atan(eta);
  EXPECT_NEAR(fresnel_conductor(std::cos(brewster), {eta, 0.0}).p, 0.0, 1e-12);
}

TEST(LorentzDrude, ShippedAluminiumTableIsTheModel) {
  const FlakeCoating table = load_nk_table(test::flake_data_dir() / "aluminium_rakic1998_ld.csv");
  ASSERT_EQ(table.wavelengths_nm.front(), 360.0);
  ASSERT_EQ(table.wavelengths_nm.back(), 830.0);
  const LorentzDrudeMetal al = rakic_aluminium();
  for (std::size_t i = 0; i < table.wavelengths_nm.size(); ++i) {
    const auto m = refractive_index(al, table.wavelengths_nm[i]);
    EXPECT_NEAR(table.n[i], m.real(), 1e-4) << table.wavelengths_nm[i];
    EXPECT_NEAR(table.k[i], m.imag(), 1e-4) << table.wavelengths_nm[i];
  }
  EXPECT_NE(table.source.find("Rakic"), std::string::npos);
}

TEST(LorentzDrude, AluminiumMatchesMeasuredValuesAt550nm) {
  // Handbook values for evaporated aluminium at 550 nm: n ≈ 0.96, k ≈ 6.69.
  const auto m = refractive_index(rakic_aluminium(), 550.0);
  EXPECT_NEAR(m.real(), 0.96, 0.08);
  EXPECT_NEAR(m.imag(), 6.69, 0.25);
}

TEST(LorentzDrude, AluminiumReflectsAboutNinetyPercentAndMoreAtGrazing) {
  const LorentzDrudeMetal al = rakic_aluminium();
  for (double nm : {400.0, 550.0, 700.0}) {
    const auto m = refractive_index(al, nm);
    const double in_air = fresnel_conductor(1.0, m).unpolarised();
    EXPECT_GT(in_air, 0.88) << nm;
    EXPECT_LT(in_air, 0.94) << nm;
    EXPECT_LT(fresnel_conductor(1.0, m / 1.5).unpolarised(), in_air);  // in a binder: less
    EXPECT_GT(fresnel_conductor(1e-4, m / 1.5).unpolarised(), 0.99) << nm;
  }
  // The interband absorption of aluminium near 1.5 eV (826 nm) dips the reflectance.
  EXPECT_LT(fresnel_conductor(1.0, refractive_index(al, 820.0)).unpolarised(),
            fresnel_conductor(1.0, refractive_index(al, 500.0)).unpolarised() - 0.03);
}

TEST(ThinFilm, QuarterAndHalfWaveLayers) {
  const double n0 = 1.5, ns = 1.58, n1 = 2.6, nm = 550.0;
  // A quarter-wave layer: R = ((n0 ns − n1²) / (n0 ns + n1²))².
  const std::vector<FilmLayer> quarter{{n1, nm / (4 * n1)}};
  const double expected = std::pow((n0 * ns - n1 * n1) / (n0 * ns + n1 * n1), 2);
  EXPECT_NEAR(thin_film_optics(quarter, n0, ns, nm, 1.0).reflectance, expected, 1e-12);
  // A half-wave layer is absent at its design wavelength, and so is a layer of no thickness.
  const double bare = std::pow((n0 - ns) / (n0 + ns), 2);
  const std::vector<FilmLayer> half{{n1, nm / (2 * n1)}};
  EXPECT_NEAR(thin_film_optics(half, n0, ns, nm, 1.0).reflectance, bare, 1e-12);
  const std::vector<FilmLayer> none{{n1, 0.0}};
  for (double c : {0.2, 0.6, 1.0}) {
    EXPECT_NEAR(thin_film_optics(none, n0, 2.0, nm, c).reflectance,
                fresnel_conductor(c, {2.0 / n0, 0.0}).unpolarised(), 1e-12);
  }
}

TEST(ThinFilm, LosslessStacksConserveEnergyAtAnyAngle) {
  const std::vector<FilmLayer> stack{{rutile_index(480), 120}, {1.58, 400}, {2.0, 75}};
  for (double c : {0.05, 0.3, 0.8, 1.0}) {
    const FilmOptics o = thin_film_optics(stack, 1.48, 1.48, 480, c);
    EXPECT_NEAR(o.reflectance + o.transmittance, 1.0, 1e-12) << c;
    const FilmOptics core = coated_core_optics(thin_film_optics(stack, 1.48, 1.58, 480, c));
    EXPECT_NEAR(core.reflectance + core.transmittance, 1.0, 1e-12) << c;
  }
  const FilmOptics clear = coated_core_optics({0.0, 1.0});
  EXPECT_EQ(clear.reflectance, 0.0);
  EXPECT_EQ(clear.transmittance, 1.0);
}

// Many thick layers, low-index ones at grazing light (the light evanescent in them): the
// characteristic matrix's entries grow as e^(phase) and once overflowed to NaN pixels (a
// flake file of 100+ layers). The stack stays finite, conserves energy and, where no light
// gets through, reflects it all.
TEST(ThinFilm, AThickManyLayeredStackStaysFiniteAtEveryAngle) {
  std::vector<FilmLayer> stack;
  for (int i = 0; i < 200; ++i) stack.push_back({i % 2 == 0 ? 2.6 : 1.0, 100000});
  for (double c : {0.02, 0.1, 0.5, 1.0}) {
    const FilmOptics o = thin_film_optics(stack, 1.48, 1.48, 400, c);
    ASSERT_TRUE(std::isfinite(o.reflectance) && std::isfinite(o.transmittance)) << c;
    EXPECT_GE(o.reflectance, 0.0);
    EXPECT_LE(o.reflectance, 1.0 + 1e-9);
    EXPECT_NEAR(o.reflectance + o.transmittance, 1.0, 1e-6) << c;
  }
}

TEST(ThinFilm, RutileIndexFollowsDevore) {
  EXPECT_NEAR(rutile_index(550), 2.648, 0.002);
  EXPECT_GT(rutile_index(420), rutile_index(700));  // normal dispersion
}

TEST(ThinFilm, BluePearlReflectsBlueAndPassesTheRest) {
  const FlakePaint pearl = test::shipped_pearl();
  const FilmOptics blue = pearl.coating.optics(460, 1.0, pearl.binder_index);
  const FilmOptics red = pearl.coating.optics(640, 1.0, pearl.binder_index);
  EXPECT_GT(blue.reflectance, 0.3);
  EXPECT_LT(red.reflectance, 0.05);
  EXPECT_NEAR(red.reflectance + red.transmittance, 1.0, 1e-12);
}

}  // namespace
}  // namespace impasto::flakes
