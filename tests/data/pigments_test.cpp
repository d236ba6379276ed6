#include "impasto/data/pigments.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "../common/scratch_folder.hpp"

namespace impasto::data {
namespace {

namespace fs = std::filesystem;

using test::scratch_folder;

// The default set anyone may ship: the 13 Kimera acrylics (CC BY 4.0, fitted from measured
// masstones and tints) and the two modelled flake paints (Impasto's own), nothing under a
// non-commercial licence.
TEST(PigmentDatabase, DefaultsHoldTheFreeAcrylics) {
  const PigmentDatabase& db = PigmentDatabase::defaults();
  const std::vector<std::string> kimera = {
      "White",           "Black",  "Cold Yellow", "Warm Yellow",
      "Yellow Oxide",    "Orange", "Red",         "Red Oxide",
      "Magenta",         "Violet", "Green",       "Blue Red Shade",
      "Blue Green Shade"};
  ASSERT_EQ(db.all().size(), kimera.size() + 2u);
  for (const std::string& name : kimera) {
    const Pigment& p = db.get(name);
    EXPECT_EQ(p.metadata.at("licence"), "CC BY 4.0") << name;
    EXPECT_NE(p.metadata.at("source").find("M. Iwanicki, PaintMixing"), std::string::npos) << name;
    EXPECT_NE(p.metadata.at("uncertainty").find("three repeats"), std::string::npos) << name;
    for (std::size_t i = 0; i < p.K.values.size(); ++i) {  // the fit left no zero
      EXPECT_GT(p.K.values[i], 0.0) << name << " K at " << p.K.wavelengths_nm[i];
      EXPECT_GT(p.S.values[i], 0.0) << name << " S at " << p.K.wavelengths_nm[i];
    }
  }
  for (const Pigment& p : db.all()) {
    ASSERT_EQ(p.K.values.size(), 40u) << p.name;  // 360..750 nm every 10 nm
    EXPECT_EQ(p.K.wavelengths_nm.front(), 360.0);
    EXPECT_EQ(p.S.wavelengths_nm, p.K.wavelengths_nm);
    for (std::size_t i = 0; i < p.K.values.size(); ++i) {
      EXPECT_TRUE(std::isfinite(p.K.values[i]) && p.K.values[i] >= 0.0) << p.name;
      EXPECT_TRUE(std::isfinite(p.S.values[i]) && p.S.values[i] >= 0.0) << p.name;
    }
    EXPECT_EQ(p.metadata.at("binder"), "acrylic");
    EXPECT_EQ(p.metadata.at("licence").find("NC"), std::string::npos) << p.name;
  }
  EXPECT_EQ(&PigmentDatabase::defaults(), &db) << "loaded once";
}

// White scatters by definition (S = 1) and, measured at 85-93 %, absorbs little: its K/S, the
// ratio an opaque layer's colour depends on, stays under 0.02 in the visible.
TEST(PigmentDatabase, WhiteIsTheScatteringReference) {
  const Pigment& white = PigmentDatabase::defaults().get("White");
  for (double s : white.S.values) EXPECT_EQ(s, 1.0);
  for (double nm = 420; nm <= 680; nm += 10) EXPECT_LT(white.K.at(nm), 0.02) << nm;
}

TEST(PigmentDatabase, FindsByNameAndListsNamesWhenUnknown) {
  const PigmentDatabase& db = PigmentDatabase::defaults();
  ASSERT_NE(db.find("blue green shade"), nullptr);
  EXPECT_EQ(db.find("BLUE green Shade")->name, "Blue Green Shade");
  EXPECT_EQ(db.find("Unobtainium"), nullptr);
  try {
    db.get("Unobtainium");
    FAIL() << "unknown pigment accepted";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("Unobtainium"), std::string::npos);
    EXPECT_NE(std::string(e.what()).find("Red Oxide"), std::string::npos);
  }
}

// Strokes recorded with earlier versions name the Golden acrylics, now an optional add-on: the
// error says which package holds them; a pigment of no known set says how to add one.
TEST(PigmentDatabase, AnUnknownPigmentSaysWhereToGetIt) {
  const PigmentDatabase& db = PigmentDatabase::defaults();
  const auto message = [&](const std::string& name) {
    try {
      db.get(name);
    } catch (const std::runtime_error& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  const std::string golden = message("ultramarine blue");
  EXPECT_NE(golden.find("'ultramarine blue'"), std::string::npos) << golden;
  EXPECT_NE(golden.find("impasto-pigments-okumura"), std::string::npos) << golden;
  EXPECT_NE(golden.find("--pigments DIR"), std::string::npos) << golden;
  const std::string other = message("Unobtainium");
  EXPECT_EQ(other.find("okumura"), std::string::npos) << other;
  EXPECT_NE(other.find("impasto pigments import"), std::string::npos) << other;
}

TEST(PigmentFile, RoundTripsAndKeepsUnknownMetadata) {
  const fs::path dir = scratch_folder("impasto_pigment_roundtrip");
  Pigment p{"Test Red",
            {"K", {400, 500, 600}, {1.5, 0.25, 0.0}},
            {"S", {400, 500, 600}, {1, 2, 3}},
            {{"colour_index", "PR254"}, {"flake_size_um", "20"}}};
  write_pigment_file(dir / pigment_file_name(p.name), p);
  const PigmentDatabase db = PigmentDatabase::load(dir);
  ASSERT_EQ(db.all().size(), 1u);
  const Pigment& q = db.get("Test Red");
  EXPECT_EQ(q.K.values, p.K.values);
  EXPECT_EQ(q.S.values, p.S.values);
  EXPECT_EQ(q.metadata.at("colour_index"), "PR254");
  EXPECT_EQ(q.metadata.at("flake_size_um"), "20");
  fs::remove_all(dir);
}

TEST(PigmentDatabase, FlakePaintsNameTheirFlakeFiles) {
  const PigmentDatabase& db = PigmentDatabase::defaults();
  const Pigment& aluminium = db.get("Aluminium Metallic");
  const Pigment& pearl = db.get("Mica Blue Pearl");
  EXPECT_EQ(aluminium.flakes.filename(), "aluminium_flakes.flake");
  EXPECT_EQ(pearl.flakes.filename(), "mica_tio2_blue_pearl.flake");
  EXPECT_TRUE(aluminium.flakes.is_absolute());
  EXPECT_TRUE(fs::is_regular_file(aluminium.flakes));
  EXPECT_TRUE(db.get("White").flakes.empty());
}

TEST(PigmentFile, AMissingFlakeFileIsAnErrorNamingTheField) {
  const fs::path dir = scratch_folder("impasto_pigment_flakes");
  std::ofstream(dir / "shiny.csv") << "# quantity: kubelka_munk\n# name: Shiny\n"
                                      "# flakes: nowhere.flake\nwavelength_nm,K,S\n400,1,2\n";
  try {
    PigmentDatabase::load(dir);
    FAIL() << "a missing flake file was accepted";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("shiny.csv: field 'flakes'"), std::string::npos)
        << e.what();
    EXPECT_NE(std::string(e.what()).find("nowhere.flake"), std::string::npos) << e.what();
  }
  std::ofstream(dir / "shiny.csv") << "# quantity: kubelka_munk\n# name: Shiny\n"
                                      "# flakes: \nwavelength_nm,K,S\n400,1,2\n";
  EXPECT_THROW(PigmentDatabase::load(dir), std::runtime_error);
  std::ofstream(dir / "mine.flake") << "format = impasto-flake-paint 1\n";
  std::ofstream(dir / "shiny.csv") << "# quantity: kubelka_munk\n# name: Shiny\n"
                                      "# flakes: mine.flake\nwavelength_nm,K,S\n400,1,2\n";
  EXPECT_EQ(PigmentDatabase::load(dir).get("Shiny").flakes,
            (dir / "mine.flake").lexically_normal());
  fs::remove_all(dir);
}

TEST(PigmentFile, ExtraColumnsAreAllowed) {
  const fs::path dir = scratch_folder("impasto_pigment_extra");
  std::ofstream(dir / "flake.csv") << "# quantity: kubelka_munk\n# name: Flake\n# future_key: x\n"
                                      "wavelength_nm,K,S,flake_density\n400,1,2,3\n500,1,2,3\n";
  EXPECT_EQ(PigmentDatabase::load(dir).get("Flake").S.values, (std::vector<double>{2, 2}));
  fs::remove_all(dir);
}

TEST(PigmentDatabase, RejectsBadFolders) {
  const fs::path dir = scratch_folder("impasto_pigment_bad");
  EXPECT_THROW(PigmentDatabase::load(dir), std::runtime_error);  // empty
  EXPECT_THROW(PigmentDatabase::load(dir / "missing"), std::runtime_error);
  const char* good = "# quantity: kubelka_munk\n# name: Same\nwavelength_nm,K,S\n400,1,1\n";
  std::ofstream(dir / "a.csv") << good;
  std::ofstream(dir / "b.csv") << good;
  try {
    PigmentDatabase::load(dir);
    FAIL() << "a repeated name was accepted";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("a.csv"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("b.csv"), std::string::npos) << e.what();
  }
  fs::remove(dir / "b.csv");
  std::ofstream(dir / "c.csv") << "# quantity: kubelka_munk\nwavelength_nm,K,S\n400,1,1\n";
  EXPECT_THROW(PigmentDatabase::load(dir), std::runtime_error);  // no name
  std::ofstream(dir / "c.csv") << "# quantity: kubelka_munk\n# name: C\nwavelength_nm,K\n400,1\n";
  EXPECT_THROW(PigmentDatabase::load(dir), std::runtime_error);  // no S
  std::ofstream(dir / "c.csv")
      << "# quantity: kubelka_munk\n# name: C\nwavelength_nm,K,S\n400,-1,1\n";
  EXPECT_THROW(PigmentDatabase::load(dir), std::runtime_error);  // negative K
  std::ofstream(dir / "c.csv")
      << "# quantity: reflectance\n# name: C\nwavelength_nm,K,S\n400,1,1\n";
  EXPECT_THROW(PigmentDatabase::load(dir), std::runtime_error);  // wrong quantity
  fs::remove_all(dir);
}

TEST(PigmentFile, FileNamesAreLowerCaseWords) {
  EXPECT_EQ(pigment_file_name("Blue Green Shade"), "blue_green_shade.csv");
  EXPECT_EQ(pigment_file_name("  ??  "), "pigment.csv");
}

}  // namespace
}  // namespace impasto::data
