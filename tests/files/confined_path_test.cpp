#include "impasto/files/confined_path.hpp"

#include <gtest/gtest.h>

#include <fstream>

#include "temp_folder.hpp"

namespace impasto::files {
namespace {

std::string error_of(const std::filesystem::path& folder, const std::string& relative) {
  try {
    confined_path(folder, relative, "p.csv: field 'flakes'");
  } catch (const std::runtime_error& e) {
    return e.what();
  }
  return "";
}

TEST(ConfinedPath, AcceptsAPathInsideTheFolder) {
  test::TempFolder folder;
  std::filesystem::create_directory(folder / "flakes");
  std::ofstream(folder / "flakes/gold.txt") << "x";
  EXPECT_EQ(confined_path(folder.path(), "flakes/gold.txt", "w"), folder / "flakes/gold.txt");
  EXPECT_EQ(confined_path(folder.path(), "./flakes/gold.txt", "w"),
            folder.path() / "./flakes/gold.txt");
}

TEST(ConfinedPath, RefusesAbsoluteAndClimbingPaths) {
  test::TempFolder folder;
  EXPECT_NE(error_of(folder.path(), "/etc/shadow")
                .find("p.csv: field 'flakes': '/etc/shadow' is an absolute path"),
            std::string::npos);
  EXPECT_NE(error_of(folder.path(), "../x.txt").find("climbs out with '..'"), std::string::npos);
  EXPECT_NE(error_of(folder.path(), "a/../../x.txt").find("climbs out"), std::string::npos);
  EXPECT_EQ(error_of(folder.path(), "a/../x.txt"), "");
  EXPECT_NE(error_of(folder.path(), "").find("is empty"), std::string::npos);
}

TEST(ConfinedPath, RefusesASymlinkLeadingOut) {
  test::TempFolder folder;
  std::filesystem::create_directory(folder / "lib");
  std::filesystem::create_symlink("/etc", folder / "lib/out");
  std::filesystem::create_symlink("/etc/passwd", folder / "lib/passwd");
  EXPECT_NE(
      error_of(folder / "lib", "out/passwd").find("leads out of the library through a symlink"),
      std::string::npos);
  EXPECT_NE(error_of(folder / "lib", "passwd").find("through a symlink"), std::string::npos);
  // A symlink that stays inside is fine.
  std::ofstream(folder / "lib/real.txt") << "x";
  std::filesystem::create_symlink("real.txt", folder / "lib/alias.txt");
  EXPECT_EQ(error_of(folder / "lib", "alias.txt"), "");
}

// A pigment in <library>/pigments names its flakes as ../flakes/NAME: inside the library.
TEST(ConfinedPath, ALibraryAboveTheNamingFolder) {
  test::TempFolder folder;
  const auto library = folder / "data";
  std::filesystem::create_directories(library / "pigments");
  std::filesystem::create_directories(library / "flakes");
  EXPECT_EQ(confined_path(library, library / "pigments", "../flakes/gold.flake", "w"),
            library / "pigments" / "../flakes/gold.flake");
  try {
    confined_path(library, library / "pigments", "../../secret", "p.csv: field 'flakes'");
    FAIL();
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("climbs out"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace impasto::files
