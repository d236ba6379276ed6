#include "impasto/data/spectral_csv.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <string>

namespace impasto::data {
namespace {

// The message parse_spectral_csv throws for `text`, or "" when it parses.
std::string error_of(const std::string& text) {
  try {
    parse_spectral_csv(text, "bad.csv");
  } catch (const std::runtime_error& e) {
    return e.what();
  }
  return "";
}

constexpr const char* kGood =
    "# quantity: reflectance\n"
    "# units: fraction\n"
    "# plain comment without a key\n"
    "wavelength_nm,white,\"grey, 50%\"\n"
    "400,0.9,0.5\n"
    "\n"
    "410, 0.95 ,0.25\r\n"
    "420,1,0\n";

TEST(SpectralCsv, ReadsMetadataHeaderAndColumns) {
  const SpectralTable t = parse_spectral_csv(kGood, "good.csv");
  EXPECT_EQ(t.quantity, SpectralQuantity::reflectance);
  EXPECT_EQ(t.metadata.at("units"), "fraction");
  EXPECT_EQ(t.metadata.size(), 2u);
  ASSERT_EQ(t.columns.size(), 2u);
  EXPECT_EQ(t.wavelengths_nm, (std::vector<double>{400, 410, 420}));
  EXPECT_EQ(t.column("white").values, (std::vector<double>{0.9, 0.95, 1.0}));
  EXPECT_EQ(t.column("grey, 50%").values, (std::vector<double>{0.5, 0.25, 0.0}));
  EXPECT_EQ(t.column("white").wavelengths_nm, t.wavelengths_nm);
  EXPECT_EQ(t.find("black"), nullptr);
  EXPECT_THROW(t.column("black"), std::runtime_error);
}

TEST(SpectralCsv, WriterRoundTripsExactly) {
  SpectralTable t = parse_spectral_csv(kGood, "good.csv");
  t.columns[0].values[1] = 0.1 + 0.2;  // a number with no short decimal form
  const SpectralTable again = parse_spectral_csv(format_spectral_csv(t), "again.csv");
  EXPECT_EQ(again.quantity, t.quantity);
  EXPECT_EQ(again.metadata, t.metadata);
  EXPECT_EQ(again.wavelengths_nm, t.wavelengths_nm);
  ASSERT_EQ(again.columns.size(), 2u);
  for (std::size_t c = 0; c < 2; ++c) {
    EXPECT_EQ(again.columns[c].name, t.columns[c].name);
    EXPECT_EQ(again.columns[c].values, t.columns[c].values);
  }
}

TEST(SpectralCsv, ReadsAndWritesFiles) {
  const auto path = std::filesystem::path(testing::TempDir()) / "impasto_spectral_csv_test.csv";
  const SpectralTable t = parse_spectral_csv(kGood, "good.csv");
  write_spectral_csv(path, t);
  EXPECT_EQ(read_spectral_csv(path).column("white").values, t.column("white").values);
  std::ofstream(path) << "wavelength_nm,a\n400,x\n";
  try {
    read_spectral_csv(path);
    FAIL() << "a bad file was accepted";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find(path.string() + ":2:2:"), std::string::npos) << e.what();
  }
  std::filesystem::remove(path);
  EXPECT_THROW(read_spectral_csv(path), std::runtime_error);
}

TEST(SpectralCsv, RejectsEachKindOfBadFileWithFileLineColumn) {
  const std::string head = "# quantity: reflectance\nwavelength_nm,a,b\n";
  struct Case {
    std::string text, where, what;
  };
  const Case cases[] = {
      {head + "400,0.1,0.2\n400,0.1,0.2\n", "bad.csv:4:1:", "does not increase"},
      {head + "410,0.1,0.2\n400,0.1,0.2\n", "bad.csv:4:1:", "does not increase"},
      {head + "400,0.1,1.5\n", "bad.csv:3:3:", "outside 0..1"},
      {head + "400,-0.01,0.5\n", "bad.csv:3:2:", "outside 0..1"},
      {head + "400,0.1,\n", "bad.csv:3:3:", "missing value in column 'b'"},
      {head + "400,,0.2\n", "bad.csv:3:2:", "missing value in column 'a'"},
      {head + "400,0.1\n", "bad.csv:3:3:", "row has 2 cells, the header has 3"},
      {head + "400,0.1,0.2,0.3\n", "bad.csv:3:4:", "row has 4 cells"},
      {head + "400,nan,0.2\n", "bad.csv:3:2:", "not finite"},
      {head + "400,0.1,inf\n", "bad.csv:3:3:", "not finite"},
      {head + "400,0.1,0.2x\n", "bad.csv:3:3:", "not a number"},
      {head + "-5,0.1,0.2\n", "bad.csv:3:1:", "not positive"},
      {head + "400,\"0.1,0.2\n", "bad.csv:3:", "malformed CSV"},
      {"# quantity: paint\nwavelength_nm,a\n400,1\n", "bad.csv:1:1:", "unknown quantity"},
      {"# k: 1\n# k: 2\nwavelength_nm,a\n400,1\n", "bad.csv:2:1:", "given twice"},
      {"nm,a\n400,1\n", "bad.csv:1:1:", "must start with 'wavelength_nm'"},
      {"wavelength_nm,a,a\n400,1,1\n", "bad.csv:1:3:", "appears twice"},
      {"wavelength_nm,a,\n400,1,1\n", "bad.csv:1:3:", "empty column name"},
      {"wavelength_nm\n400\n", "bad.csv:1:", "names no sample column"},
      {"# quantity: cmf\nwavelength_nm,a\n400,-1\n", "bad.csv:3:2:", "outside >= 0"},
      // A K or S no render can use (K (K + 2S) beyond floats) is refused as it is read.
      {"# quantity: kubelka_munk\nwavelength_nm,K,S\n400,1e308,1\n",
       "bad.csv:3:2:", "outside 0..1e+06"},
      {"# only metadata\n", "bad.csv:", "no header"},
      {"wavelength_nm,a\n", "bad.csv:", "no data rows"},
  };
  for (const Case& c : cases) {
    const std::string message = error_of(c.text);
    EXPECT_EQ(message.rfind(c.where, 0), 0u) << c.text << " -> " << message;
    EXPECT_NE(message.find(c.what), std::string::npos) << c.text << " -> " << message;
  }
}

TEST(SpectralCsv, WriterRefusesMetadataThatWouldNotReadBack) {
  SpectralTable t = parse_spectral_csv(kGood, "good.csv");
  t.metadata["note"] = "two\nlines";
  EXPECT_THROW(format_spectral_csv(t), std::runtime_error);
  t.metadata.erase("note");
  t.metadata["a: b"] = "c";
  EXPECT_THROW(format_spectral_csv(t), std::runtime_error);
}

TEST(SpectralCsv, WithoutQuantityAcceptsAnyFiniteValue) {
  const SpectralTable t = parse_spectral_csv("wavelength_nm,a\n400,-7\n410,1e5\n", "any.csv");
  EXPECT_EQ(t.quantity, SpectralQuantity::unspecified);
  EXPECT_EQ(t.column("a").values, (std::vector<double>{-7, 1e5}));
}

TEST(SpectralCsv, MakeTableChecksTheGrid) {
  const Spectrum a{"a", {400, 410}, {1, 2}};
  const Spectrum b{"b", {400, 420}, {1, 2}};
  EXPECT_EQ(make_spectral_table(SpectralQuantity::unspecified, {a}).wavelengths_nm,
            a.wavelengths_nm);
  EXPECT_THROW(make_spectral_table(SpectralQuantity::unspecified, {a, b}), std::runtime_error);
  EXPECT_THROW(make_spectral_table(SpectralQuantity::unspecified, {}), std::runtime_error);
}

}  // namespace
}  // namespace impasto::data
