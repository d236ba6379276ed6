// Sparkle statistics over many cells: counts are Poisson(⟨N⟩), the mean radiance is the
// flake BRDF term, ⟨N⟩ grows as Δ², and the two depth models differ as Eqs. 5–6 say.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <utility>
#include <vector>

#include "flake_test_geometry.hpp"
#include "impasto/flakes/fresnel.hpp"
#include "impasto/flakes/sparkle_math.hpp"
#include "impasto/flakes/sparkles.hpp"
#include "test_paints.hpp"

namespace impasto::flakes {
namespace {

using test::direction;
using test::kDegree;
using test::kNodes;
using test::kPi;
using test::viewer;

constexpr int kCells = 20000;

// The sun 40° from the zenith, the viewer 25° from it on the other side.
Light sun(double diameter_deg = 0.53) {
  Light light;
  light.kind = Light::Kind::directional;
  light.direction = -direction(40, 0);
  light.angular_diameter_rad = diameter_deg * kDegree;
  light.spectral.assign(kNodes.size(), 1.0);
  return light;
}

FlakeCell cell_at(int i, double area_mm2, double thickness_mm = 0.05) {
  FlakeCell cell;
  cell.ix = i % 200;
  cell.iy = i / 200;
  cell.area_mm2 = area_mm2;
  cell.flake_concentration = 1.0;
  cell.thickness_mm = thickness_mm;
  return cell;
}

// The cell area that makes ⟨N⟩ = mean (⟨N⟩ is proportional to the area).
double area_for_mean(const SparkleRenderer& r, double mean) {
  return mean / r.expected_count(cell_at(0, 1.0), sun(), viewer());
}

// Upper α = 0.001 point of χ² with `df` degrees of freedom (Wilson–Hilferty).
double chi_square_critical(int df) {
  const double z = 3.0902, k = df;
  return k * std::pow(1.0 - 2.0 / (9 * k) + z * std::sqrt(2.0 / (9 * k)), 3);
}

// χ² of observed counts against Poisson(mean), bins merged until each expects ≥ 5.
void expect_poisson(const std::vector<int>& counts, double mean) {
  const int top = *std::max_element(counts.begin(), counts.end()) + 1;
  std::vector<double> observed(top + 1, 0.0), expected(top + 1, 0.0);
  for (int c : counts) observed[c] += 1;
  double p = std::exp(-mean), cdf = 0;
  for (int k = 0; k < top; ++k, p *= mean / k) {
    expected[k] = p * counts.size();
    cdf += p;
  }
  expected[top] = (1.0 - cdf) * counts.size();  // the tail beyond the largest count
  // Merge neighbouring counts until each bin expects at least 5; a short tail joins the last.
  std::vector<std::pair<double, double>> bins;  // (observed, expected)
  double o = 0, e = 0;
  for (int k = 0; k <= top; ++k) {
    o += observed[k];
    e += expected[k];
    if (e >= 5) {
      bins.push_back({o, e});
      o = e = 0;
    }
  }
  if (!bins.empty()) {
    bins.back().first += o;
    bins.back().second += e;
  }
  double chi2 = 0;
  for (const auto& [bin_observed, bin_expected] : bins) {
    chi2 += std::pow(bin_observed - bin_expected, 2) / bin_expected;
  }
  const int bin_count = static_cast<int>(bins.size());
  ASSERT_GE(bin_count, 2);
  EXPECT_LT(chi2, chi_square_critical(bin_count - 1)) << "mean " << mean << ", bins " << bin_count;
}

std::vector<int> sparkle_counts(const SparkleRenderer& r, double mean) {
  const double area = area_for_mean(r, mean);
  std::vector<int> counts(kCells);
  std::vector<double> radiance(kNodes.size());
  for (int i = 0; i < kCells; ++i)
    counts[i] = r.add_cell(cell_at(i, area), sun(), viewer(), radiance);
  return counts;
}

TEST(SparkleStatistics, CountsArePoissonAtTheSignificanceLevelOf0001) {
  const SparkleRenderer r(test::grey_metal_paint(1.5), kNodes);
  for (double mean : {0.5, 2.5, 30.0}) {  // inversion and PTRS
    SCOPED_TRACE(mean);
    expect_poisson(sparkle_counts(r, mean), mean);
  }
}

TEST(SparkleStatistics, RareSparklesAreBernoulli) {
  const SparkleRenderer r(test::grey_metal_paint(1.5), kNodes);
  const double mean = 0.05;
  const std::vector<int> counts = sparkle_counts(r, mean);
  const double ones = std::count(counts.begin(), counts.end(), 1);
  EXPECT_EQ(ones + std::count(counts.begin(), counts.end(), 0), kCells);
  const double expected = mean * kCells;
  const double chi2 =
      std::pow(ones - expected, 2) / expected + std::pow(ones - expected, 2) / (kCells - expected);
  EXPECT_LT(chi2, 10.83);  // χ²(1) at α = 0.001
}

// The flake BRDF term written out from the paper's formulas, independently of the library:
// L = I T_in T_out r_p D⟨S⟩ H P(β) f / (8π η² cos ϑ′_p cos ϑ_p), with I the irradiance.
double analytic_mean_radiance(const SparkleRenderer& r, double thickness_mm) {
  const FlakePaint& paint = r.tables().paint();
  const double eta = paint.binder_index;
  const double light_polar = 40 * kDegree, view_polar = 25 * kDegree;
  const double light_in = std::asin(std::sin(light_polar) / eta);
  const double view_in = std::asin(std::sin(view_polar) / eta);
  const Vec3 v_light{std::sin(light_in), 0, std::cos(light_in)};
  const Vec3 v_view{-std::sin(view_in), 0, std::cos(view_in)};
  const Vec3 nf = normalized(v_light + v_view);
  const double beta = std::acos(nf.z), cos_alpha = dot(nf, v_light);
  // P(β) of a Gaussian normalised over the hemisphere, by a fine midpoint rule.
  const double sd = paint.orientation.gaussian_sd_rad;
  double z = 0;
  for (int i = 0; i < 100000; ++i) {
    const double b = (i + 0.5) * (kPi / 2) / 100000;
    z += std::exp(-0.5 * b * b / (sd * sd)) * std::sin(b) * (kPi / 2) / 100000;
  }
  const double density = std::exp(-0.5 * beta * beta / (sd * sd)) / z;
  const double r_p =
      fresnel_conductor(cos_alpha, std::complex<double>(1.2, 7.0) / eta).unpolarised();
  const double t_in = 1 - fresnel_dielectric(std::cos(light_polar), eta);
  const double t_out = 1 - fresnel_dielectric(std::cos(view_polar), eta);
  const double tau = paint.area_density_per_mm *
                     (r.tables().projected_area(std::cos(view_in)) / std::cos(view_in) +
                      r.tables().projected_area(std::cos(light_in)) / std::cos(light_in));
  const double f = (1 - std::exp(-tau * thickness_mm)) / (tau * thickness_mm);
  const double irradiance = std::cos(light_polar);
  return irradiance * t_in * t_out * r_p * paint.area_density_per_mm * thickness_mm * density * f /
         (8 * kPi * eta * eta * std::cos(light_in) * std::cos(view_in));
}

// Optical thickness per unit depth of the way in and out for the sun and viewer above, for
// flakes without binder absorption or pigment: D⟨S⟩ Σ ⟨s⟩(ϑ_p) / cos ϑ_p.
double path_thickness(const SparkleRenderer& r) {
  const double eta = r.tables().paint().binder_index;
  const double light_in = cos_inside_binder(std::cos(40 * kDegree), eta);
  const double view_in = cos_inside_binder(std::cos(25 * kDegree), eta);
  return r.tables().paint().area_density_per_mm * (r.tables().projected_area(light_in) / light_in +
                                                   r.tables().projected_area(view_in) / view_in);
}

TEST(SparkleStatistics, MeanRadianceIsTheFlakeBrdfInBothDepthModels) {
  for (auto model :
       {SparkleSettings::DepthModel::with_masking, SparkleSettings::DepthModel::without_masking}) {
    SparkleSettings settings;
    settings.depth_model = model;
    const SparkleRenderer r(test::grey_metal_paint(1.5), kNodes, settings);
    const double expected = analytic_mean_radiance(r, 0.05);
    std::vector<double> mean(kNodes.size());
    r.add_mean_radiance(cell_at(0, 0.01), sun(), viewer(), mean);
    EXPECT_NEAR(mean[1] / expected, 1.0, 2e-3);  // table interpolation only

    // Monte Carlo over cells: within 4 standard errors of the expectation.
    const double area = area_for_mean(r, 0.8);
    double sum = 0, sum2 = 0;
    for (int i = 0; i < kCells; ++i) {
      std::vector<double> radiance(kNodes.size(), 0.0);
      r.add_cell(cell_at(i, area), sun(), viewer(), radiance);
      ASSERT_GE(radiance[1], 0.0);
      sum += radiance[1];
      sum2 += radiance[1] * radiance[1];
    }
    const double m = sum / kCells, sd = std::sqrt(sum2 / kCells - m * m);
    EXPECT_NEAR(m, expected, 4 * sd / std::sqrt(kCells));
    EXPECT_NEAR(m / expected, 1.0, 0.05);
  }
}

TEST(SparkleStatistics, AFootprintOfManySparklesKeepsTheMean) {
  // Thousands of sparkles in one footprint: their summed area is drawn at once, with the
  // exact mean, and the relative spread falls as 1 / √⟨N⟩.
  const SparkleRenderer r(test::grey_metal_paint(1.5), kNodes);
  const double area = area_for_mean(r, 2000.0);
  std::vector<double> expected(kNodes.size());
  r.add_mean_radiance(cell_at(0, area), sun(), viewer(), expected);
  double sum = 0, sum2 = 0;
  const int footprints = 2000;
  for (int i = 0; i < footprints; ++i) {
    std::vector<double> radiance(kNodes.size(), 0.0);
    EXPECT_GT(r.add_cell(cell_at(i, area), sun(), viewer(), radiance), 256);
    sum += radiance[1];
    sum2 += radiance[1] * radiance[1];
  }
  const double m = sum / footprints, cv = std::sqrt(sum2 / footprints - m * m) / m;
  EXPECT_NEAR(m / expected[1], 1.0, 4 * cv / std::sqrt(footprints));
  // For a Poisson number of sparkles of weight W = S e^{−tz}, Var / mean² = E[W²] / (⟨N⟩E[W]²)
  // with E[S²] / E[S]² = 1 + (sd/mean)² and E[e^{−2tz}] / E[e^{−tz}]² from the depth factor.
  const FlakePaint& paint = r.tables().paint();
  const double t = path_thickness(r), h = 0.05;
  const double spread = paint.flake_area_sd_mm2 / paint.flake_area_mean_mm2;
  const double f1 = (1 - std::exp(-t * h)) / (t * h), f2 = (1 - std::exp(-2 * t * h)) / (2 * t * h);
  const double expected_cv = std::sqrt((1 + spread * spread) * f2 / (f1 * f1) / 2000.0);
  EXPECT_NEAR(cv / expected_cv, 1.0, 0.1);
}

TEST(SparkleStatistics, PearlSparklesHaveTheFlakeColour) {
  const SparkleRenderer r(test::shipped_pearl(), kNodes);
  const double area = area_for_mean(r, 0.5);
  int sparkling = 0;
  for (int i = 0; i < 200; ++i) {
    std::vector<double> radiance(kNodes.size(), 0.0);
    if (r.add_cell(cell_at(i, area), sun(), viewer(), radiance) == 0) continue;
    ++sparkling;
    EXPECT_GT(radiance[0], 5 * radiance[2]);  // 450 nm against 650 nm: a blue sparkle
  }
  EXPECT_GT(sparkling, 20);
}

TEST(SparkleStatistics, ExpectedCountGrowsAsTheLightSizeSquared) {
  const SparkleRenderer r(test::shipped_aluminium(), kNodes);
  const FlakeCell cell = cell_at(0, 0.01);
  const double small = r.expected_count(cell, sun(0.25), viewer());
  ASSERT_GT(small, 0.0);
  EXPECT_NEAR(r.expected_count(cell, sun(0.5), viewer()) / small, 4.0, 1e-9);
  EXPECT_NEAR(r.expected_count(cell, sun(2.0), viewer()) / small, 64.0, 1e-9);
  // ... while the mean radiance does not depend on it.
  std::vector<double> a(kNodes.size()), b(kNodes.size());
  r.add_mean_radiance(cell, sun(0.25), viewer(), a);
  r.add_mean_radiance(cell, sun(2.0), viewer(), b);
  EXPECT_NEAR(b[1] / a[1], 1.0, 1e-9);
}

TEST(SparkleStatistics, DepthModelsDifferAsTheFormulasSay) {
  SparkleSettings with, without;
  without.depth_model = SparkleSettings::DepthModel::without_masking;
  const SparkleRenderer rw(test::grey_metal_paint(1.5), kNodes, with);
  const SparkleRenderer ro(test::grey_metal_paint(1.5), kNodes, without);
  const double thickness = 0.1;  // deep enough that few flakes are seen directly
  const FlakeCell cell = cell_at(0, 0.01, thickness);
  const double t = path_thickness(rw);
  const double direct = (1 - std::exp(-t * thickness)) / (t * thickness);
  ASSERT_LT(direct, 0.3);
  // Eq. 6 / Eq. 5: fewer sparkles without masking ...
  EXPECT_NEAR(ro.expected_count(cell, sun(), viewer()) / rw.expected_count(cell, sun(), viewer()),
              direct, 1e-12);
  // ... but each as bright as a top flake, while with masking the mean sparkle is dimmed by
  // ⟨e^{−tz}⟩ over z uniform in [0, H], which is the same factor: equal mean radiance.
  auto mean_per_sparkle = [&](const SparkleRenderer& r) {
    const double area = 0.3 / r.expected_count(cell_at(0, 1.0, thickness), sun(), viewer());
    double energy = 0, sparkles = 0;
    for (int i = 0; i < kCells; ++i) {
      std::vector<double> radiance(kNodes.size(), 0.0);
      sparkles += r.add_cell(cell_at(i, area, thickness), sun(), viewer(), radiance);
      energy += radiance[1] * area;  // radiance × area: independent of the cell size
    }
    return energy / sparkles;
  };
  EXPECT_NEAR(mean_per_sparkle(rw) / mean_per_sparkle(ro), direct, 0.05 * direct);
  std::vector<double> a(kNodes.size()), b(kNodes.size());
  rw.add_mean_radiance(cell, sun(), viewer(), a);
  ro.add_mean_radiance(cell, sun(), viewer(), b);
  EXPECT_NEAR(a[1] / b[1], 1.0, 1e-12);
}

TEST(SparkleStatistics, DiffuseLightMakesNoSparkles) {
  const SparkleRenderer r(test::shipped_aluminium(), kNodes);
  Light ambient;
  ambient.kind = Light::Kind::diffuse;
  for (int i = 0; i < 1000; ++i) {
    std::vector<double> radiance(kNodes.size(), 0.0);
    const FlakeCell cell = cell_at(i, 1.0);
    EXPECT_EQ(r.add_cell(cell, ambient, viewer(), radiance), 0);
    EXPECT_EQ(r.expected_count(cell, ambient, viewer()), 0.0);
    EXPECT_EQ(radiance, std::vector<double>(kNodes.size(), 0.0));
  }
}

TEST(SparkleStatistics, LightsAndViewersBelowThePaintMakeNoSparkles) {
  const SparkleRenderer r(test::shipped_aluminium(), kNodes);
  Light below = sun();
  below.direction = direction(40, 0);  // travelling upwards: it lights the back of the canvas
  EXPECT_EQ(r.expected_count(cell_at(0, 1.0), below, viewer()), 0.0);
  View under;
  under.direction = -direction(25, 180);
  EXPECT_EQ(r.expected_count(cell_at(0, 1.0), sun(), under), 0.0);
}

TEST(SparkleStatistics, PointAndSpotLightsFollowDistanceAndCone) {
  const SparkleRenderer r(test::grey_metal_paint(1.5), kNodes);
  Light point = sun();
  point.kind = Light::Kind::point;
  point.position_mm = 500.0 * direction(40, 0);
  point.spectral.assign(kNodes.size(), 500.0 * 500.0);  // the sun's irradiance at 500 mm
  std::vector<double> from_point(kNodes.size()), from_sun(kNodes.size());
  r.add_mean_radiance(cell_at(0, 0.01), point, viewer(), from_point);
  r.add_mean_radiance(cell_at(0, 0.01), sun(), viewer(), from_sun);
  EXPECT_NEAR(from_point[1] / from_sun[1], 1.0, 1e-9);

  Light spot = point;
  spot.kind = Light::Kind::spot;
  spot.direction = -direction(40, 0);
  std::vector<double> in_cone(kNodes.size());
  r.add_mean_radiance(cell_at(0, 0.01), spot, viewer(), in_cone);
  EXPECT_NEAR(in_cone[1] / from_sun[1], 1.0, 1e-9);
  spot.direction = -direction(10, 0);  // aimed 30° away, outside the 0.4 rad cone
  EXPECT_EQ(r.expected_count(cell_at(0, 0.01), spot, viewer()), 0.0);
}

}  // namespace
}  // namespace impasto::flakes
