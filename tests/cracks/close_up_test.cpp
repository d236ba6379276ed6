// Close-up radiosity of wall points and the far-view cell reflectance.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "impasto/cracks/cavity_look.hpp"
#include "impasto/cracks/close_up.hpp"
#include "impasto/cracks/gouffe.hpp"

namespace impasto::cracks {
namespace {

TEST(CloseUp, SphereRadiosityUnderSkyIsTheApparentReflectance) {
  // In a sphere F_p = G everywhere, so every wall point has the same radiosity, and the
  // light it sends out through the opening, B F S, must equal rho A E_sky: B = rho E_sky.
  const CavityDims dims{1.4, 1.0};
  const CavityLighting sky{2.0, 0.0, {0.0, 0.0, 1.0}};
  const double rho = apparent_reflectance(0.7, view_factors(CavityShape::SpherePit, dims));
  for (double s : {0.0, 0.4, 0.9}) {
    const CavityWallPoint p = cavity_wall_point(CavityShape::SpherePit, dims, s, 1.0);
    EXPECT_NEAR(cavity_point_radiosity(CavityShape::SpherePit, dims, p, 0.7, sky), rho * 2.0,
                1e-12);
  }
}

TEST(CloseUp, ShallowBottomReflectsLikeAFlatSurface) {
  const CavityDims dims{1e-6, 1.0};
  const CavityLighting light{1.0, 3.0, {0.0, 0.0, 1.0}};
  const CavityWallPoint bottom = cavity_wall_point(CavityShape::CylinderPit, dims, 0.0, 0.0);
  EXPECT_NEAR(cavity_point_radiosity(CavityShape::CylinderPit, dims, bottom, 0.5, light),
              0.5 * (1.0 + 3.0), 1e-5);
}

TEST(CloseUp, SunBehindTheWallCastsAShadow) {
  // A deep box groove lit at a grazing angle across it: the bottom is in shadow and gets
  // only interreflected light; the wall facing the sun (the left one, x = -R) is lit near the rim.
  const CavityDims dims{4.0, 1.0};
  const CavityLighting sun{0.0, 1.0, {std::sin(1.2), 0.0, std::cos(1.2)}};
  const CavityWallPoint bottom = cavity_wall_point(CavityShape::BoxGroove, dims, 0.0, 1.0);
  const CavityWallPoint lit = cavity_wall_point(CavityShape::BoxGroove, dims, 0.97, -1.0);
  const double b_bottom = cavity_point_radiosity(CavityShape::BoxGroove, dims, bottom, 0.5, sun);
  const double b_lit = cavity_point_radiosity(CavityShape::BoxGroove, dims, lit, 0.5, sun);
  EXPECT_GT(b_bottom, 0.0);
  EXPECT_GT(b_lit, 0.5 * std::sin(1.2) * 0.99);  // at least its direct light
  EXPECT_LT(b_bottom, 0.1 * b_lit);
}

TEST(CellReflectance, BlendsSurfaceAndCavityByCoverage) {
  const std::vector<float> surface{0.8f, 0.6f, 0.4f};
  const std::vector<float> wall{0.9f, 0.5f, 0.1f};
  std::vector<float> out(3);
  // A groove as wide as the cell covers it completely: the cell is the cavity.
  CrackCell wide{0.5f, 0.05f, CavityShape::VGroove, kCanvasGround};
  crack_cell_reflectance(wide, 0.1, surface, wall, out, CavityModel::Gouffe);
  const ViewFactors vf = view_factors(CavityShape::VGroove, wide.dims());
  for (int i = 0; i < 3; ++i) EXPECT_NEAR(out[i], apparent_reflectance(wall[i], vf), 1e-6);
  // The default model: the closed form times the table's correction.
  crack_cell_reflectance(wide, 0.1, surface, wall, out);
  for (int i = 0; i < 3; ++i) {
    EXPECT_NEAR(
        out[i],
        cavity_reflectance(CavityModel::Corrected, CavityShape::VGroove, wide.dims(), vf, wall[i]),
        1e-6);
  }
  // A quarter-width groove: a quarter of the cavity, three quarters of the surface.
  CrackCell narrow{0.5f, 0.0125f, CavityShape::VGroove, kCanvasGround};
  EXPECT_NEAR(crack_coverage(narrow, 0.1), 0.25, 1e-6);
  crack_cell_reflectance(narrow, 0.1, surface, wall, out, CavityModel::Gouffe);
  const ViewFactors vf_narrow = view_factors(CavityShape::VGroove, narrow.dims());
  for (int i = 0; i < 3; ++i) {
    EXPECT_NEAR(out[i], 0.75 * surface[i] + 0.25 * apparent_reflectance(wall[i], vf_narrow), 1e-6);
  }
  // No crack: the surface unchanged; in place too.
  std::vector<float> in_place = surface;
  crack_cell_reflectance(CrackCell{}, 0.1, in_place, wall, in_place);
  EXPECT_EQ(in_place, surface);
  EXPECT_THROW(crack_cell_reflectance(wide, 0.1, surface, std::vector<float>(2), out),
               std::invalid_argument);
}

TEST(CellReflectance, PitCoverageIsItsOpeningArea) {
  const CrackCell pit{0.2f, 0.02f, CavityShape::SpherePit, 0};
  EXPECT_NEAR(crack_coverage(pit, 0.1), std::acos(-1.0) * 0.0004 / 0.01, 1e-6);
}

}  // namespace
}  // namespace impasto::cracks
