// Data files against hostile contents: paths confined to the library, devices and folders
// refused by name, quoted content cut and escaped, saves atomic (docs/guarantees.md).
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>

#include "impasto/data/pigment_library.hpp"
#include "impasto/data/pigments.hpp"
#include "impasto/data/spectral_csv.hpp"
#include "impasto/files/data_dir.hpp"

namespace impasto::data {
namespace {

namespace fs = std::filesystem;

fs::path scratch(const std::string& name) {
  const fs::path dir = fs::temp_directory_path() / (name + "_" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

std::string pigment_error(const fs::path& dir) {
  try {
    PigmentDatabase::load(dir);
  } catch (const std::runtime_error& e) {
    return e.what();
  }
  return "";
}

std::string csv_error(const fs::path& file) {
  try {
    read_spectral_csv(file);
  } catch (const std::runtime_error& e) {
    return e.what();
  }
  return "";
}

void write_pigment(const fs::path& file, const std::string& flakes) {
  std::ofstream(file) << "# quantity: kubelka_munk\n# name: Shiny\n# flakes: " << flakes
                      << "\nwavelength_nm,K,S\n400,1,2\n";
}

// A pigment folder's files name only files inside that folder: a --pigments or user folder
// never reaches the folder above it (its owner's home, with ~/.ssh beside it).
TEST(DataFileSafety, AFlakesPathStaysInsideThePigmentFolder) {
  const fs::path home = scratch("impasto_confined_flakes");
  const fs::path folder = home / "my-pigments";
  fs::create_directories(folder);
  fs::create_directories(home / ".ssh");
  std::ofstream(home / ".ssh/id_rsa") << "-----BEGIN OPENSSH PRIVATE KEY-----\n";
  std::ofstream(folder / "mine.flake") << "format = impasto-flake-paint 1\n";
  write_pigment(folder / "shiny.csv", "mine.flake");
  EXPECT_EQ(pigment_error(folder), "");
  write_pigment(folder / "shiny.csv", "../.ssh/id_rsa");
  EXPECT_NE(pigment_error(folder).find("shiny.csv: field 'flakes': '../.ssh/id_rsa' climbs out"),
            std::string::npos)
      << pigment_error(folder);
  fs::create_directories(home / "flakes");
  std::ofstream(home / "flakes/mine.flake") << "format = impasto-flake-paint 1\n";
  write_pigment(folder / "shiny.csv", "../flakes/mine.flake");
  EXPECT_NE(pigment_error(folder).find("climbs out with '..'"), std::string::npos);
  write_pigment(folder / "shiny.csv", "/etc/shadow");
  EXPECT_NE(
      pigment_error(folder).find("shiny.csv: field 'flakes': '/etc/shadow' is an absolute path"),
      std::string::npos);
  write_pigment(folder / "shiny.csv", "../../../../etc/passwd");
  EXPECT_NE(pigment_error(folder).find("climbs out with '..'"), std::string::npos);
  fs::create_symlink(home / ".ssh/id_rsa", folder / "out.flake");
  write_pigment(folder / "shiny.csv", "out.flake");
  EXPECT_NE(pigment_error(folder).find("through a symlink"), std::string::npos);
  fs::remove_all(home);
}

// The bundled pigments keep their flakes in the data folder beside them (data/flakes).
TEST(DataFileSafety, TheBundledFlakePaintsReachTheDataFoldersFlakes) {
  const PigmentFolderScan scan = scan_pigment_folder(files::data_dir() / "pigments");
  EXPECT_TRUE(scan.problems.empty()) << scan.problems.front();
  int with_flakes = 0;
  for (const auto& loaded : scan.pigments) with_flakes += loaded.pigment.flakes.empty() ? 0 : 1;
  EXPECT_EQ(with_flakes, 2);
}

TEST(DataFileSafety, DevicesAndFoldersAreRefusedByName) {
  EXPECT_EQ(csv_error("/dev/zero"),
            "/dev/zero: cannot read the spectral CSV: it is a device, not a file");
  const fs::path dir = scratch("impasto_csv_folder");
  EXPECT_EQ(csv_error(dir),
            dir.string() + ": cannot read the spectral CSV: it is a folder, not a file");
  fs::remove_all(dir);
}

// A huge cell and escape codes are quoted cut to ~100 characters with control bytes escaped.
TEST(DataFileSafety, QuotedCellsAreCutAndEscaped) {
  const fs::path dir = scratch("impasto_csv_cell");
  std::ofstream(dir / "a.csv") << "# quantity: reflectance\nwavelength_nm,R\n400,"
                               << std::string(5'000'000, '7') << "x\n500,\x1b[31m\n";
  const std::string error = csv_error(dir / "a.csv");
  EXPECT_LT(error.size(), 300u) << error.substr(0, 300);
  EXPECT_NE(error.find("a.csv"), std::string::npos) << error.substr(0, 300);
  EXPECT_NE(error.find("(5000001 bytes)"), std::string::npos) << error.substr(0, 300);
  std::ofstream(dir / "a.csv") << "# quantity: reflectance\nwavelength_nm,R\n400,\x1b[31m\n";
  const std::string escaped = csv_error(dir / "a.csv");
  EXPECT_EQ(escaped.find('\x1b'), std::string::npos) << escaped;
  EXPECT_NE(escaped.find("\\x1b[31m"), std::string::npos) << escaped;
  fs::remove_all(dir);
}

TEST(DataFileSafety, AWrittenTableReplacesTheOldOneWholeAndKeepsItsMode) {
  const fs::path dir = scratch("impasto_csv_write");
  const SpectralTable table = make_spectral_table(SpectralQuantity::reflectance,
                                                  {Spectrum{"R", {400.0, 500.0}, {0.5, 0.6}}}, {});
  std::ofstream(dir / "real.csv") << "old";
  fs::permissions(dir / "real.csv", fs::perms::owner_read | fs::perms::owner_write);
  fs::create_symlink("real.csv", dir / "link.csv");
  write_spectral_csv(dir / "link.csv", table);
  EXPECT_TRUE(fs::is_symlink(dir / "link.csv"));
  EXPECT_EQ(read_spectral_csv(dir / "real.csv").columns.size(), 1u);
  EXPECT_EQ(fs::status(dir / "real.csv").permissions(),
            fs::perms::owner_read | fs::perms::owner_write);
  EXPECT_EQ(std::distance(fs::directory_iterator(dir), {}), 2);  // no temp file left
  fs::remove_all(dir);
}

}  // namespace
}  // namespace impasto::data
