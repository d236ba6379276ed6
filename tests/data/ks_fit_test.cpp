#include "impasto/data/ks_fit.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <stdexcept>

#include "impasto/data/spectral_csv.hpp"

namespace impasto::data {
namespace {

TEST(KubelkaMunk, OpaqueReflectanceAndKsAreInverse) {
  EXPECT_EQ(ks_from_reflectance(1.0), 0.0);
  EXPECT_DOUBLE_EQ(ks_from_reflectance(0.5), 0.25);
  EXPECT_EQ(reflectance_from_ks(0.0), 1.0);
  EXPECT_NEAR(reflectance_from_ks(1e12), 0.5e-12, 1e-20);  // R∞ → 1/(2·K/S) for large K/S
  for (double r : {1e-6, 0.01, 0.3, 0.9, 0.999}) {
    EXPECT_NEAR(reflectance_from_ks(ks_from_reflectance(r)), r, 1e-12 * (1 + r)) << r;
  }
}

TEST(KubelkaMunk, SaundersonRoundTripsAndHasTheRightLimits) {
  const Saunderson s{0.03, 0.65};
  EXPECT_NEAR(s.to_measured(0.0), 0.03, 1e-15);  // a black body shows only its surface gloss
  EXPECT_NEAR(s.to_measured(1.0), 1.0, 1e-15);   // a perfect white stays white
  for (double r : {0.05, 0.4, 0.8}) EXPECT_NEAR(s.to_internal(s.to_measured(r)), r, 1e-14);
}

// An instrument that reads part of the surface's reflection (a 45/0 probe reads none of it)
// sees that share of k1 on top of the same body: the light crossing the surface does not
// depend on where the instrument looks from.
TEST(KubelkaMunk, SaundersonWithPartOfTheSurfaceSeen) {
  const Saunderson all{0.03, 0.65}, part{0.03, 0.65, 0.4}, none{0.03, 0.65, 0.0};
  EXPECT_NEAR(part.to_measured(0.0), 0.4 * 0.03, 1e-15);
  EXPECT_NEAR(none.to_measured(0.0), 0.0, 1e-15);
  for (double r : {0.0, 0.05, 0.4, 0.8, 1.0}) {
    EXPECT_NEAR(all.to_measured(r) - part.to_measured(r), 0.6 * 0.03, 1e-15) << r;
    EXPECT_NEAR(none.to_measured(r), saunderson_body(r, 0.03, 0.65), 1e-15) << r;
    EXPECT_NEAR(part.to_internal(part.to_measured(r)), r, 1e-14) << r;
    EXPECT_NEAR(none.to_internal(none.to_measured(r)), r, 1e-14) << r;
  }
}

// Synthetic measurements made from known K and S by the forward model.
KsFitProblem synthetic_problem(const std::vector<const Pigment*>& truth,
                               const std::optional<Saunderson>& saunderson) {
  KsFitProblem problem;
  for (const Pigment* p : truth) problem.pigment_names.push_back(p->name);
  problem.reference_pigment = truth.front()->name;
  problem.saunderson = saunderson;
  const std::size_t n = truth.size();
  auto add = [&](std::string name, std::vector<double> c) {
    problem.samples.push_back({name, mixture_reflectance(truth, c, saunderson), c});
  };
  for (std::size_t j = 0; j < n; ++j) {
    std::vector<double> c(n, 0.0);
    c[j] = 1.0;
    add("masstone " + truth[j]->name, c);
  }
  for (std::size_t a = 0; a < n; ++a) {
    for (std::size_t b = a + 1; b < n; ++b) {
      for (double share : {0.1, 0.5, 0.9}) {
        std::vector<double> c(n, 0.0);
        c[a] = share;
        c[b] = 1.0 - share;
        add(truth[a]->name + "+" + truth[b]->name, c);
      }
    }
  }
  return problem;
}

void expect_recovered(const std::vector<const Pigment*>& truth, const KsFitResult& fit) {
  ASSERT_EQ(fit.pigments.size(), truth.size());
  for (std::size_t j = 0; j < truth.size(); ++j) {
    for (std::size_t w = 0; w < truth[j]->K.values.size(); ++w) {
      const double k = truth[j]->K.values[w], s = truth[j]->S.values[w];
      EXPECT_NEAR(fit.pigments[j].K.values[w], k, 1e-6 * std::max(1.0, k)) << truth[j]->name << w;
      EXPECT_NEAR(fit.pigments[j].S.values[w], s, 1e-6 * std::max(1.0, s)) << truth[j]->name << w;
    }
  }
  for (const KsSampleResidual& r : fit.residuals) EXPECT_LT(r.max_reflectance, 1e-9) << r.name;
}

std::vector<const Pigment*> four_golden_pigments() {
  const PigmentDatabase& db = PigmentDatabase::defaults();
  return {&db.get("White"), &db.get("Blue Green Shade"), &db.get("Red"), &db.get("Cold Yellow")};
}

TEST(KsFit, RecoversKnownPigmentsFromSyntheticMixtures) {
  const auto truth = four_golden_pigments();
  const KsFitResult fit = fit_kubelka_munk(synthetic_problem(truth, std::nullopt));
  expect_recovered(truth, fit);
  EXPECT_EQ(fit.residuals.size(), 4u + 6u * 3u);
}

TEST(KsFit, RecoversThroughTheSaundersonCorrection) {
  const auto truth = four_golden_pigments();
  expect_recovered(truth, fit_kubelka_munk(synthetic_problem(truth, Saunderson{0.03, 0.65})));
}

TEST(KsFit, RecoversThroughASurfacePartlySeen) {
  const auto truth = four_golden_pigments();
  expect_recovered(truth, fit_kubelka_munk(synthetic_problem(truth, Saunderson{0.03, 0.65, 0.6})));
}

TEST(KsFit, ReportsResidualsOfInconsistentData) {
  const auto truth = four_golden_pigments();
  KsFitProblem problem = synthetic_problem(truth, std::nullopt);
  for (double& r : problem.samples[5].reflectance.values) r *= 0.9;  // one bad measurement
  const KsFitResult fit = fit_kubelka_munk(problem);
  double worst = 0;
  for (const auto& r : fit.residuals) worst = std::max(worst, r.max_reflectance);
  EXPECT_GT(worst, 1e-3);
  for (const Pigment& p : fit.pigments) {
    for (double k : p.K.values) EXPECT_GE(k, 0.0);
    for (double s : p.S.values) EXPECT_GE(s, 0.0);
  }
}

TEST(KsFit, RejectsInconsistentProblems) {
  const auto truth = four_golden_pigments();
  KsFitProblem problem = synthetic_problem(truth, std::nullopt);
  problem.reference_pigment = "Lead White";
  EXPECT_THROW(fit_kubelka_munk(problem), std::runtime_error);
  problem = synthetic_problem(truth, std::nullopt);
  problem.samples[0].concentrations.pop_back();
  EXPECT_THROW(fit_kubelka_munk(problem), std::runtime_error);
  problem = synthetic_problem(truth, std::nullopt);
  problem.samples[0].reflectance.values[3] = 1.5;
  EXPECT_THROW(fit_kubelka_munk(problem), std::runtime_error);
}

TEST(KsFit, ShippedExampleGivesBackTheShippedPigments) {
  // The example's reflectances were computed from the shipped K and S and rounded to 6
  // decimals, so the fit returns them up to that rounding.
  const KsFitProblem problem = read_ks_measurements(std::filesystem::path(IMPASTO_SOURCE_DIR) /
                                                    "data/measurements/synthetic_mixtures.csv");
  ASSERT_TRUE(problem.saunderson.has_value());
  const KsFitResult fit = fit_kubelka_munk(problem);
  const PigmentDatabase& db = PigmentDatabase::defaults();
  for (const Pigment& p : fit.pigments) {
    const Pigment& shipped = db.get(p.name);
    for (std::size_t w = 0; w < p.K.values.size(); ++w) {
      const double nm = p.K.wavelengths_nm[w];
      EXPECT_NEAR(p.K.values[w], shipped.K.at(nm), 2e-3 * (1 + shipped.K.at(nm))) << p.name << nm;
      EXPECT_NEAR(p.S.values[w], shipped.S.at(nm), 2e-3 * (1 + shipped.S.at(nm))) << p.name << nm;
    }
  }
  for (const KsSampleResidual& r : fit.residuals) EXPECT_LT(r.max_reflectance, 1e-3) << r.name;
}

class KsMeasurementsFile : public testing::Test {
 protected:
  // One file per test, so that tests run in parallel do not share it.
  std::filesystem::path path_ =
      std::filesystem::path(testing::TempDir()) /
      (std::string("impasto_ks_") + testing::UnitTest::GetInstance()->current_test_info()->name() +
       ".csv");
  void TearDown() override { std::filesystem::remove(path_); }
  void write(const std::string& text) { std::ofstream(path_) << text; }
  std::string error() {
    try {
      read_ks_measurements(path_);
    } catch (const std::runtime_error& e) {
      return e.what();
    }
    return "";
  }
};

TEST_F(KsMeasurementsFile, ReadsMixesReferenceAndSaunderson) {
  write(
      "# quantity: reflectance\n# reference: White\n# saunderson: 0.04, 0.6\n"
      "# mix w: White=1\n# mix tint: Blue=1; White=3\n# mix b: Blue = 2\n"
      "wavelength_nm,w,b,tint\n400,0.9,0.1,0.5\n500,0.9,0.2,0.6\n");
  const KsFitProblem p = read_ks_measurements(path_);
  EXPECT_EQ(p.reference_pigment, "White");
  ASSERT_TRUE(p.saunderson.has_value());
  EXPECT_EQ(p.saunderson->k1, 0.04);
  EXPECT_EQ(p.saunderson->k2, 0.6);
  EXPECT_EQ(p.pigment_names, (std::vector<std::string>{"White", "Blue"}));
  ASSERT_EQ(p.samples.size(), 3u);
  EXPECT_EQ(p.samples[1].name, "b");
  EXPECT_EQ(p.samples[1].concentrations, (std::vector<double>{0, 2}));
  EXPECT_EQ(p.samples[2].concentrations, (std::vector<double>{3, 1}));
  EXPECT_EQ(p.samples[2].reflectance.values, (std::vector<double>{0.5, 0.6}));
}

TEST_F(KsMeasurementsFile, ReadsTheShareOfTheSurfaceSeen) {
  write(
      "# quantity: reflectance\n# reference: White\n# saunderson: 0.03 0.65\n"
      "# surface_seen: 0.6\n# mix w: White=1\nwavelength_nm,w\n400,0.9\n");
  const KsFitProblem p = read_ks_measurements(path_);
  ASSERT_TRUE(p.saunderson.has_value());
  EXPECT_EQ(p.saunderson->surface_seen, 0.6);
  write(
      "# quantity: reflectance\n# reference: W\n# saunderson: 0.03 0.65\n# mix w: W=1\n"
      "wavelength_nm,w\n400,0.9\n");
  EXPECT_EQ(read_ks_measurements(path_).saunderson->surface_seen, 1.0);  // by default, all
  const std::string file = path_.string();
  write(
      "# quantity: reflectance\n# reference: W\n# saunderson: 0.03 0.65\n# surface_seen: 1.5\n"
      "# mix w: W=1\nwavelength_nm,w\n400,0.9\n");
  EXPECT_EQ(error().rfind(file + ":4:", 0), 0u) << error();
  write(
      "# quantity: reflectance\n# reference: W\n# surface_seen: 0.5\n# mix w: W=1\n"
      "wavelength_nm,w\n400,0.9\n");
  EXPECT_NE(error().find("after a '# saunderson"), std::string::npos) << error();
}

// The one range of a Saunderson coefficient, which the measurements file and the render
// settings both check.
TEST(SaundersonCoefficient, IsInZeroToOneOpen) {
  EXPECT_TRUE(saunderson_coefficient_valid(0.0));
  EXPECT_TRUE(saunderson_coefficient_valid(kSaundersonK1));
  EXPECT_TRUE(saunderson_coefficient_valid(kSaundersonK2));
  EXPECT_TRUE(saunderson_coefficient_valid(0.999));
  EXPECT_FALSE(saunderson_coefficient_valid(1.0));
  EXPECT_FALSE(saunderson_coefficient_valid(-0.01));
  EXPECT_FALSE(saunderson_coefficient_valid(std::nan("")));
}

TEST_F(KsMeasurementsFile, ErrorsNameFileAndLine) {
  const std::string file = path_.string();
  write("# quantity: reflectance\n# reference: W\n# mix a: W=x\nwavelength_nm,a\n400,0.5\n");
  EXPECT_EQ(error().rfind(file + ":3:", 0), 0u) << error();
  write(
      "# quantity: reflectance\n# reference: W\n# mix a: W=1\n# mix z: "
      "W=1\nwavelength_nm,a\n400,0.5\n");
  EXPECT_EQ(error().rfind(file + ":4:", 0), 0u) << error();
  write(
      "# quantity: reflectance\n# reference: W\n# saunderson: 2\n# mix a: "
      "W=1\nwavelength_nm,a\n400,0.5\n");
  EXPECT_EQ(error().rfind(file + ":3:", 0), 0u) << error();
  write(
      "# quantity: reflectance\n# reference: W\n# saunderson: 0.04 1\n# mix a: "
      "W=1\nwavelength_nm,a\n400,0.5\n");
  EXPECT_EQ(error().rfind(file + ":3:", 0), 0u) << error();
  EXPECT_NE(error().find("in [0, 1)"), std::string::npos) << error();
  write("# quantity: reflectance\n# reference: W\nwavelength_nm,a\n400,0.5\n");
  EXPECT_NE(error().find("column 'a' has no '# mix a"), std::string::npos) << error();
  write("# quantity: reflectance\n# mix a: W=1\nwavelength_nm,a\n400,0.5\n");
  EXPECT_NE(error().find("reference"), std::string::npos) << error();
  write("# quantity: reflectance\n# reference: W\n# mix a: W=1\nwavelength_nm,a\n400,1.5\n");
  EXPECT_EQ(error().rfind(file + ":5:2:", 0), 0u) << error();
}

}  // namespace
}  // namespace impasto::data
