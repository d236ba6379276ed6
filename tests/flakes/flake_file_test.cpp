// Reading flake paints and n, k tables; bad input names the file and line or field.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

#include "flake_test_geometry.hpp"
#include "impasto/flakes/flake_file.hpp"
#include "test_paints.hpp"

namespace impasto::flakes {
namespace {

using test::kDegree;

const std::string kValid =
    "format = impasto-flake-paint 1\n"
    "name = test paint   # a comment\n"
    "area_density_per_mm = 30\n"
    "flake_area_mean_mm2 = 2e-4\n"
    "flake_area_sd_mm2 = 5e-5\n"
    "orientation = table\n"
    "orientation_point = 0 1\n"
    "orientation_point = 10 0.5\n"
    "orientation_point = 20 0\n"
    "coating = thin_film\n"
    "film_layer = rutile 60\n"
    "film_layer = 1.58 300\n"
    "binder_ior = 1.5\n";

// The message of the error parsing `text` throws.
std::string error_of(const std::string& text) {
  try {
    parse_flake_paint(text, "paint.flake", ".");
  } catch (const std::runtime_error& e) {
    return e.what();
  }
  return "no error";
}

TEST(FlakeFile, ReadsTheShippedPaints) {
  const FlakePaint al = test::shipped_aluminium();
  EXPECT_EQ(al.name, "Aluminium flakes");
  EXPECT_EQ(al.coating.kind, FlakeCoating::Kind::metal);
  EXPECT_EQ(al.coating.wavelengths_nm.size(), 48u);
  EXPECT_DOUBLE_EQ(al.area_density_per_mm, 50.0);
  EXPECT_DOUBLE_EQ(al.orientation.gaussian_sd_rad, 12.0 * kDegree);
  EXPECT_DOUBLE_EQ(al.binder_index, 1.48);

  const FlakePaint pearl = test::shipped_pearl();
  EXPECT_EQ(pearl.coating.kind, FlakeCoating::Kind::thin_film);
  ASSERT_EQ(pearl.coating.layers.size(), 1u);
  EXPECT_EQ(pearl.coating.layers[0].material.name, "rutile");
  EXPECT_DOUBLE_EQ(pearl.coating.layers[0].thickness_nm, 120.0);
  EXPECT_DOUBLE_EQ(pearl.coating.core_index, 1.58);
}

TEST(FlakeFile, ParsesTablesLayersAndDefaults) {
  const FlakePaint p = parse_flake_paint(kValid, "paint.flake", ".");
  EXPECT_EQ(p.name, "test paint");
  ASSERT_EQ(p.orientation.table_beta_rad.size(), 3u);
  EXPECT_DOUBLE_EQ(p.orientation.table_beta_rad[1], 10.0 * kDegree);
  EXPECT_DOUBLE_EQ(p.orientation.relative_density(5.0 * kDegree), 0.75);
  EXPECT_EQ(p.orientation.relative_density(30.0 * kDegree), 0.0);
  ASSERT_EQ(p.coating.layers.size(), 2u);
  EXPECT_DOUBLE_EQ(p.coating.layers[1].material.constant_index, 1.58);
  EXPECT_EQ(p.coating.core_index, 0.0);
  EXPECT_EQ(p.binder_absorption_per_mm, 0.0);
  EXPECT_EQ(p.rayleigh_weight_per_mm, 0.0);
}

TEST(FlakeFile, ErrorsNameTheFileAndLine) {
  auto replace = [](std::string text, const std::string& from, const std::string& to) {
    return text.replace(text.find(from), from.size(), to);
  };
  EXPECT_EQ(error_of(replace(kValid, "area_density_per_mm = 30", "area_density_per_mm = nan")),
            "paint.flake:3: area_density_per_mm: must be finite");
  EXPECT_EQ(error_of(replace(kValid, "= 2e-4", "= lots")),
            "paint.flake:4: flake_area_mean_mm2: 'lots' is not a number");
  EXPECT_NE(error_of(replace(kValid, "binder_ior = 1.5", "binder_ior = 40")).find("paint.flake:13"),
            std::string::npos);
  EXPECT_EQ(error_of(kValid + "colour = red\n"), "paint.flake:14: unknown field 'colour'");
  EXPECT_EQ(error_of(kValid + "binder_ior = 1.4\n"), "paint.flake:14: 'binder_ior' given twice");
  EXPECT_EQ(error_of(replace(kValid, "name = test paint", "name test paint")),
            "paint.flake:2: expected 'key = value'");
  EXPECT_EQ(error_of(replace(kValid, "orientation_point = 20 0", "orientation_point = 5 0")),
            "paint.flake:9: orientation_point angles must increase");
  EXPECT_EQ(error_of(replace(kValid, "film_layer = rutile 60", "film_layer = rutile -60")),
            "paint.flake:11: film_layer thickness outside (0, 100000] nm");
  EXPECT_EQ(error_of(replace(kValid, "coating = thin_film", "coating = gold")),
            "paint.flake:10: coating must be 'metal' or 'thin_film'");
}

TEST(FlakeFile, ErrorsNameAMissingField) {
  std::string text = kValid;
  text.erase(text.find("binder_ior"));
  EXPECT_EQ(error_of(text), "paint.flake: missing field 'binder_ior'");
  EXPECT_EQ(error_of("format = impasto-flake-paint 1\n"), "paint.flake: missing field 'name'");
  std::string metal = kValid;
  metal.replace(metal.find("coating = thin_film"), 19, "coating = metal");
  EXPECT_EQ(error_of(metal), "paint.flake: missing field 'nk_table'");
}

TEST(FlakeFile, MissingNkTableNamesItsPath) {
  std::string text = kValid;
  text.replace(text.find("coating = thin_film"), 19, "coating = metal\nnk_table = nowhere.csv");
  const std::string message = error_of(text);
  EXPECT_NE(message.find("nowhere.csv: cannot open"), std::string::npos) << message;
}

TEST(NkTable, ErrorsNameTheLine) {
  auto error = [](const std::string& text) -> std::string {
    try {
      parse_nk_table(text, "al.csv");
    } catch (const std::runtime_error& e) {
      return e.what();
    }
    return "no error";
  };
  EXPECT_EQ(error("# c\nwavelength_nm,n,k\n400,1,5\n390,1,5\n"),
            "al.csv:4: wavelengths must increase");
  EXPECT_EQ(error("wavelength_nm,n,k\n400,1,5\n500,1\n"),
            "al.csv:3: expected 3 columns: wavelength_nm,n,k");
  EXPECT_EQ(error("wavelength_nm,n,k\n400,1,-5\n500,1,5\n"), "al.csv:2: need n > 0 and k >= 0");
  EXPECT_EQ(error("wavelength_nm,n,k\n400,1,inf\n500,1,5\n"), "al.csv:2: k: must be finite");
  EXPECT_EQ(error("400,1,5\n500,1,5\n"), "al.csv:1: expected the header 'wavelength_nm,n,k'");
  EXPECT_EQ(error("wavelength_nm,n,k\n400,1,5\n"), "al.csv: an n, k table needs at least two rows");
}

}  // namespace
}  // namespace impasto::flakes
